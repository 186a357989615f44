#include "common/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "common/scene/scene_json.hpp"
#include "common/util/path_policy.hpp"

namespace chatsim::scene {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string describe(const fs::path& file, const std::string& field, const std::string& problem) {
  std::string out = file.string();
  if (!field.empty()) out += ": " + field;
  return out + ": " + problem;
}

Camera read_camera(const FieldReader& c) {
  Camera cam;
  cam.name = c.at("name").str();
  cam.width = c.at("width").integer();
  cam.height = c.at("height").integer();
  if (cam.width <= 0 || cam.height <= 0) c.fail("width and height must be positive");
  cam.fx = c.at("fx").number();
  cam.fy = c.at("fy").number();
  if (cam.fx <= 0 || cam.fy <= 0) c.fail("fx and fy must be positive (focal lengths in pixels)");
  cam.cx = c.at("cx").number();
  cam.cy = c.at("cy").number();
  if (c.has("distortion")) cam.distortion_model = c.at("distortion").str_or("model", "none");
  if (cam.distortion_model != "none")
    c.at("distortion").at("model").fail("only model 'none' is supported; undistort the images first");
  cam.sensor_to_ego = c.at("sensor_to_ego").rigid();
  return cam;
}

Frame read_frame(const FieldReader& f, const Scene& scene, const LoadOptions& options) {
  Frame frame;
  frame.index = f.at("index").integer();
  frame.timestamp_s = f.at("timestamp_s").number();
  frame.ego_to_world = f.at("ego_to_world").rigid();
  if (f.has("images")) {
    const auto images = f.at("images");
    if (!images.json().is_object()) images.fail("expected an object keyed by camera name");
    for (const auto& [name, _] : images.json().items()) {
      const auto img = images.at(name);
      if (scene.camera(name) == nullptr)
        img.fail("unknown camera '" + name + "' (cameras: see scene.json 'cameras')");
      ImageRef ref;
      ref.path = img.at("path").str();
      if (!stays_inside(ref.path)) img.at("path").fail("must be a path inside the scene folder (relative, no '..' out of it)");
      ref.timestamp_s = img.has("timestamp_s") ? img.at("timestamp_s").number() : frame.timestamp_s;
      if (img.has("exposure_s")) {
        ref.exposure_s = img.at("exposure_s").number();
        if (*ref.exposure_s <= 0) img.at("exposure_s").fail("must be positive seconds");
      }
      if (img.has("camera_to_world")) ref.camera_to_world = img.at("camera_to_world").rigid();
      if (options.check_files && !fs::exists(scene.dir / ref.path))
        img.at("path").fail("image file " + (scene.dir / ref.path).string() + " does not exist");
      frame.images.emplace(name, std::move(ref));
    }
  }
  if (f.has("lidar")) {
    frame.lidar = f.at("lidar").str();
    if (!stays_inside(frame.lidar)) f.at("lidar").fail("must be a path inside the scene folder (relative, no '..' out of it)");
    if (options.check_files && !fs::exists(scene.dir / frame.lidar))
      f.at("lidar").fail("LiDAR file " + (scene.dir / frame.lidar).string() + " does not exist");
  }
  return frame;
}

std::vector<ObjectTrack> read_objects(const fs::path& file, size_t frame_count) {
  const json doc = read_json_file(file);
  const FieldReader root(file, doc);
  const auto objects = root.at("objects");
  std::vector<ObjectTrack> out;
  std::set<std::string> ids;
  for (size_t i = 0; i < objects.array_size(); ++i) {
    const auto o = objects.at(i);
    ObjectTrack t;
    t.id = o.at("id").str();
    if (!ids.insert(t.id).second) o.at("id").fail("duplicate object id '" + t.id + "'");
    t.category = o.at("category").str();
    if (o.has("color_rgb")) {
      const auto c = o.at("color_rgb");
      if (c.array_size() != 3) c.fail("expected 3 integers 0..255");
      std::array<int, 3> rgb{};
      for (size_t k = 0; k < 3; ++k) {
        rgb[k] = c.at(k).integer();
        if (rgb[k] < 0 || rgb[k] > 255) c.at(k).fail("must be 0..255");
      }
      t.color_rgb = rgb;
    }
    t.size_lwh = o.at("size_lwh").vec3();
    if ((t.size_lwh.array() <= 0).any()) o.at("size_lwh").fail("sizes must be positive metres");
    const auto track = o.at("track");
    for (size_t k = 0; k < track.array_size(); ++k) {
      const auto p = track.at(k);
      TrackPoint tp{p.at("frame").integer(), p.at("center").vec3(), p.at("yaw").number()};
      if (tp.frame < 0 || size_t(tp.frame) >= frame_count)
        p.at("frame").fail("frame " + std::to_string(tp.frame) + " is not in scene.json (0.." +
                           std::to_string(frame_count - 1) + ")");
      if (!t.track.empty() && tp.frame <= t.track.back().frame)
        p.at("frame").fail("track frames must increase");
      t.track.push_back(tp);
    }
    out.push_back(std::move(t));
  }
  return out;
}

LaneMap read_lanes(const fs::path& file) {
  const json doc = read_json_file(file);
  const FieldReader root(file, doc);
  const auto lanes = root.at("lanes");
  std::vector<Lane> out;
  for (size_t i = 0; i < lanes.array_size(); ++i) {
    const auto l = lanes.at(i);
    Lane lane;
    lane.id = l.at("id").str();
    lane.type = l.str_or("type", "driving");
    lane.width = l.number_or("width", 3.5);
    if (lane.width <= 0) l.at("width").fail("must be positive metres");
    const std::string dir = l.str_or("direction", "forward");
    if (dir == "forward") lane.direction = TrafficDirection::Forward;
    else if (dir == "backward") lane.direction = TrafficDirection::Backward;
    else if (dir == "both") lane.direction = TrafficDirection::Both;
    else l.at("direction").fail("'" + dir + "' is not one of forward, backward, both");
    const auto cl = l.at("centerline");
    if (cl.array_size() < 2) cl.fail("a centreline needs at least 2 points");
    for (size_t k = 0; k < cl.array_size(); ++k) lane.centerline.push_back(cl.at(k).vec3());
    out.push_back(std::move(lane));
  }
  return LaneMap(std::move(out));
}

}  // namespace

