#include "render/inpaint/deletion_eval.hpp"

#include <chrono>
#include <fstream>
#include <map>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "render/image_io.hpp"
#include "render/image_metrics.hpp"
#include "render/inpaint/deletion.hpp"

namespace chatsim::render::inpaint {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Plate {
  std::string object, camera, path;
  int frame;
  cv::Rect rect;
};

// Mean over ground cells of the spread (standard deviation, 8-bit levels) of the values that
// different frames put there: zero for a fill that never changes.
double ground_flicker(const scene::Scene& s, const std::string& id, const std::vector<DeletionImage>& images,
                      const std::vector<cv::Mat>& encoded, const DeletionOptions& o) {
  const auto* obj = s.object(id);
  if (obj == nullptr) return 0;
  std::map<std::pair<int, int>, std::vector<float>> cells;
  const double res = 0.1;
  for (size_t i = 0; i < images.size(); ++i) {
    const auto& im = images[i];
    const cv::Mat mask = deletion_mask(s, im, {id}, o);
    const auto pose = obj->at(im.frame);
    if (!pose) continue;
    const double z = pose->center.z() - obj->size_lwh.z() / 2;
    for (int y = 0; y < mask.rows; y += 2)
      for (int x = 0; x < mask.cols; x += 2) {
        if (!mask.at<uchar>(y, x)) continue;
        const Eigen::Vector3d d = im.pose.linear() * Eigen::Vector3d((x - im.cam.cx) / im.cam.fx, (y - im.cam.cy) / im.cam.fy, 1);
        if (d.z() > -1e-6) continue;
        const Eigen::Vector3d p = im.pose.translation() + d * ((z - im.pose.translation().z()) / d.z());
        if ((p - pose->center).head<2>().norm() > obj->size_lwh.head<2>().norm()) continue;  // the ground right there
        const cv::Vec3b c = encoded[i].at<cv::Vec3b>(y, x);
        cells[{int(std::floor(p.x() / res)), int(std::floor(p.y() / res))}].push_back((c[0] + c[1] + c[2]) / 3.0f);
      }
  }
  double sum = 0;
  int n = 0;
  for (const auto& [k, v] : cells) {
    if (v.size() < 2) continue;
    double m = 0, q = 0;
    for (float x : v) m += x;
    m /= double(v.size());
    for (float x : v) q += (x - m) * (x - m);
    sum += std::sqrt(q / double(v.size()));
    ++n;
  }
  return n > 0 ? sum / n : 0;
}

}  // namespace

