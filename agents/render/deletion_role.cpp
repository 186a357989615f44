#include "agents/render/deletion_role.hpp"

#include "agents/core/scene_cache.hpp"
#include "agents/render/background_role.hpp"
#include "agents/render/foreground_role.hpp"
#include "agents/render/render_job.hpp"
#include "render/image_io.hpp"
#include "render/inpaint/deletion.hpp"

#include <map>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace chatsim::agents::render {
namespace fs = std::filesystem;
using chatsim::render::inpaint::DeletionImage;

namespace {

cv::Rect padded_bounds(const cv::Mat& mask, int pad) {
  const cv::Rect r = cv::boundingRect(mask);
  if (r.empty()) return r;
  return cv::Rect(r.x - pad, r.y - pad, r.width + 2 * pad, r.height + 2 * pad) & cv::Rect(0, 0, mask.cols, mask.rows);
}

}  // namespace

AgentOutcome deletion_inpaint(const AgentCall& call) {
  try {
    const auto s = cached_scene(call.scene);
    const RenderJob job = RenderJob::from_json(call.args);
    if (job.in.empty()) return AgentOutcome::failure(ErrorKind::BadRequest, "args.in: missing: the background stage's folder");
    for (const auto& id : job.removed)
      if (s->object(id) == nullptr)
        return AgentOutcome::failure(ErrorKind::BadRequest, "args.removed: no object '" + id + "' in " + (s->dir / "objects.json").string());
    std::shared_ptr<const chatsim::render::gs::RadianceField> model;
    if (!job.model.empty()) model = load_model_cached(job.model);
    const auto images = view_images(*s, job, model.get());
    std::vector<DeletionImage> targets;
    for (const auto& im : images) {
      DeletionImage d;
      d.frame = im.frame, d.camera = im.camera, d.cam = im.cam, d.pose = im.pose, d.time = im.time;
      d.exposure = read_exposure(job.in, im.camera, im.frame);
      const fs::path f = radiance_file(job.in, im.camera, im.frame);
      if (!fs::exists(f)) return AgentOutcome::failure(ErrorKind::BadRequest, "args.in: no background image " + f.string());
      d.radiance = chatsim::render::read_float_image(f);
      // A view the field rendered: its ground along a removed car's path is replaced too.
      if (const fs::path depth = depth_file(job.in, im.camera, im.frame); !im.original && fs::exists(depth))
        d.rendered_depth = chatsim::render::read_float_image(depth);
      targets.push_back(std::move(d));
    }
    chatsim::render::inpaint::DeletionStats stats;
    std::map<std::pair<int, std::string>, chatsim::render::gs::GsImage> rendered;  // the model's view without the removed objects
    if (!job.removed.empty()) {
      // In the background stage's units (the field's, where there is one).
      const auto sources = chatsim::render::inpaint::scene_images(*s, model.get());
      // Follow the deleted objects' shadows with the scene's estimated sun.
      chatsim::render::inpaint::DeletionOptions opts;
      const auto light = scene_light(*s);
      if (light.sunny) opts.sun_direction = light.sky.sun_direction.normalized().cast<double>();
      chatsim::render::inpaint::BackgroundRenderer behind;
      if (model)  // its renders kept, so the depth below needs no second render
        behind = chatsim::render::inpaint::field_renderer(model, *s, opts, [&](const DeletionImage& im, const chatsim::render::gs::GsImage& g) {
          rendered[{im.frame, im.camera}] = g;
        });
      stats = chatsim::render::inpaint::delete_objects(*s, job.removed, targets, sources, opts, behind);
    }
    for (const auto& im : targets) {
      chatsim::render::write_exr(radiance_file(job.out, im.camera, im.frame), im.radiance, chatsim::render::ExrCompression::None);
      write_exposure(job.out, im.camera, im.frame, im.exposure);
      const fs::path d = depth_file(job.in, im.camera, im.frame);
      if (!fs::exists(d)) continue;
      // Depth without the deleted objects, so an added car is not hidden behind a removed one.
      cv::Mat depth = chatsim::render::read_float_image(d);
      if (model && !job.removed.empty()) {
        const cv::Mat mask = chatsim::render::inpaint::deletion_mask(*s, im, job.removed);
        if (cv::countNonZero(mask) > 0) {
          // The fill's render covers the mask with the shadows (a superset of this one).
          const auto it = rendered.find({im.frame, im.camera});
          const auto b = it != rendered.end() ? it->second : model->render_region(*s, im.cam, im.pose, im.time, job.removed, padded_bounds(mask, 2));
          b.depth.copyTo(depth, mask);
        }
      }
      chatsim::render::write_exr(depth_file(job.out, im.camera, im.frame), depth);
    }
    return AgentOutcome::success({{"images", targets.size()}, {"edited", stats.images_edited}, {"ground_seen", stats.ground_seen},
                                  {"fallback_pixels", stats.fallback_pixels}, {"field_fills", stats.field_fills},
                                  {"field_rejected", stats.field_rejected}, {"seconds", stats.seconds}});
  } catch (const scene::SceneError& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
  } catch (const std::invalid_argument& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, e.what());
  }
}

}  // namespace chatsim::agents::render
