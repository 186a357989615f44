#include "render/inpaint/moved_view_eval.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "common/scene/scene_json.hpp"
#include "render/gs/model.hpp"
#include "render/image_io.hpp"
#include "render/image_metrics.hpp"
#include "render/inpaint/deletion.hpp"
#include "render/light/light_estimate.hpp"

namespace chatsim::render::inpaint {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct TruthView {
  std::string name;
  cv::Mat image;      // CV_8UC3, noise-free
  double exposure = 1;
};

// Where two 8-bit images differ visibly (by 2 levels or more, summed over the channels).
cv::Mat changed(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  cv::Mat most;
  cv::transform(diff, most, cv::Matx13f(1, 1, 1));  // summed over channels: 2 levels or more
  return most > 1;
}

}  // namespace

json evaluate_moved_view_deletion(const scene::Scene& s, std::shared_ptr<const gs::RadianceField> model, const std::string& save_dir) {
  const fs::path vj = s.dir / "ground_truth" / "views.json";
  if (!fs::exists(vj)) throw std::invalid_argument(vj.string() + ": missing: moved-view deletion needs a demo scene's shifted ground-truth views");
  const json doc = scene::read_json_file(vj);
  std::vector<std::string> vehicles;
  for (const auto& o : s.objects)
    if (o.has_category_prefix("vehicle")) vehicles.push_back(o.id);
  // The truth's vehicles at each instant, with their shadows under the true sun: left out.
  DeletionOptions truth_outline;
  if (const fs::path sky = s.dir / "ground_truth" / "sky.json"; fs::exists(sky)) {
    const json sky_doc = scene::read_json_file(sky);  // outlives the reader, which refers to it
    if (const scene::FieldReader j(sky, sky_doc); j.has("sun_direction_world")) truth_outline.sun_direction = j.at("sun_direction_world").vec3();
  }

  std::vector<DeletionImage> field;  // the field's render of each shifted view (as the background stage makes it)
  std::vector<TruthView> truth;
  const scene::FieldReader listed = scene::FieldReader(vj, doc).at("views");
  for (size_t i = 0; i < listed.array_size(); ++i) {
    const scene::FieldReader v = listed.at(i);
    if (v.at("shift").str() == "none") continue;
    const auto* cam = s.camera(v.at("camera").str());
    if (cam == nullptr) continue;
    DeletionImage im;
    im.frame = v.at("frame").integer(), im.camera = cam->name, im.cam = *cam, im.time = v.at("timestamp_s").number();
    im.pose = v.at("camera_to_world").rigid();
    im.exposure = model->exposure(s, im.frame, im.camera);
    const gs::GsImage g = model->render(s, im.cam, im.pose, im.time);
    im.radiance = g.radiance;
    im.rendered_depth = g.depth;
    field.push_back(im);
    truth.push_back({v.at("name").str(), read_rgb8(s.dir / v.at("image").str()), v.at("exposure_s").number()});
  }
  if (field.empty()) throw std::invalid_argument(vj.string() + ": no shifted views");

  const auto sources = scene_images(s, model.get());
  // The deletion follows the shadows with the sun estimated from the images, as the agent does.
  DeletionOptions opts;
  const auto light = light::estimate_scene_light(s);
  if (light.sunny) opts.sun_direction = light.sky.sun_direction.normalized().cast<double>();
  const BackgroundRenderer behind = field_renderer(model, s, opts);
  auto run = [&](bool clear_paths, double min_log_step, double& seconds) {
    std::vector<DeletionImage> targets = field;
    for (auto& t : targets) {
      t.radiance = t.radiance.clone();
      if (!clear_paths) t.rendered_depth = cv::Mat();
    }
    DeletionOptions variant = opts;
    variant.path_min_log_step = min_log_step;
    const auto t0 = std::chrono::steady_clock::now();
    delete_objects(s, vehicles, targets, sources, variant, behind);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return targets;
  };
  double secs_outline = 0, secs_ungated = 0, secs_agent = 0;
  const auto outline_only = run(false, opts.path_min_log_step, secs_outline);
  const auto ungated = run(true, 0, secs_ungated);
  const auto agent = run(true, opts.path_min_log_step, secs_agent);

  json views = json::array();
  double sum_field = 0, sum_outline = 0, sum_ungated = 0, sum_agent = 0;
  long pixels = 0;
  int scored = 0;
  for (size_t i = 0; i < field.size(); ++i) {
    const float e = float(truth[i].exposure);
    const cv::Mat a = encode_srgb8(field[i].radiance, e), b = encode_srgb8(outline_only[i].radiance, e),
                  c = encode_srgb8(ungated[i].radiance, e), d = encode_srgb8(agent[i].radiance, e);
    // The same pixels for every fill: wherever any of them changed the render.
    cv::Mat region = changed(a, b) | changed(a, c) | changed(a, d);
    region &= ~deletion_mask(s, field[i], vehicles, truth_outline);
    const int n = cv::countNonZero(region);
    json r{{"view", truth[i].name}, {"pixels", n}};
    if (n >= 50) {
      const double pf = psnr(a, truth[i].image, region), po = psnr(b, truth[i].image, region), pu = psnr(c, truth[i].image, region),
                   pa = psnr(d, truth[i].image, region);
      r.update({{"psnr_field", pf}, {"psnr_outline_only", po}, {"psnr_path_ungated", pu}, {"psnr_agent", pa}});
      sum_field += pf, sum_outline += po, sum_ungated += pu, sum_agent += pa, pixels += n, ++scored;
    }
    views.push_back(r);
    if (!save_dir.empty()) {
      cv::Mat shown;
      cv::cvtColor(region, shown, cv::COLOR_GRAY2BGR);
      cv::Mat row;
      cv::hconcat(std::vector<cv::Mat>{truth[i].image, a, b, c, d, shown}, row);
      write_rgb8(fs::path(save_dir) / (truth[i].name + "_truth_field_outline_ungated_agent_region.png"), row);
    }
  }
  json summary{{"views", field.size()}, {"scored_views", scored}, {"sun_estimated", light.sunny}, {"scored_pixels", pixels}, {"vehicles_removed", vehicles.size()},
               {"seconds_per_image_outline_only", secs_outline / double(field.size())},
               {"seconds_per_image_path_ungated", secs_ungated / double(field.size())},
               {"seconds_per_image_agent", secs_agent / double(field.size())}};
  if (scored > 0)
    summary.update({{"psnr_field", sum_field / scored}, {"psnr_outline_only", sum_outline / scored},
                    {"psnr_path_ungated", sum_ungated / scored}, {"psnr_agent", sum_agent / scored}});
  return {{"summary", summary},
          {"views", views},
          {"what", "every vehicle removed from the field's render of each shifted ground-truth view; PSNR against the noise-free truth "
                   "where the deletion changed the render and the truth shows no vehicle or vehicle shadow: the field's render as "
                   "it was, the deletion without clearing the removed cars' paths, clearing all of each path, and the deletion as "
                   "the agent does it (clearing the path where the render and the ground map differ)"}};
}

}  // namespace chatsim::render::inpaint