json evaluate_deletion(const scene::Scene& s, const DeletionEvalOptions& opt) {
  const fs::path pj = s.dir / "ground_truth" / "clean_plates.json";
  if (!fs::exists(pj)) throw std::invalid_argument(s.dir.string() + ": no ground_truth/clean_plates.json (render the demo scene with its plates)");
  const json doc = json::parse(std::ifstream(pj));
  std::map<std::string, std::vector<Plate>> plates;
  std::map<std::string, long> area;
  for (const auto& p : doc["plates"]) {
    Plate pl{p["object"], p["camera"], p["path"], p["frame"], cv::Rect(p["x"], p["y"], p["width"], p["height"])};
    if (!opt.objects.empty() && std::find(opt.objects.begin(), opt.objects.end(), pl.object) == opt.objects.end()) continue;
    area[pl.object] += pl.rect.area();
    plates[pl.object].push_back(pl);
  }
  std::vector<std::string> ids;
  for (const auto& [id, a] : area) ids.push_back(id);
  std::sort(ids.begin(), ids.end(), [&](const auto& a, const auto& b) { return area[a] > area[b]; });
  if (opt.max_objects > 0 && int(ids.size()) > opt.max_objects) ids.resize(size_t(opt.max_objects));
  const std::vector<DeletionImage> sources = scene_images(s);
  DeletionOptions dopt;
  json per_object = json::array();
  double ours_psnr = 0, base_psnr = 0, ours_ssim = 0, base_ssim = 0, ours_t = 0, base_t = 0, ours_flicker = 0, base_flicker = 0;
  int n_plates = 0, n_images = 0, n_objects = 0;
  for (const auto& id : ids) {
    if (opt.progress)
      opt.progress("object " + std::to_string(&id - ids.data() + 1) + "/" + std::to_string(ids.size()) + ": " + id);
    // Every image the object appears in.
    std::vector<DeletionImage> targets;
    std::vector<cv::Mat> masks;
    for (const auto& im : sources) {
      const cv::Mat m = deletion_mask(s, im, {id}, dopt);
      if (cv::countNonZero(m) == 0) continue;
      targets.push_back(im);
      targets.back().radiance = im.radiance.clone();
      masks.push_back(m);
    }
    if (targets.empty()) continue;
    std::vector<DeletionImage> ours = targets;
    for (auto& im : ours) im.radiance = im.radiance.clone();  // cv::Mat copies share pixels
    const DeletionStats st = delete_objects(s, {id}, ours, sources, dopt, opt.background);
    // Baseline: Telea on the 8-bit images with the same masks.
    const auto tb = std::chrono::steady_clock::now();
    std::vector<cv::Mat> base_enc;
    for (size_t i = 0; i < targets.size() && opt.baseline; ++i) {
      cv::Mat enc = encode_srgb8(targets[i].radiance, float(targets[i].exposure)), out;
      cv::inpaint(enc, masks[i], out, 5, cv::INPAINT_TELEA);
      base_enc.push_back(out);
    }
    const double base_secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - tb).count();
    std::vector<cv::Mat> ours_enc;
    for (const auto& im : ours) ours_enc.push_back(encode_srgb8(im.radiance, float(im.exposure)));
    double op = 0, bp = 0, os = 0, bs = 0;
    int np = 0;
    for (const auto& pl : plates[id]) {
      size_t k = 0;
      while (k < targets.size() && !(targets[k].frame == pl.frame && targets[k].camera == pl.camera)) ++k;
      if (k == targets.size()) continue;
      const cv::Mat plate = read_rgb8(s.dir / pl.path);
      const cv::Mat m = masks[k](pl.rect);
      if (cv::countNonZero(m) < 20) continue;
      op += psnr(ours_enc[k](pl.rect), plate, m), os += ssim(ours_enc[k](pl.rect), plate, m);
      if (opt.baseline) bp += psnr(base_enc[k](pl.rect), plate, m), bs += ssim(base_enc[k](pl.rect), plate, m);
      ++np;
      if (!opt.save_dir.empty()) {
        const fs::path d = fs::path(opt.save_dir) / id;
        const std::string stem = pl.camera + "_" + std::to_string(pl.frame);
        write_rgb8(d / (stem + "_before.png"), encode_srgb8(targets[k].radiance, float(targets[k].exposure)));
        write_rgb8(d / (stem + "_after.png"), ours_enc[k]);
        if (opt.baseline) write_rgb8(d / (stem + "_telea.png"), base_enc[k]);
        write_rgb8(d / (stem + "_plate.png"), plate);
      }
    }
    if (np == 0) continue;
    const double of = ground_flicker(s, id, ours, ours_enc, dopt), bf = opt.baseline ? ground_flicker(s, id, targets, base_enc, dopt) : 0;
    const double n = double(targets.size());
    json obj{{"object", id}, {"images", targets.size()}, {"plates", np}, {"psnr", op / np}, {"ssim", os / np},
             {"seconds_per_image", st.seconds / n}, {"flicker", of}, {"ground_seen", st.ground_seen}};
    if (opt.background) obj.update({{"field_fills", st.field_fills}, {"field_rejected", st.field_rejected}});
    // The baseline's fields only where it ran: no numbers rather than zeros.
    if (opt.baseline)
      obj.update({{"baseline_psnr", bp / np}, {"baseline_ssim", bs / np}, {"baseline_seconds_per_image", base_secs / n}, {"baseline_flicker", bf}});
    per_object.push_back(obj);
    ours_psnr += op / np, base_psnr += bp / np, ours_ssim += os / np, base_ssim += bs / np;
    ours_t += st.seconds, base_t += base_secs, ours_flicker += of, base_flicker += bf;
    n_plates += np, n_images += int(targets.size()), ++n_objects;
  }
  if (n_objects == 0) throw std::invalid_argument("no object with a usable clean plate");
  json summary{{"objects", n_objects},
               {"plates", n_plates},
               {"psnr", ours_psnr / n_objects},
               {"ssim", ours_ssim / n_objects},
               {"seconds_per_image", ours_t / n_images},
               {"flicker", ours_flicker / n_objects},
               {"behind_the_vehicle", opt.background ? "radiance field, or 2D exemplar inpainting where its surface lies before the vehicle's box"
                                                     : "2D exemplar inpainting"}};
  if (opt.baseline)
    summary.update({{"baseline_psnr", base_psnr / n_objects}, {"psnr_gain_db", (ours_psnr - base_psnr) / n_objects},
                    {"baseline_ssim", base_ssim / n_objects}, {"baseline_seconds_per_image", base_t / n_images},
                    {"baseline_flicker", base_flicker / n_objects}});
  return {{"objects", per_object}, {"summary", summary}, {"targets", {{"psnr_gain_db", 3}, {"seconds_per_image", 0.5}}}};
}