SceneError::SceneError(fs::path file, std::string field, const std::string& problem)
    : std::runtime_error(describe(file, field, problem)), file_(std::move(file)), field_(std::move(field)) {}

const Camera* Scene::camera(const std::string& n) const {
  for (const auto& c : cameras)
    if (c.name == n) return &c;
  return nullptr;
}

const Frame* Scene::frame(int index) const {
  for (const auto& f : frames)
    if (f.index == index) return &f;
  return nullptr;
}

const ObjectTrack* Scene::object(const std::string& id) const {
  for (const auto& o : objects)
    if (o.id == id) return &o;
  return nullptr;
}

Eigen::Isometry3d Scene::camera_to_world(const Frame& frame, const Camera& cam) const {
  const auto it = frame.images.find(cam.name);
  if (it == frame.images.end()) return frame.ego_to_world * cam.sensor_to_ego;
  if (it->second.camera_to_world) return *it->second.camera_to_world;
  // Asynchronous trigger: the rig where the ego was when this camera fired, not at the frame's
  // time (at 8 m/s, 12 ms is a decimetre).
  if (std::abs(it->second.timestamp_s - frame.timestamp_s) > 1e-6) return ego_to_world_at(it->second.timestamp_s) * cam.sensor_to_ego;
  return frame.ego_to_world * cam.sensor_to_ego;
}

Eigen::Isometry3d Scene::ego_to_world_at(double t) const {
  const auto& fr = frames;
  if (fr.empty()) return Eigen::Isometry3d::Identity();
  if (t <= fr.front().timestamp_s) {
    if (fr.size() < 2) return fr.front().ego_to_world;
    // Extrapolate backwards along the first step (a camera triggered before frame 0).
    const auto& a = fr[0];
    const auto& b = fr[1];
    const double s = (t - a.timestamp_s) / (b.timestamp_s - a.timestamp_s);
    Eigen::Isometry3d e = a.ego_to_world;
    e.translation() += s * (b.ego_to_world.translation() - a.ego_to_world.translation());
    return e;
  }
  for (size_t i = 0; i + 1 < fr.size(); ++i) {
    if (t > fr[i + 1].timestamp_s) continue;
    const double s = (t - fr[i].timestamp_s) / (fr[i + 1].timestamp_s - fr[i].timestamp_s);
    Eigen::Isometry3d e = Eigen::Isometry3d::Identity();
    e.translation() = fr[i].ego_to_world.translation() * (1 - s) + fr[i + 1].ego_to_world.translation() * s;
    e.linear() = Eigen::Quaterniond(fr[i].ego_to_world.linear())
                     .slerp(s, Eigen::Quaterniond(fr[i + 1].ego_to_world.linear()))
                     .toRotationMatrix();
    return e;
  }
  const auto& a = fr[fr.size() - 2];
  const auto& b = fr.back();
  const double s = (t - a.timestamp_s) / (b.timestamp_s - a.timestamp_s);
  Eigen::Isometry3d e = b.ego_to_world;
  e.translation() = a.ego_to_world.translation() + s * (b.ego_to_world.translation() - a.ego_to_world.translation());
  return e;
}

Eigen::Isometry3d Scene::world_to_ego0() const {
  return frames.empty() ? Eigen::Isometry3d::Identity() : frames.front().ego_to_world.inverse();
}

double Scene::duration_s() const {
  return frames.size() < 2 ? 0.0 : frames.back().timestamp_s - frames.front().timestamp_s;
}

