#include "common/import/nuscenes_import.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "common/scene/camera_model.hpp"
#include "common/util/output_dir.hpp"

namespace chatsim::import {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using Table = std::map<std::string, json>;  // by token

json read_table(const fs::path& dir, const std::string& name) {
  const fs::path file = dir / (name + ".json");
  std::ifstream in(file);
  if (!in) throw ImportError(file.string() + ": missing (a nuScenes table; is --dataroot/--version right?)");
  try {
    return json::parse(in);
  } catch (const json::parse_error& e) {
    throw ImportError(file.string() + ": not valid JSON: " + e.what());
  }
}

Table by_token(const json& rows) {
  Table t;
  for (const auto& r : rows) t[r.at("token").get<std::string>()] = r;
  return t;
}

Eigen::Isometry3d pose_of(const json& row) {
  const auto q = row.at("rotation").get<std::array<double, 4>>();  // w, x, y, z
  const auto t = row.at("translation").get<std::array<double, 3>>();
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  m.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return m;
}

double yaw_of(const Eigen::Matrix3d& r) { return std::atan2(r(1, 0), r(0, 0)); }

// The ego path, smoothed and extended 30 m at both ends, as a lane centreline.
std::vector<Eigen::Vector3d> path_centerline(const std::vector<Eigen::Vector3d>& ego) {
  std::vector<Eigen::Vector3d> pts;
  for (const auto& p : ego)
    if (pts.empty() || (p - pts.back()).head<2>().norm() > 1.0) pts.push_back({p.x(), p.y(), 0});
  if (pts.size() < 2) {  // a standing ego: a short lane along its heading is all we know
    return {};
  }
  const Eigen::Vector3d d0 = (pts[0] - pts[1]).normalized(), d1 = (pts.back() - pts[pts.size() - 2]).normalized();
  std::vector<Eigen::Vector3d> out{pts.front() + 30 * d0};
  out.insert(out.end(), pts.begin(), pts.end());
  out.push_back(pts.back() + 30 * d1);
  return out;
}

std::vector<Eigen::Vector3d> offset_line(const std::vector<Eigen::Vector3d>& line, double left) {
  std::vector<Eigen::Vector3d> out;
  for (size_t i = 0; i < line.size(); ++i) {
    const Eigen::Vector3d d = (line[std::min(i + 1, line.size() - 1)] - line[i > 0 ? i - 1 : 0]).normalized();
    out.push_back(line[i] + left * Eigen::Vector3d(-d.y(), d.x(), 0));
  }
  return out;
}

}  // namespace

