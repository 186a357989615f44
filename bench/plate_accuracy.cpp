#include "bench/plate_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

namespace chatsim::bench {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Plate {
  std::string object, camera, path;
  int frame = 0;
  cv::Rect rect;
};

cv::Mat read_image(const fs::path& p) {
  if (!fs::exists(p)) throw std::runtime_error(p.string() + ": missing image");
  cv::Mat m = cv::imread(p.string(), cv::IMREAD_COLOR);
  if (m.empty()) throw std::runtime_error(p.string() + ": unreadable image");
  return m;
}

double psnr(double sse, long n) { return n == 0 ? 0.0 : 10 * std::log10(255.0 * 255.0 / std::max(1e-12, sse / double(n))); }

}  // namespace

PlateAccuracy plate_accuracy(const scene::Scene& s, const fs::path& result_dir, const std::vector<std::string>& removed) {
  const fs::path index = s.dir / "ground_truth" / "clean_plates.json";
  std::ifstream in(index);
  if (!in) throw std::runtime_error(index.string() + ": missing: the scene has no clean plates (render it with chatsim scene demo)");
  const json j = json::parse(in);
  std::vector<Plate> plates;
  for (const auto& p : j.at("plates"))
    if (std::find(removed.begin(), removed.end(), p.at("object").get<std::string>()) != removed.end())
      plates.push_back({p["object"], p["camera"], p["path"], p["frame"], cv::Rect(p["x"], p["y"], p["width"], p["height"])});
  PlateAccuracy out;
  double sse = 0, sse_captured = 0;
  for (const auto& p : plates) {
    const bool overlaps = std::any_of(plates.begin(), plates.end(), [&](const Plate& q) {
      return &q != &p && q.camera == p.camera && q.frame == p.frame && (q.rect & p.rect).area() > 0;
    });
    if (overlaps) continue;
    const auto frame = std::find_if(s.frames.begin(), s.frames.end(), [&](const scene::Frame& f) { return f.index == p.frame; });
    if (frame == s.frames.end() || !frame->images.count(p.camera)) continue;
    char name[32];
    std::snprintf(name, sizeof name, "%06d.png", p.frame);
    const cv::Mat result = read_image(result_dir / "frames" / p.camera / name)(p.rect);
    const cv::Mat captured = read_image(s.dir / frame->images.at(p.camera).path)(p.rect);
    const cv::Mat plate = read_image(s.dir / p.path);
    if (plate.size() != p.rect.size()) throw std::runtime_error((s.dir / p.path).string() + ": size differs from its entry in " + index.string());
    ++out.plates;
    for (int y = 0; y < plate.rows; ++y)
      for (int x = 0; x < plate.cols; ++x) {
        const cv::Vec3b g = plate.at<cv::Vec3b>(y, x), c = captured.at<cv::Vec3b>(y, x), r = result.at<cv::Vec3b>(y, x);
        if (cv::norm(cv::Vec3i(g) - cv::Vec3i(c), cv::NORM_INF) <= 1) continue;  // the vehicle did not change it
        ++out.pixels;
        for (int k = 0; k < 3; ++k) {
          sse += 1.0 * (r[k] - g[k]) * (r[k] - g[k]) / 3;
          sse_captured += 1.0 * (c[k] - g[k]) * (c[k] - g[k]) / 3;
        }
      }
  }
  out.psnr_db = psnr(sse, out.pixels);
  out.captured_psnr_db = psnr(sse_captured, out.pixels);
  return out;
}

json to_json(const PlateAccuracy& a) {
  return {{"plates", a.plates}, {"pixels", a.pixels}, {"psnr_db", a.psnr_db}, {"captured_psnr_db", a.captured_psnr_db}};
}

}  // namespace chatsim::bench
