#include "common/scene/scene_summary.hpp"

#include <map>
#include <cstdio>
#include <sstream>

namespace chatsim::scene {

nlohmann::json summarize(const Scene& scene) {
  using nlohmann::json;
  json cams = json::array();
  for (const auto& c : scene.cameras)
    cams.push_back({{"name", c.name}, {"width", c.width}, {"height", c.height},
                    {"hfov_deg", 2 * std::atan(c.width / (2 * c.fx)) * 180 / M_PI}});
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& f : scene.frames) {
    lo = lo.cwiseMin(f.ego_to_world.translation());
    hi = hi.cwiseMax(f.ego_to_world.translation());
  }
  std::map<std::string, int> by_category;
  for (const auto& o : scene.objects) by_category[o.category]++;
  std::map<std::string, int> lanes_by_type;
  double lane_length = 0;
  for (const auto& l : scene.lanes.lanes()) {
    lanes_by_type[l.type]++;
    lane_length += l.length();
  }
  size_t images = 0, exposures = 0;
  for (const auto& f : scene.frames) {
    images += f.images.size();
    for (const auto& [_, img] : f.images) exposures += img.exposure_s ? 1 : 0;
  }
  const double path = [&] {
    double d = 0;
    for (size_t i = 1; i < scene.frames.size(); ++i)
      d += (scene.frames[i].ego_to_world.translation() - scene.frames[i - 1].ego_to_world.translation()).norm();
    return d;
  }();
  return {{"name", scene.name},
          {"source", scene.source},
          {"layout_only", scene.layout_only},
          {"cameras", cams},
          {"frames", scene.frames.size()},
          {"duration_s", scene.duration_s()},
          {"frame_rate_hz", scene.frame_rate_hz},
          {"images", images},
          {"images_with_exposure", exposures},
          {"ego_path_m", path},
          {"ego_extent_min", {lo.x(), lo.y(), lo.z()}},
          {"ego_extent_max", {hi.x(), hi.y(), hi.z()}},
          {"objects", scene.objects.size()},
          {"objects_by_category", by_category},
          {"lanes", scene.lanes.lanes().size()},
          {"lanes_by_type", lanes_by_type},
          {"lane_length_m", lane_length},
          {"lanes_source", scene.lanes_source.empty() ? "map" : scene.lanes_source}};
}

std::string summary_text(const nlohmann::json& s) {
  std::ostringstream o;
  o << "scene " << s["name"].get<std::string>() << " (" << s["source"].get<std::string>() << ")"
    << (s["layout_only"].get<bool>() ? ", layout only" : "") << "\n";
  o << "  cameras: " << s["cameras"].size() << "\n";
  for (const auto& c : s["cameras"])
    o << "    " << c["name"].get<std::string>() << " " << c["width"] << "x" << c["height"] << ", horizontal FOV "
      << int(std::lround(c["hfov_deg"].get<double>())) << " deg\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "  frames: %d over %.1f s (%.1f Hz), ", s["frames"].get<int>(), s["duration_s"].get<double>(),
                s["frame_rate_hz"].get<double>());
  o << buf << s["images"] << " images (" << s["images_with_exposure"] << " with exposure)\n";
  std::snprintf(buf, sizeof buf, "  ego path: %.1f m\n", s["ego_path_m"].get<double>());
  o << buf;
  o << "  objects: " << s["objects"] << "\n";
  for (const auto& [cat, n] : s["objects_by_category"].items()) o << "    " << cat << ": " << n << "\n";
  std::snprintf(buf, sizeof buf, "%.0f", s["lane_length_m"].get<double>());
  o << "  lanes: " << s["lanes"] << " (" << buf << " m of centreline, source: "
    << s["lanes_source"].get<std::string>() << ")\n";
  for (const auto& [type, n] : s["lanes_by_type"].items()) o << "    " << type << ": " << n << "\n";
  return o.str();
}

}  // namespace chatsim::scene