json deletion_before_after(const scene::Scene& s, const std::string& prefix, std::shared_ptr<const gs::RadianceField> field) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<DeletionImage> sources = scene_images(s);
  DeletionOptions dopt;
  // The parked vehicle (moves under half a metre) that covers the most of one image, whole and
  // with nothing in front of it.
  std::string best_id;
  size_t best_image = 0;
  double best_share = 0;
  for (const auto& obj : s.objects) {
    if (!obj.has_category_prefix("vehicle") || obj.track.size() < 2) continue;
    if ((obj.track.front().center - obj.track.back().center).norm() > 0.5) continue;
    for (size_t i = 0; i < sources.size(); ++i) {
      const cv::Mat m = deletion_mask(s, sources[i], {obj.id}, dopt);
      const cv::Rect r = cv::boundingRect(m);
      if (r.empty() || r.x <= 0 || r.y <= 0 || r.x + r.width >= m.cols || r.y + r.height >= m.rows) continue;  // cut off
      // In the clear: no nearer labelled object's box over it (those pixels would stay).
      const Eigen::Isometry3d w2c = sources[i].pose.inverse();
      const double depth = (w2c * obj.track.front().center).z();
      bool covered = false;
      for (const auto& other : s.objects) {
        if (other.id == obj.id || other.track.empty() || (w2c * other.track.front().center).z() >= depth) continue;
        if (cv::countNonZero(deletion_mask(s, sources[i], {other.id}, dopt) & m) > 0) covered = true;
        if (covered) break;
      }
      if (covered) continue;
      const double share = double(cv::countNonZero(m)) / double(m.total());
      if (share > best_share && share < 0.25) best_share = share, best_id = obj.id, best_image = i;
    }
  }
  if (best_id.empty()) throw std::invalid_argument(s.dir.string() + ": no parked vehicle seen whole in any image");
  std::vector<DeletionImage> target{sources[best_image]};
  target[0].radiance = sources[best_image].radiance.clone();
  const cv::Mat mask = deletion_mask(s, target[0], {best_id}, dopt);
  const DeletionStats st = delete_objects(s, {best_id}, target, sources, dopt);
  const cv::Mat before = encode_srgb8(sources[best_image].radiance, float(sources[best_image].exposure));
  cv::Mat telea;
  cv::inpaint(before, mask, telea, 5, cv::INPAINT_TELEA);
  write_rgb8(prefix + "before.png", before);
  write_rgb8(prefix + "after.png", encode_srgb8(target[0].radiance, float(target[0].exposure)));
  write_rgb8(prefix + "telea.png", telea);
  json images{prefix + "before.png", prefix + "after.png", prefix + "telea.png"};
  json out{{"scene", s.name}, {"object", best_id}, {"camera", target[0].camera}, {"frame", target[0].frame},
           {"mask_share", best_share}, {"ground_seen", st.ground_seen}, {"seconds", st.seconds},
           {"fallback_pixels", st.fallback_pixels}};  // what the ground map could not fill: 2D fill, or the field's render
  if (field) {
    // As the agent does: every image in the field's units, the field behind the vehicle.
    const std::vector<DeletionImage> field_sources = in_field_units(sources, s, *field);
    std::vector<DeletionImage> with_field{field_sources[best_image]};
    with_field[0].radiance = field_sources[best_image].radiance.clone();
    const DeletionStats field_stats = delete_objects(s, {best_id}, with_field, field_sources, dopt, field_renderer(field, s, dopt));
    write_rgb8(prefix + "after-field.png", encode_srgb8(with_field[0].radiance, float(with_field[0].exposure)));
    images.push_back(prefix + "after-field.png");
    out["seconds_with_field"] = field_stats.seconds;
    out["field_fits"] = field_stats.field_fills > 0;  // else 2D inpainting filled behind the vehicle
  }
  out["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out["images"] = images;
  return out;
}

}  // namespace chatsim::render::inpaint
