#include "render/ray_scene.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

namespace chatsim::render {
namespace {

void on_error(void*, RTCError code, const char* str) {
  // Embree calls back from C: never throw through it. Errors are checked after each call.
  (void)code;
  (void)str;
}

void check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw std::runtime_error(std::string("embree: ") + what + " failed (error " + std::to_string(int(e)) + ")");
}

void to_column_major(const Eigen::Affine3f& xf, float out[12]) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) out[c * 3 + r] = xf.matrix()(r, c);
}

}  // namespace

RayScene::RayScene() {
  device_ = rtcNewDevice("verbose=0");
  if (device_ == nullptr) throw std::runtime_error("embree: cannot create a device");
  rtcSetDeviceErrorFunction(device_, on_error, nullptr);
  top_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(top_, RTC_BUILD_QUALITY_LOW);
}

RayScene::~RayScene() {
  for (auto& p : prototypes_)
    if (p->scene != nullptr) rtcReleaseScene(p->scene);
  if (top_ != nullptr) rtcReleaseScene(top_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

uint32_t RayScene::add_material(Material m) {
  materials_.push_back(std::move(m));
  return uint32_t(materials_.size() - 1);
}

int RayScene::add_prototype(TriangleMesh mesh, std::vector<uint32_t> slots) {
  if (mesh.material.size() != mesh.triangles.size()) mesh.material.resize(mesh.triangles.size(), 0);
  for (uint16_t s : mesh.material)
    if (s >= slots.size()) throw std::invalid_argument("add_prototype: triangle slot " + std::to_string(s) + " has no material");
  for (uint32_t m : slots)
    if (m >= materials_.size()) throw std::invalid_argument("add_prototype: unknown material " + std::to_string(m));
  auto p = std::make_unique<Prototype>();
  p->mesh = std::move(mesh);
  p->slots = std::move(slots);
  p->scene = rtcNewScene(device_);
  rtcSetSceneBuildQuality(p->scene, RTC_BUILD_QUALITY_HIGH);
  if (!p->mesh.empty()) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), p->mesh.positions.size()));
    for (size_t i = 0; i < p->mesh.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + size_t(k)] = p->mesh.positions[i][k];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), p->mesh.triangles.size()));
    for (size_t i = 0; i < p->mesh.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + size_t(k)] = unsigned(p->mesh.triangles[i][k]);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(p->scene, g, 0);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(p->scene);
  check(device_, "building a mesh");
  prototypes_.push_back(std::move(p));
  return int(prototypes_.size() - 1);
}

