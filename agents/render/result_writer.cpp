#include "agents/render/result_writer.hpp"

#include <fstream>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "agents/render/foreground_role.hpp"
#include "common/scene/objects.hpp"
#include "render/gs/model.hpp"

namespace chatsim::agents::render {
namespace fs = std::filesystem;
using nlohmann::json;

std::string kitti_type(const std::string& c) {
  auto has = [&](const char* p) { return c.rfind(p, 0) == 0; };
  if (has("vehicle.bus")) return "Bus";
  if (has("vehicle.truck") || has("vehicle.construction") || has("vehicle.trailer")) return "Truck";
  if (has("vehicle.emergency")) return "Van";
  if (has("vehicle.motorcycle") || has("vehicle.bicycle")) return "Cyclist";
  if (has("vehicle.van")) return "Van";
  if (has("vehicle")) return "Car";
  if (has("human")) return "Pedestrian";
  return "Misc";
}

namespace {

json camera_box(const ViewImage& im, const Eigen::Vector3d& center, const Eigen::Vector3d& size, double yaw) {
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const auto& c : scene::box_corners(center, size, yaw)) {
    const Eigen::Vector3d p = im.pose.inverse() * c;
    if (p.z() < 0.1) return nullptr;  // reaches behind the camera: not labelled in this view
    const double u = im.cam.fx * p.x() / p.z() + im.cam.cx, v = im.cam.fy * p.y() / p.z() + im.cam.cy;
    x0 = std::min(x0, u), x1 = std::max(x1, u), y0 = std::min(y0, v), y1 = std::max(y1, v);
  }
  const double W = im.cam.width, H = im.cam.height;
  const double cx0 = std::clamp(x0, 0.0, W - 1), cx1 = std::clamp(x1, 0.0, W - 1), cy0 = std::clamp(y0, 0.0, H - 1),
               cy1 = std::clamp(y1, 0.0, H - 1);
  if (cx1 <= cx0 || cy1 <= cy0) return nullptr;
  const double full = (x1 - x0) * (y1 - y0), inside = (cx1 - cx0) * (cy1 - cy0);
  return {{"bbox_xyxy", {cx0, cy0, cx1, cy1}}, {"truncated", full > 0 ? std::clamp(1 - inside / full, 0.0, 1.0) : 1.0}};
}

}  // namespace

json edited_labels(const scene::Scene& s, const json& edit, const std::vector<ViewImage>& images) {
  const auto removed = edit.value("removed", std::vector<std::string>{});
  json frames = json::array();
  for (const auto& f : s.frames) {
    std::vector<const ViewImage*> ims;
    for (const auto& im : images)
      if (im.frame == f.index) ims.push_back(&im);
    if (ims.empty()) continue;
    const double t = ims.front()->time;
    json objects = json::array();
    auto add = [&](const std::string& id, const std::string& category, const std::string& source, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& size, double yaw) {
      json cams = json::object();
      for (const auto* im : ims)
        if (auto b = camera_box(*im, c, size, yaw); !b.is_null()) cams[im->camera] = b;
      objects.push_back({{"id", id}, {"category", category}, {"source", source}, {"center", {c.x(), c.y(), c.z()}},
                         {"size_lwh", {size.x(), size.y(), size.z()}}, {"yaw", yaw}, {"cameras", cams}});
    };
    for (const auto& o : s.objects) {
      if (std::find(removed.begin(), removed.end(), o.id) != removed.end()) continue;
      const auto p = chatsim::render::gs::object_pose(s, o, t);
      if (!p) continue;
      add(o.id, o.category, "scene", p->translation(), o.size_lwh, std::atan2(p->linear()(1, 0), p->linear()(0, 0)));
    }
    for (const auto& v : edit.value("added", json::array())) {
      const auto p = added_vehicle_pose(s, v, t);
      if (!p) continue;
      const auto sz = v.value("size_lwh", std::array<double, 3>{4.5, 1.85, 1.45});
      const Eigen::Vector3d size(sz[0], sz[1], sz[2]);
      add(v.value("id", std::string("added")), v.value("category", std::string("vehicle.car")), "added",
          p->translation() + Eigen::Vector3d(0, 0, size.z() / 2), size, std::atan2(p->linear()(1, 0), p->linear()(0, 0)));
    }
    frames.push_back({{"frame", f.index}, {"timestamp_s", t}, {"objects", objects}});
  }
  return {{"format", "chatsim-labels/1"},
          {"frame", "world (scene.json), box centre, size length-width-height, yaw about +z"},
          {"frames", frames}};
}

