#pragma once
// The Embree 3 scene everything is traced in: prototypes (meshes with material slots) placed
// as instances (rigid transforms, optionally moving over the shutter for motion blur). Each
// instance carries its own material per slot (a recoloured car) and a mask of what it is
// (scene, foreground, catcher), so queries can ignore kinds of geometry.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "render/material.hpp"
#include "render/mesh.hpp"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace chatsim::render {

namespace mask {
inline constexpr uint32_t kScene = 1;       // background geometry (demo street)
inline constexpr uint32_t kForeground = 2;  // inserted objects
inline constexpr uint32_t kCatcher = 4;     // shadow-catcher ground
inline constexpr uint32_t kAll = 0xffffffffu;
}  // namespace mask

struct Ray {
  Eigen::Vector3f origin;
  Eigen::Vector3f direction;  // unit
  float t_min = 1e-4f;
  float t_max = 1e30f;
  float time = 0.5f;          // 0..1 across the shutter
  uint32_t mask = mask::kAll;
};

struct Hit {
  float t = 0;
  Eigen::Vector3f position;
  Eigen::Vector3f geometric_normal;  // world, unit (not flipped)
  Eigen::Vector3f shading_normal;    // world, unit (not flipped)
  Eigen::Vector2f uv = Eigen::Vector2f::Zero();
  uint32_t material = 0;
  int instance = -1;
  uint32_t instance_mask = 0;
};

class RayScene {
 public:
  RayScene();
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  uint32_t add_material(Material material);
  const Material& material(uint32_t id) const { return materials_[id]; }
  Material& material(uint32_t id) { return materials_[id]; }

  // A mesh whose triangle slots map to materials (slot_materials[slot] = material id).
  int add_prototype(TriangleMesh mesh, std::vector<uint32_t> slot_materials);
  // Places a prototype. `end` is the transform at the shutter's close (motion blur); slot
  // overrides replace the prototype's material per slot (empty: keep).
  int add_instance(int prototype, const Eigen::Affine3f& start, std::optional<Eigen::Affine3f> end = std::nullopt,
                   std::vector<uint32_t> slot_overrides = {}, uint32_t mask = mask::kScene);
  void set_transform(int instance, const Eigen::Affine3f& start, std::optional<Eigen::Affine3f> end = std::nullopt);
  void set_enabled(int instance, bool enabled);
  // Call after adding or changing instances, before tracing.
  void commit();

  std::optional<Hit> intersect(const Ray& ray) const;
  bool occluded(const Ray& ray) const;

  size_t instance_count() const { return instances_.size(); }
  size_t triangle_count() const;
  Eigen::AlignedBox3f bounds() const;

 private:
  struct Prototype {
    TriangleMesh mesh;
    std::vector<uint32_t> slots;
    RTCSceneTy* scene = nullptr;
  };
  struct Instance {
    int prototype = 0;
    Eigen::Affine3f start, end;
    bool moving = false;
    bool enabled = true;
    std::vector<uint32_t> slots;
    uint32_t mask = 0;
    unsigned geom_id = 0;
  };
  void apply_transform(Instance& inst);
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* top_ = nullptr;
  std::vector<Material> materials_;
  std::vector<std::unique_ptr<Prototype>> prototypes_;
  std::vector<Instance> instances_;
  std::vector<int> instance_of_geom_;
};

}  // namespace chatsim::render