void RayScene::apply_transform(Instance& inst) {
  RTCGeometry g = rtcGetGeometry(top_, inst.geom_id);
  float m[12];
  to_column_major(inst.start, m);
  rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
  if (inst.moving) {
    to_column_major(inst.end, m);
    rtcSetGeometryTransform(g, 1, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
  }
  rtcCommitGeometry(g);
}

int RayScene::add_instance(int prototype, const Eigen::Affine3f& start, std::optional<Eigen::Affine3f> end,
                           std::vector<uint32_t> overrides, uint32_t mask) {
  if (prototype < 0 || size_t(prototype) >= prototypes_.size()) throw std::invalid_argument("add_instance: no such prototype");
  Instance inst;
  inst.prototype = prototype;
  inst.start = start;
  inst.end = end.value_or(start);
  inst.moving = end.has_value();
  inst.slots = overrides.empty() ? prototypes_[size_t(prototype)]->slots : std::move(overrides);
  if (inst.slots.size() != prototypes_[size_t(prototype)]->slots.size())
    throw std::invalid_argument("add_instance: slot overrides must cover every slot of the prototype");
  inst.mask = mask;
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(g, prototypes_[size_t(prototype)]->scene);
  rtcSetGeometryTimeStepCount(g, inst.moving ? 2 : 1);
  rtcSetGeometryMask(g, mask);
  inst.geom_id = rtcAttachGeometry(top_, g);
  rtcReleaseGeometry(g);
  if (instance_of_geom_.size() <= inst.geom_id) instance_of_geom_.resize(inst.geom_id + 1, -1);
  instance_of_geom_[inst.geom_id] = int(instances_.size());
  instances_.push_back(std::move(inst));
  apply_transform(instances_.back());
  check(device_, "adding an instance");
  return int(instances_.size() - 1);
}

void RayScene::set_transform(int instance, const Eigen::Affine3f& start, std::optional<Eigen::Affine3f> end) {
  Instance& inst = instances_.at(size_t(instance));
  const bool moving = end.has_value();
  if (moving != inst.moving) rtcSetGeometryTimeStepCount(rtcGetGeometry(top_, inst.geom_id), moving ? 2 : 1);
  inst.start = start;
  inst.end = end.value_or(start);
  inst.moving = moving;
  apply_transform(inst);
}

void RayScene::set_enabled(int instance, bool enabled) {
  Instance& inst = instances_.at(size_t(instance));
  if (inst.enabled == enabled) return;
  inst.enabled = enabled;
  RTCGeometry g = rtcGetGeometry(top_, inst.geom_id);
  if (enabled) rtcEnableGeometry(g);
  else rtcDisableGeometry(g);
}

void RayScene::commit() {
  rtcCommitScene(top_);
  check(device_, "building the scene");
}

namespace {
RTCRay to_rtc(const Ray& r) {
  RTCRay ray;
  ray.org_x = r.origin.x();
  ray.org_y = r.origin.y();
  ray.org_z = r.origin.z();
  ray.dir_x = r.direction.x();
  ray.dir_y = r.direction.y();
  ray.dir_z = r.direction.z();
  ray.tnear = r.t_min;
  ray.tfar = r.t_max;
  ray.time = r.time;
  ray.mask = r.mask;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}
}  // namespace

std::optional<Hit> RayScene::intersect(const Ray& r) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray = to_rtc(r);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(top_, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const Instance& inst = instances_[size_t(instance_of_geom_[rh.hit.instID[0]])];
  const Prototype& proto = *prototypes_[size_t(inst.prototype)];
  const TriangleMesh& mesh = proto.mesh;
  const Eigen::Vector3i& tri = mesh.triangles[rh.hit.primID];
  const float u = rh.hit.u, v = rh.hit.v, w = 1 - u - v;
  // The instance's transform at the ray's time (linear, as Embree interpolates it).
  Eigen::Affine3f xf = inst.start;
  if (inst.moving) xf.matrix() = inst.start.matrix() * (1 - r.time) + inst.end.matrix() * r.time;
  const Eigen::Matrix3f nxf = xf.linear().inverse().transpose();
  const auto& p0 = mesh.positions[size_t(tri[0])];
  const auto& p1 = mesh.positions[size_t(tri[1])];
  const auto& p2 = mesh.positions[size_t(tri[2])];
  Hit h;
  h.t = rh.ray.tfar;
  h.position = r.origin + r.direction * h.t;
  h.geometric_normal = (nxf * (p1 - p0).cross(p2 - p0)).normalized();
  if (!mesh.normals.empty()) {
    const Eigen::Vector3f n = mesh.normals[size_t(tri[0])] * w + mesh.normals[size_t(tri[1])] * u + mesh.normals[size_t(tri[2])] * v;
    h.shading_normal = (nxf * n).normalized();
    if (!h.shading_normal.allFinite()) h.shading_normal = h.geometric_normal;
  } else {
    h.shading_normal = h.geometric_normal;
  }
  if (!mesh.uvs.empty())
    h.uv = mesh.uvs[size_t(tri[0])] * w + mesh.uvs[size_t(tri[1])] * u + mesh.uvs[size_t(tri[2])] * v;
  h.material = inst.slots[mesh.material[rh.hit.primID]];
  h.instance = instance_of_geom_[rh.hit.instID[0]];
  h.instance_mask = inst.mask;
  return h;
}

bool RayScene::occluded(const Ray& r) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray = to_rtc(r);
  rtcOccluded1(top_, &ctx, &ray);
  return ray.tfar < 0;
}

size_t RayScene::triangle_count() const {
  size_t n = 0;
  for (const auto& inst : instances_)
    if (inst.enabled) n += prototypes_[size_t(inst.prototype)]->mesh.triangle_count();
  return n;
}

Eigen::AlignedBox3f RayScene::bounds() const {
  Eigen::AlignedBox3f b;
  for (const auto& inst : instances_) {
    if (!inst.enabled) continue;
    const auto pb = prototypes_[size_t(inst.prototype)]->mesh.bounds();
    if (pb.isEmpty()) continue;
    for (int k = 0; k < 8; ++k) {
      b.extend(inst.start * pb.corner(Eigen::AlignedBox3f::CornerType(k)));
      b.extend(inst.end * pb.corner(Eigen::AlignedBox3f::CornerType(k)));
    }
  }
  return b;
}

}  // namespace chatsim::render
