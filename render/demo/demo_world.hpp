#pragma once
// The demo street as a 3D world: asphalt with lane markings drawn from the lane map, kerbs and
// sidewalks, buildings with windows, trees and street lights that cast shadows, the layout's
// vehicles (from the asset bank) and pedestrian, under a Preetham or overcast sky.
#include <map>
#include <memory>
#include <set>
#include <string>

#include "common/scene/scene.hpp"
#include "render/env_map.hpp"
#include "render/path_tracer.hpp"
#include "render/ray_scene.hpp"
#include "render/sky.hpp"

namespace chatsim::render::demo {

struct WorldOptions {
  uint64_t seed = 1;
  bool overcast = false;
  Eigen::Vector3f sun_direction = Eigen::Vector3f(-0.35f, 0.6f, 0.72f);  // behind-left, ~46 degrees up
  float turbidity = 3.0f;
};

class DemoWorld {
 public:
  DemoWorld(const scene::Scene& layout, const WorldOptions& options);

  RayScene& scene() { return *scene_; }
  const RayScene& scene() const { return *scene_; }
  const Sky& sky() const { return sky_; }
  const EnvMap& sky_map() const { return sky_map_; }
  const Lighting& lighting() const { return lighting_; }

  // Moves every object to where it is at time t (seconds, the scene's clock).
  void place_objects(double t);
  // Hides or shows one labelled object (clean plates); commit() before tracing.
  void set_object_visible(const std::string& id, bool visible);
  void commit() { scene_->commit(); }
  bool has_object(const std::string& id) const { return instances_.count(id) > 0; }

 private:
  void build_street();
  void build_objects();
  const scene::Scene& layout_;
  WorldOptions o_;
  std::unique_ptr<RayScene> scene_;
  Sky sky_;
  EnvMap sky_map_;
  Lighting lighting_;
  std::map<std::string, int> instances_;  // object id -> instance
  std::set<std::string> hidden_;
};

// An object's box centre and yaw at time t, interpolated between its labelled frames.
std::optional<scene::TrackPoint> object_at_time(const scene::Scene& layout, const scene::ObjectTrack& o, double t);

}  // namespace chatsim::render::demo