Scene load_scene(const fs::path& dir, const LoadOptions& options_in) {
  const fs::path file = dir / "scene.json";
  if (!fs::is_directory(dir)) throw SceneError(dir, "", "is not a scene directory (it does not exist)");
  const json doc = read_json_file(file);
  const FieldReader root(file, doc);
  Scene scene;
  scene.dir = dir;
  const std::string format = root.at("format").str();
  if (format != "chatsim-scene/1") root.at("format").fail("'" + format + "' is not supported; expected chatsim-scene/1");
  scene.name = root.at("name").str();
  scene.source = root.str_or("source", "");
  scene.frame_rate_hz = root.number_or("frame_rate_hz", 10.0);
  if (scene.frame_rate_hz <= 0) root.at("frame_rate_hz").fail("must be positive");
  scene.ego_origin = root.str_or("ego_origin", "rear_axle");
  scene.layout_only = root.bool_or("layout_only", false);
  scene.lanes_source = root.str_or("lanes_source", "");
  LoadOptions options = options_in;
  if (scene.layout_only) options.check_files = false;

  const auto cams = root.at("cameras");
  for (size_t i = 0; i < cams.array_size(); ++i) {
    Camera c = read_camera(cams.at(i));
    if (scene.camera(c.name) != nullptr) cams.at(i).at("name").fail("duplicate camera '" + c.name + "'");
    scene.cameras.push_back(std::move(c));
  }
  if (scene.cameras.empty()) cams.fail("a scene needs at least one camera");

  const auto frames = root.at("frames");
  for (size_t i = 0; i < frames.array_size(); ++i) {
    Frame f = read_frame(frames.at(i), scene, options);
    if (f.index != int(i)) frames.at(i).at("index").fail("expected " + std::to_string(i) + " (frames are numbered from 0 in order)");
    if (i > 0 && f.timestamp_s <= scene.frames.back().timestamp_s)
      frames.at(i).at("timestamp_s").fail("timestamps must increase");
    if (!scene.layout_only && f.images.empty())
      frames.at(i).fail("has no images (a scene that is only a layout must say \"layout_only\": true)");
    scene.frames.push_back(std::move(f));
  }
  if (scene.frames.empty()) frames.fail("a scene needs at least one frame");

  if (fs::exists(dir / "objects.json")) scene.objects = read_objects(dir / "objects.json", scene.frames.size());
  if (fs::exists(dir / "lanes.json")) scene.lanes = read_lanes(dir / "lanes.json");
  return scene;
}

void save_scene(const Scene& scene, const fs::path& dir) {
  fs::create_directories(dir);
  json cams = json::array();
  for (const auto& c : scene.cameras)
    cams.push_back({{"name", c.name}, {"width", c.width}, {"height", c.height}, {"fx", c.fx}, {"fy", c.fy},
                    {"cx", c.cx}, {"cy", c.cy}, {"distortion", {{"model", c.distortion_model}}},
                    {"sensor_to_ego", matrix_json(c.sensor_to_ego)}});
  json frames = json::array();
  for (const auto& f : scene.frames) {
    json images = json::object();
    for (const auto& [name, img] : f.images) {
      json j{{"path", img.path.string()}, {"timestamp_s", img.timestamp_s}};
      if (img.exposure_s) j["exposure_s"] = *img.exposure_s;
      if (img.camera_to_world) j["camera_to_world"] = matrix_json(*img.camera_to_world);
      images[name] = j;
    }
    json fj{{"index", f.index}, {"timestamp_s", f.timestamp_s}, {"ego_to_world", matrix_json(f.ego_to_world)}};
    if (!images.empty()) fj["images"] = images;
    if (!f.lidar.empty()) fj["lidar"] = f.lidar.string();
    frames.push_back(fj);
  }
  json doc{{"format", "chatsim-scene/1"}, {"name", scene.name}, {"source", scene.source},
           {"frame_rate_hz", scene.frame_rate_hz}, {"ego_origin", scene.ego_origin},
           {"cameras", cams}, {"frames", frames}};
  if (scene.layout_only) doc["layout_only"] = true;
  if (!scene.lanes_source.empty()) doc["lanes_source"] = scene.lanes_source;
  std::ofstream(dir / "scene.json") << doc.dump(1) << "\n";

  json objects = json::array();
  for (const auto& o : scene.objects) {
    json track = json::array();
    for (const auto& p : o.track)
      track.push_back({{"frame", p.frame}, {"center", {p.center.x(), p.center.y(), p.center.z()}}, {"yaw", p.yaw}});
    json oj{{"id", o.id}, {"category", o.category},
            {"size_lwh", {o.size_lwh.x(), o.size_lwh.y(), o.size_lwh.z()}}, {"track", track}};
    if (o.color_rgb) oj["color_rgb"] = *o.color_rgb;
    objects.push_back(oj);
  }
  std::ofstream(dir / "objects.json") << json{{"objects", objects}}.dump(1) << "\n";

  json lanes = json::array();
  for (const auto& l : scene.lanes.lanes()) {
    json cl = json::array();
    for (const auto& p : l.centerline) cl.push_back({p.x(), p.y(), p.z()});
    const char* dir_name = l.direction == TrafficDirection::Forward    ? "forward"
                           : l.direction == TrafficDirection::Backward ? "backward"
                                                                       : "both";
    lanes.push_back({{"id", l.id}, {"type", l.type}, {"width", l.width}, {"direction", dir_name}, {"centerline", cl}});
  }
  std::ofstream(dir / "lanes.json") << json{{"lanes", lanes}}.dump(1) << "\n";
}

}  // namespace chatsim::scene