scene::Scene import_nuscenes(const NuScenesOptions& o, const fs::path& out, const Progress& progress, std::map<int, FrameLevel>* levels) {
  StagedOutputDir staged(out, "scene", o.force_output);  // refused before anything is read
  const fs::path& tmp = staged.path();
  const fs::path tables = o.dataroot / o.version;
  const json scenes = read_table(tables, "scene");
  const auto samples = by_token(read_table(tables, "sample"));
  const json sample_data = read_table(tables, "sample_data");
  const auto ego_poses = by_token(read_table(tables, "ego_pose"));
  const auto calibrated = by_token(read_table(tables, "calibrated_sensor"));
  const auto sensors = by_token(read_table(tables, "sensor"));
  const json annotations = read_table(tables, "sample_annotation");
  const auto instances = by_token(read_table(tables, "instance"));
  const auto categories = by_token(read_table(tables, "category"));

  const json* sc = nullptr;
  std::string known;
  for (const auto& s : scenes) {
    known += (known.empty() ? "" : ", ") + s.at("name").get<std::string>();
    if (s.at("name") == o.scene) sc = &s;
  }
  if (sc == nullptr) throw ImportError("--scene " + o.scene + ": not in " + (tables / "scene.json").string() + " (scenes: " + known + ")");

  // Key-frame sample_data by sample and channel.
  std::map<std::string, std::map<std::string, const json*>> by_sample;
  for (const auto& d : sample_data) {
    if (!d.value("is_key_frame", false)) continue;
    const auto& cs = calibrated.at(d.at("calibrated_sensor_token").get<std::string>());
    const std::string channel = sensors.at(cs.at("sensor_token").get<std::string>()).at("channel");
    by_sample[d.at("sample_token").get<std::string>()][channel] = &d;
  }
  std::vector<std::string> sample_tokens;
  for (std::string t = sc->at("first_sample_token"); !t.empty(); t = samples.at(t).at("next").get<std::string>()) {
    sample_tokens.push_back(t);
    if (samples.at(t).at("next").get<std::string>().empty()) break;
  }

  scene::Scene s;
  s.name = o.scene;
  s.source = "nuscenes " + o.version;
  s.ego_origin = "rear_axle";
  s.lanes_source = "derived_from_ego_path";
  // Cameras: intrinsics and extrinsics from the first key frame (constant within a scene).
  const auto& first = by_sample.at(sample_tokens.front());
  for (const auto& cam : o.cameras) {
    const auto it = first.find(cam);
    if (it == first.end()) throw ImportError("--cameras: '" + cam + "' has no key-frame data in " + o.scene);
    const auto& cs = calibrated.at(it->second->at("calibrated_sensor_token").get<std::string>());
    const auto k = cs.at("camera_intrinsic");
    if (k.empty()) throw ImportError("--cameras: '" + cam + "' is not a camera");
    scene::Camera c;
    c.name = cam;
    c.width = it->second->at("width");
    c.height = it->second->at("height");
    c.fx = k[0][0];
    c.fy = k[1][1];
    c.cx = k[0][2];
    c.cy = k[1][2];
    c.sensor_to_ego = pose_of(cs);
    s.cameras.push_back(c);
  }
  if (!first.count("LIDAR_TOP")) throw ImportError(o.scene + ": no LIDAR_TOP key frames (the frame clock)");
  // World: the ego pose at frame 0, so "5 m ahead" is +x.
  const Eigen::Isometry3d global_to_world =
      pose_of(ego_poses.at(first.at("LIDAR_TOP")->at("ego_pose_token").get<std::string>())).inverse();
  const double t0 = first.at("LIDAR_TOP")->at("timestamp").get<double>() * 1e-6;

  const int total = int(sample_tokens.size());
  for (size_t f = 0; f < sample_tokens.size(); ++f) {
    const auto& sd = by_sample.at(sample_tokens[f]);
    const json& lidar = *sd.at("LIDAR_TOP");
    scene::Frame frame;
    frame.index = int(f);
    frame.timestamp_s = lidar.at("timestamp").get<double>() * 1e-6 - t0;
    frame.ego_to_world = global_to_world * pose_of(ego_poses.at(lidar.at("ego_pose_token").get<std::string>()));
    char name[32];
    std::snprintf(name, sizeof name, "%06zu", f);
    for (const auto& cam : s.cameras) {
      const auto it = sd.find(cam.name);
      if (it == sd.end()) continue;
      const json& d = *it->second;
      const fs::path src = o.dataroot / d.at("filename").get<std::string>();
      if (!fs::exists(src)) throw ImportError(src.string() + ": image listed in sample_data.json is missing");
      const fs::path rel = fs::path("images") / cam.name / (std::string(name) + src.extension().string());
      fs::create_directories(tmp / rel.parent_path());
      fs::copy_file(src, tmp / rel, fs::copy_options::overwrite_existing);
      scene::ImageRef img;
      img.path = rel;
      img.timestamp_s = d.at("timestamp").get<double>() * 1e-6 - t0;
      // Its own ego pose: the rig moved between the camera's and the LiDAR's trigger.
      img.camera_to_world = global_to_world * pose_of(ego_poses.at(d.at("ego_pose_token").get<std::string>())) *
                            cam.sensor_to_ego;
      frame.images.emplace(cam.name, img);
    }
    if (o.lidar) {
      const fs::path src = o.dataroot / lidar.at("filename").get<std::string>();
      const auto pts = scene::read_lidar(src, 5);
      const Eigen::Isometry3f lidar_to_ego =
          pose_of(calibrated.at(lidar.at("calibrated_sensor_token").get<std::string>())).cast<float>();
      std::vector<float> buf;
      buf.reserve(pts.size() * 4);
      for (const auto& p : pts) {
        const Eigen::Vector3f e = lidar_to_ego * p.xyz;
        buf.insert(buf.end(), {e.x(), e.y(), e.z(), p.intensity});
      }
      frame.lidar = fs::path("lidar") / (std::string(name) + ".bin");
      fs::create_directories(tmp / "lidar");
      std::ofstream(tmp / frame.lidar, std::ios::binary)
          .write(reinterpret_cast<const char*>(buf.data()), std::streamsize(buf.size() * sizeof(float)));
    }
    s.frames.push_back(std::move(frame));
    if (progress) progress(int(f) + 1, total, "frames");
  }
  s.frame_rate_hz = s.frames.size() > 1 ? (s.frames.size() - 1) / s.frames.back().timestamp_s : 2.0;

  // Boxes as tracks, one per instance.
  std::map<std::string, size_t> frame_of_sample;
  for (size_t f = 0; f < sample_tokens.size(); ++f) frame_of_sample[sample_tokens[f]] = f;
  std::map<std::string, scene::ObjectTrack> tracks;
  std::vector<std::string> order;
  for (const auto& a : annotations) {
    const auto fi = frame_of_sample.find(a.at("sample_token").get<std::string>());
    if (fi == frame_of_sample.end()) continue;
    const std::string inst = a.at("instance_token");
    auto [it, fresh] = tracks.try_emplace(inst);
    if (fresh) {
      order.push_back(inst);
      it->second.category = categories.at(instances.at(inst).at("category_token").get<std::string>()).at("name");
      const auto wlh = a.at("size").get<std::array<double, 3>>();
      it->second.size_lwh = Eigen::Vector3d(wlh[1], wlh[0], wlh[2]);
    }
    const Eigen::Isometry3d box = global_to_world * pose_of(a);
    it->second.track.push_back({int(fi->second), box.translation(), yaw_of(box.linear())});
  }
  std::sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
    return tracks[a].track.front().frame != tracks[b].track.front().frame
               ? tracks[a].track.front().frame < tracks[b].track.front().frame
               : a < b;
  });
  int n = 0;
  for (const auto& inst : order) {
    auto& t = tracks[inst];
    std::sort(t.track.begin(), t.track.end(), [](const auto& x, const auto& y) { return x.frame < y.frame; });
    t.id = "obj_" + std::to_string(++n);
    s.objects.push_back(t);
  }
  // nuScenes' ego poses have no height: each frame is levelled by its static boxes.
  std::map<int, FrameLevel> fitted;
  if (o.level_frames) {
    fitted = fit_frame_levels(s);
    apply_frame_levels(s, fitted);
  }
  if (levels) *levels = fitted;
  std::vector<Eigen::Vector3d> ego_path;
  for (const auto& f : s.frames) ego_path.push_back(f.ego_to_world.translation());

  // Colour per vehicle: the median of the central part of its box in the image where it is largest.
  if (o.estimate_colors) {
    struct View {
      size_t object;
      cv::Rect rect;
    };
    std::map<std::pair<int, std::string>, std::vector<View>> by_image;
    for (size_t i = 0; i < s.objects.size(); ++i) {
      const auto& ob = s.objects[i];
      if (!ob.has_category_prefix("vehicle")) continue;
      double best_area = 0;
      std::pair<int, std::string> best_key;
      cv::Rect best_rect;
      for (const auto& p : ob.track) {
        const auto& frame = s.frames[size_t(p.frame)];
        for (const auto& cam : s.cameras) {
          if (!frame.images.count(cam.name)) continue;
          const auto pose = s.camera_to_world(frame, cam);
          double u0 = 1e9, v0 = 1e9, u1 = -1e9, v1 = -1e9;
          bool ok = true;
          for (const auto& c : scene::box_corners(p.center, ob.size_lwh, p.yaw)) {
            const auto pr = scene::project(cam, pose, c, 1.0);
            if (!pr) {
              ok = false;
              break;
            }
            u0 = std::min(u0, pr->pixel.x());
            v0 = std::min(v0, pr->pixel.y());
            u1 = std::max(u1, pr->pixel.x());
            v1 = std::max(v1, pr->pixel.y());
          }
          if (!ok || u0 < 0 || v0 < 0 || u1 >= cam.width || v1 >= cam.height) continue;  // wholly in view only
          const double area = (u1 - u0) * (v1 - v0);
          if (area > best_area) {
            best_area = area;
            best_key = {p.frame, cam.name};
            // The middle of the box: body paint, not road or windows at the edges.
            best_rect = cv::Rect(int(u0 + 0.3 * (u1 - u0)), int(v0 + 0.45 * (v1 - v0)), std::max(1, int(0.4 * (u1 - u0))),
                                 std::max(1, int(0.3 * (v1 - v0))));
          }
        }
      }
      if (best_area > 400) by_image[best_key].push_back({i, best_rect});
    }
    int done = 0;
    for (const auto& [key, views] : by_image) {
      const cv::Mat img = cv::imread((tmp / s.frames[size_t(key.first)].images.at(key.second).path).string());
      if (img.empty()) continue;
      for (const auto& v : views) {
        const cv::Mat roi = img(v.rect & cv::Rect(0, 0, img.cols, img.rows));
        std::array<std::vector<uchar>, 3> ch;
        for (int y = 0; y < roi.rows; ++y)
          for (int x = 0; x < roi.cols; ++x)
            for (int k = 0; k < 3; ++k) ch[size_t(k)].push_back(roi.at<cv::Vec3b>(y, x)[k]);
        if (ch[0].empty()) continue;
        std::array<int, 3> rgb{};
        for (int k = 0; k < 3; ++k) {
          auto& c = ch[size_t(k)];
          std::nth_element(c.begin(), c.begin() + long(c.size() / 2), c.end());
          rgb[size_t(2 - k)] = c[c.size() / 2];  // OpenCV is BGR
        }
        s.objects[v.object].color_rgb = rgb;
      }
      if (progress) progress(++done, int(by_image.size()), "vehicle colours");
    }
  }

  // Lanes from the ego path: the ego lane and one lane of standard width each side, direction unknown.
  const auto centre = path_centerline(ego_path);
  if (!centre.empty()) {
    s.lanes = scene::LaneMap({{"ego_lane", "driving", 3.5, centre, scene::TrafficDirection::Forward, {}},
                              {"left_of_ego", "driving", 3.5, offset_line(centre, 3.5), scene::TrafficDirection::Both, {}},
                              {"right_of_ego", "driving", 3.5, offset_line(centre, -3.5), scene::TrafficDirection::Both, {}}});
  }
  scene::save_scene(s, tmp);
  staged.commit();
  s.dir = staged.target();
  return s;
}

}  // namespace chatsim::import
