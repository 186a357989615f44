#include "render/gs/nvs_eval.hpp"

#include <chrono>
#include <map>

#include <opencv2/imgproc.hpp>

#include "common/scene/scene_json.hpp"
#include "render/gs/moving_mask.hpp"
#include "render/gs/pose_error.hpp"
#include "render/gs/trainer.hpp"
#include "render/image_io.hpp"
#include "render/image_metrics.hpp"

namespace chatsim::render::gs {
namespace fs = std::filesystem;
using nlohmann::json;

json evaluate_nvs(const RadianceField& model, const scene::Scene& s, const NvsOptions& o) {
  int width = o.max_width;
  if (width <= 0 && model.info.contains("resolution")) width = model.info["resolution"][0].get<int>();
  json views = json::array();
  std::map<std::string, std::vector<json>> sets;
  std::map<fs::path, cv::Mat> captured_held_out;  // read once: scored, then used for the ceiling
  const auto moving = moving_objects(s);
  auto evaluate = [&](const std::string& set, const std::string& name, const scene::Camera& cam,
                      const Eigen::Isometry3d& pose, double time, double exposure, const fs::path& truth_file) {
    const scene::Camera c = scaled_camera(cam, width);
    const auto t0 = std::chrono::steady_clock::now();
    const GsImage img = model.render(s, c, pose, time, {}, o.threads);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cv::Mat truth = read_rgb8(truth_file);
    if (truth.cols != c.width || truth.rows != c.height) cv::resize(truth, truth, cv::Size(c.width, c.height), 0, 0, cv::INTER_AREA);
    if (set == "held_out") captured_held_out[truth_file] = truth;
    const cv::Mat pred = encode_srgb8(img.radiance, float(exposure));
    if (!o.save_dir.empty()) write_rgb8(fs::path(o.save_dir) / set / (name + ".png"), pred);
    // The static background alone, where no moving object (nor its shadow) is at that time:
    // what the background costs apart from what the moving cars cost. Not scored where moving
    // objects cover nearly all of the view.
    cv::Mat still;
    cv::bitwise_not(moving_object_mask(s, moving, c, pose, time), still);
    json r{{"set", set}, {"name", name}, {"psnr", psnr(pred, truth)}, {"ssim", ssim(pred, truth)}, {"render_s", secs}};
    if (cv::countNonZero(still) >= 0.05 * double(still.total())) r["psnr_static"] = psnr(pred, truth, still);
    views.push_back(r);
    sets[set].push_back(r);
  };
  // Held-out captured images.
  for (const auto& f : s.frames) {
    if (!held_out(f.index, o.holdout)) continue;
    for (const auto& [cam_name, ref] : f.images) {
      const auto* cam = s.camera(cam_name);
      char name[64];
      std::snprintf(name, sizeof name, "%s_%06d", cam_name.c_str(), f.index);
      evaluate("held_out", name, *cam, model.corrected_pose(s, f.index, cam_name), ref.timestamp_s,
               model.exposure(s, f.index, cam_name), s.dir / ref.path);
    }
  }
  // The demo scene's ground-truth views.
  const fs::path vj = s.dir / "ground_truth" / "views.json";
  double ceiling_psnr = 0, ceiling_ssim = 0;
  int ceiling_n = 0;
  if (o.ground_truth && fs::exists(vj)) {
    const json doc = scene::read_json_file(vj);  // outlives the readers, which refer to it
    const scene::FieldReader listed = scene::FieldReader(vj, doc).at("views");
    for (size_t i = 0; i < listed.array_size(); ++i) {
      const scene::FieldReader v = listed.at(i);
      const auto* cam = s.camera(v.at("camera").str());
      if (cam == nullptr) continue;
      const int frame = v.at("frame").integer();
      const std::string shift = v.at("shift").str(), name = v.at("name").str();
      const fs::path image = s.dir / v.at("image").str();
      const double time = v.at("timestamp_s").number(), exposure = v.at("exposure_s").number();
      if (shift == "none" && held_out(frame, o.holdout)) {
        // The captured image against its noise-free view (same instant, same true pose): what
        // a perfect model would score on the held-out set, whose images carry sensor and
        // path-tracing noise.
        const scene::ImageRef* ref = nullptr;
        if (const auto* f = s.frame(frame); f != nullptr && f->images.count(cam->name)) ref = &f->images.at(cam->name);
        const auto captured = ref != nullptr ? captured_held_out.find(s.dir / ref->path) : captured_held_out.end();
        if (captured != captured_held_out.end()) {
          const scene::Camera c = scaled_camera(*cam, width);
          cv::Mat truth = read_rgb8(image);
          if (truth.cols != c.width || truth.rows != c.height) cv::resize(truth, truth, cv::Size(c.width, c.height), 0, 0, cv::INTER_AREA);
          ceiling_psnr += psnr(captured->second, truth), ceiling_ssim += ssim(captured->second, truth), ++ceiling_n;
        }
      }
      evaluate(shift == "none" ? "truth_unshifted" : "truth_shifted_" + shift, name, *cam, v.at("camera_to_world").rigid(), time,
               exposure, image);
      // Diagnosis: the same view at the pose training believes (recorded, corrected). Much
      // better than at the true pose means the pose corrections did not find the truth.
      if (shift == "none")
        evaluate("truth_unshifted_at_model_pose", name, *cam, model.corrected_pose(s, frame, cam->name), time, exposure, image);
    }
  }
  json summary = json::object();
  for (const auto& [name, rs] : sets) {
    double p = 0, q = 0, t = 0, ps = 0;
    int n_static = 0;
    for (const auto& r : rs) {
      p += r["psnr"].get<double>(), q += r["ssim"].get<double>(), t += r["render_s"].get<double>();
      if (r.contains("psnr_static")) ps += r["psnr_static"].get<double>(), ++n_static;
    }
    const double n = double(rs.size());
    summary[name] = {{"count", rs.size()}, {"psnr", p / n}, {"ssim", q / n}, {"render_s", t / n}};
    if (n_static > 0) summary[name]["psnr_static"] = ps / n_static, summary[name]["static_count"] = n_static;
  }
  json report{{"sets", summary}, {"views", views}, {"width", width}};
  if (ceiling_n > 0)
    report["held_out_ceiling"] = {{"count", ceiling_n}, {"psnr", ceiling_psnr / ceiling_n}, {"ssim", ceiling_ssim / ceiling_n},
                                  {"what", "the captured held-out images against their noise-free ground-truth views: a perfect model's held_out score"}};
  if (o.ground_truth)
    if (auto e = evaluate_pose_error(model, s)) report["pose_error"] = std::move(*e);
  return report;
}

}  // namespace chatsim::render::gs
