#include "agents/render/background_role.hpp"

#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>

#include "agents/core/scene_cache.hpp"
#include "agents/render/render_cache.hpp"
#include "agents/render/render_job.hpp"
#include "render/gs/trainer.hpp"
#include "render/image_io.hpp"

namespace chatsim::agents::render {
namespace fs = std::filesystem;
using nlohmann::json;

std::shared_ptr<const chatsim::render::gs::RadianceField> load_model_cached(const fs::path& file) {
  static std::mutex mu;
  static fs::path path;
  static fs::file_time_type stamp;
  static std::shared_ptr<const chatsim::render::gs::RadianceField> model;
  std::lock_guard lock(mu);
  const auto t = fs::last_write_time(file);
  if (!model || path != file || stamp != t) {
    model = std::make_shared<chatsim::render::gs::RadianceField>(chatsim::render::gs::RadianceField::load(file));
    path = file;
    stamp = t;
  }
  return model;
}

fs::path BackgroundRole::model_path(const scene::Scene& s, const std::string& preset) {
  return scene_cache_dir(s) / ("radiance_field_" + preset + "_v" + std::to_string(chatsim::render::gs::kTrainerVersion) + ".csgs");
}

AgentOutcome BackgroundRole::handle(const AgentCall& call, const RoleProgress& progress) {
  try {
    if (call.action == "ensure_model") return ensure_model(call, progress);
    if (call.action == "render") return render(call);
  } catch (const scene::SceneError& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
  } catch (const std::invalid_argument& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, e.what());
  }
  return AgentOutcome::failure(ErrorKind::BadRequest, "background has no action '" + call.action + "' (actions: ensure_model, render)");
}

AgentOutcome BackgroundRole::ensure_model(const AgentCall& call, const RoleProgress& progress) {
  const auto s = cached_scene(call.scene);
  const std::string preset = call.args.value("preset", std::string("fast"));
  const fs::path file = model_path(*s, preset);
  if (fs::exists(file)) {
    try {
      const auto m = load_model_cached(file);
      return AgentOutcome::success({{"model", file.string()}, {"trained", false}, {"info", m->info}});
    } catch (const std::exception&) {
      fs::remove(file);  // a corrupt cache entry: train again
    }
  }
  chatsim::render::gs::TrainOptions o;
  o.preset = preset;
  if (call.args.contains("iterations")) o.max_iterations = call.args["iterations"].get<int>();
  // Tests and quick looks cap training ($CHATSIM_TRAIN_ITERATIONS); the cache keeps the preset's name.
  if (const char* it = std::getenv("CHATSIM_TRAIN_ITERATIONS"); it != nullptr && std::atoi(it) > 0) o.max_iterations = std::atoi(it);
  if (call.args.contains("max_width")) o.max_width = call.args["max_width"].get<int>();
  o.progress = [&](int it, int total, double loss, double psnr, size_t n) {
    if (progress && (it % 50 == 0 || it == total))
      progress(double(it) / total, "training the radiance field: iteration " + std::to_string(it) + "/" + std::to_string(total) +
                                       ", loss " + std::to_string(loss).substr(0, 6) + ", PSNR " + std::to_string(int(psnr)) +
                                       " dB, " + std::to_string(n) + " Gaussians");
  };
  chatsim::render::gs::TrainReport r;
  const auto model = chatsim::render::gs::train(*s, o, &r);
  model.save(file);
  return AgentOutcome::success({{"model", file.string()}, {"trained", true}, {"seconds", r.seconds}, {"info", model.info}});
}

AgentOutcome BackgroundRole::render(const AgentCall& call) {
  const auto s = cached_scene(call.scene);
  const RenderJob job = RenderJob::from_json(call.args);
  std::shared_ptr<const chatsim::render::gs::RadianceField> model;
  if (!job.model.empty()) model = load_model_cached(job.model);
  const bool original = is_original_view(job.view);
  if (!original && !model)
    return AgentOutcome::failure(ErrorKind::BadRequest, "a changed view needs a radiance field: ask 'ensure_model' first and pass args.model");
  const auto images = view_images(*s, job, model.get());
  int rendered = 0, reused = 0;
  double render_s = 0;
  for (const auto& im : images) {
    cv::Mat radiance, depth;
    double exposure = 1.0;
    const auto& frame = *s->frame(im.frame);  // view_images yields only the scene's frames
    const auto it = frame.images.find(im.camera);
    if (it != frame.images.end() && it->second.exposure_s) exposure = *it->second.exposure_s;
    if (model) exposure = model->exposure(*s, im.frame, im.camera);
    if (im.original) {
      // The captured image is the background of its own view: nothing to render.
      radiance = chatsim::render::decode_srgb8(chatsim::render::read_rgb8(s->dir / it->second.path)) / exposure;
      ++reused;
    }
    if (model) {
      const auto t0 = std::chrono::steady_clock::now();
      const auto img = model->render(*s, im.cam, im.pose, im.time);
      render_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      depth = img.depth;
      if (!im.original) {
        radiance = img.radiance;
        ++rendered;
      }
    }
    chatsim::render::write_exr(radiance_file(job.out, im.camera, im.frame), radiance, chatsim::render::ExrCompression::None);
    if (!depth.empty()) chatsim::render::write_exr(depth_file(job.out, im.camera, im.frame), depth);
    write_exposure(job.out, im.camera, im.frame, exposure);
  }
  return AgentOutcome::success({{"images", images.size()}, {"rendered", rendered}, {"reused_captured", reused},
                                {"render_seconds", render_s}, {"depth", bool(model)}});
}

}  // namespace chatsim::agents::render