void write_kitti_labels(const json& labels, const std::vector<ViewImage>& images, const fs::path& dir) {
  for (const auto& im : images) {
    const json* frame = nullptr;
    for (const auto& f : labels["frames"])
      if (f["frame"] == im.frame) frame = &f;
    char name[32];
    std::snprintf(name, sizeof name, "%06d.txt", im.frame);
    fs::create_directories(dir / im.camera);
    std::ofstream out(dir / im.camera / name);
    if (frame == nullptr) continue;
    for (const auto& o : (*frame)["objects"]) {
      if (!o["cameras"].contains(im.camera)) continue;
      const auto& b = o["cameras"][im.camera];
      const Eigen::Vector3d c(o["center"][0], o["center"][1], o["center"][2]);
      const Eigen::Vector3d size(o["size_lwh"][0], o["size_lwh"][1], o["size_lwh"][2]);
      // KITTI: location is the bottom centre in camera coordinates (x right, y down, z ahead),
      // rotation_y the yaw about the camera's y axis, alpha the observation angle.
      const Eigen::Vector3d bottom = im.pose.inverse() * (c - Eigen::Vector3d(0, 0, size.z() / 2));
      const Eigen::Vector3d heading = im.pose.linear().transpose() *
                                      Eigen::Vector3d(std::cos(o["yaw"].get<double>()), std::sin(o["yaw"].get<double>()), 0);
      const double ry = std::atan2(-heading.z(), heading.x());
      const double alpha = ry - std::atan2(bottom.x(), bottom.z());
      char line[512];
      std::snprintf(line, sizeof line, "%s %.2f 3 %.2f %.2f %.2f %.2f %.2f %.2f %.2f %.2f %.2f %.2f %.2f %.2f\n",
                    kitti_type(o["category"]).c_str(), b["truncated"].get<double>(), std::remainder(alpha, 2 * M_PI),
                    b["bbox_xyxy"][0].get<double>(), b["bbox_xyxy"][1].get<double>(), b["bbox_xyxy"][2].get<double>(),
                    b["bbox_xyxy"][3].get<double>(), size.z(), size.y(), size.x(), bottom.x(), bottom.y(), bottom.z(),
                    std::remainder(ry, 2 * M_PI));
      out << line;
    }
  }
}

std::string write_side_by_side_video(const fs::path& file, const std::vector<std::vector<cv::Mat>>& frames, double fps) {
  if (frames.empty() || frames.front().empty()) throw std::invalid_argument("no frames for the video");
  int w = 0, h = frames.front().front().rows;
  for (const auto& m : frames.front()) w += m.cols;
  w -= w % 2, h -= h % 2;  // H.264 wants even sizes
  const fs::path tmp = file.parent_path() / (".video.part" + std::to_string(getpid()) + ".mp4");
  std::string codec = "avc1";
  cv::VideoWriter vw(tmp.string(), cv::VideoWriter::fourcc('a', 'v', 'c', '1'), std::max(1.0, fps), cv::Size(w, h));
  if (!vw.isOpened()) {
    codec = "mp4v";
    vw.open(tmp.string(), cv::VideoWriter::fourcc('m', 'p', '4', 'v'), std::max(1.0, fps), cv::Size(w, h));
  }
  if (!vw.isOpened()) throw std::runtime_error("cannot write a video at " + file.string() + " (no MP4 encoder)");
  for (const auto& row : frames) {
    cv::Mat joined;
    cv::hconcat(row, joined);
    cv::Mat bgr;
    cv::cvtColor(joined(cv::Rect(0, 0, w, h)), bgr, cv::COLOR_RGB2BGR);
    vw.write(bgr);
  }
  vw.release();
  fs::rename(tmp, file);
  return codec;
}

}  // namespace chatsim::agents::render
