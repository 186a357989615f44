// Built-in vehicles and road furniture as meshes: a car body is a side profile (with wheel
// arches) extruded across its width, a greenhouse profile extruded slightly narrower, wheels,
// lights and trims. Proportions come from each shape's parameters; fit_to() makes the box exact.
#include <cmath>
#include <map>
#include <stdexcept>

#include "render/asset_model.hpp"
#include "render/sampling.hpp"

namespace chatsim::render {
namespace {

enum Slot : uint16_t { kPaint = 0, kGlass, kTyre, kChrome, kHeadlight, kTaillight, kTrim, kAccentA, kAccentB, kSlotCount };

std::vector<Material> vehicle_materials(const Rgb& paint) {
  std::vector<Material> m(kSlotCount);
  m[kPaint] = Material::coated("paint", paint, 0.18f, 0.05f);
  m[kGlass] = Material::coated("glass", Rgb(0.015f, 0.02f, 0.025f), 0.03f, 0.06f);
  m[kTyre] = Material::coated("tyre", Rgb::Constant(0.025f), 0.75f, 0.03f);
  m[kChrome] = Material::metal("chrome", Rgb::Constant(0.85f), 0.2f);
  m[kHeadlight] = Material::coated("headlight", Rgb::Constant(0.75f), 0.05f, 0.08f);
  m[kTaillight] = Material::coated("taillight", Rgb(0.45f, 0.01f, 0.01f), 0.1f, 0.06f);
  m[kTrim] = Material::coated("trim", Rgb::Constant(0.035f), 0.5f, 0.04f);
  m[kAccentA] = Material::coated("accent_a", Rgb(0.8f, 0.02f, 0.02f), 0.1f, 0.06f);
  m[kAccentB] = Material::coated("accent_b", Rgb(0.02f, 0.1f, 0.9f), 0.1f, 0.06f);
  return m;
}

Eigen::Affine3f at(float x, float y, float z) {
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(Eigen::Vector3f(x, y, z));
  return t;
}

void add_box(TriangleMesh& m, float x, float y, float z, float l, float w, float h, uint16_t slot) {
  m.append(make_box({l, w, h}, slot), at(x, y, z));
}

// A polygon's bottom edge from x_hi down to x_lo at height z, arching over each wheel (centres
// at wheel_x, front to rear, at height wheel_z).
void bottom_with_arches(std::vector<Eigen::Vector2f>& poly, float x_hi, float x_lo, float z,
                        const std::vector<float>& wheel_x, float wheel_z, float arch_r) {
  poly.emplace_back(x_hi, z);
  const float dz = z - wheel_z;
  if (std::abs(dz) < arch_r) {
    // The arch meets the edge at +-half around the top of the circle.
    const float half = std::acos(dz / arch_r);
    const int n = 10;
    for (float wx : wheel_x)
      for (int i = 0; i <= n; ++i) {
        const float a = half - 2 * half * float(i) / float(n);
        poly.emplace_back(wx + arch_r * std::sin(a), wheel_z + arch_r * std::cos(a));
      }
  }
  poly.emplace_back(x_lo, z);
}

struct CarShape {
  float L, W, H;
  float clearance = 0.22f;
  float wheel_r = 0.33f;
  float overhang_f = 0.9f, overhang_r = 1.0f;
  float nose_z = 0.62f;       // top of the front bumper
  float hood_z = 0.9f;        // hood at the windshield's base
  float tail_z = 0.95f;       // top of the rear (trunk lid or tailgate)
  float belt_z = 0.95f;       // where the glass starts
  // Greenhouse, as fractions of the length from the rear: base of rear glass, rear roof end,
  // front roof end, base of the windshield.
  float g_rear_base = 0.18f, g_rear_top = 0.28f, g_front_top = 0.58f, g_front_base = 0.72f;
  float cabin_width = 0.86f;  // of W
};

void add_wheels(TriangleMesh& m, const CarShape& s, const std::vector<float>& wheel_x) {
  const float tw = std::min(0.3f, 0.13f * s.W);
  for (float wx : wheel_x)
    for (float side : {-1.0f, 1.0f}) {
      const float y = side * (s.W / 2 - tw / 2 - 0.01f);
      m.append(make_cylinder(s.wheel_r, tw, 24, kTyre), at(wx, y, s.wheel_r));
      m.append(make_cylinder(s.wheel_r * 0.55f, tw + 0.02f, 16, kChrome), at(wx, y, s.wheel_r));
    }
}

TriangleMesh car_body(const CarShape& s) {
  TriangleMesh m;
  const float xf = s.L / 2, xr = -s.L / 2;
  const std::vector<float> wheel_x{xf - s.overhang_f, xr + s.overhang_r};
  const float arch = s.wheel_r + 0.06f;
  auto gx = [&](float f) { return xr + f * s.L; };
  // Lower body: front bumper up to the hood, along the belt, down the tail; arches below.
  std::vector<Eigen::Vector2f> body;
  body.emplace_back(xr + 0.05f, s.tail_z);
  body.emplace_back(xr, s.tail_z - 0.12f);
  body.emplace_back(xr, s.clearance + 0.12f);
  body.emplace_back(xr + 0.12f, s.clearance);
  std::vector<Eigen::Vector2f> bottom;
  bottom_with_arches(bottom, xf - 0.12f, xr + 0.12f, s.clearance, wheel_x, s.wheel_r, arch);
  for (auto it = bottom.rbegin(); it != bottom.rend(); ++it) body.push_back(*it);  // rear to front
  body.emplace_back(xf, s.clearance + 0.12f);
  body.emplace_back(xf, s.nose_z);
  body.emplace_back(xf - 0.15f, s.nose_z + 0.12f);
  body.emplace_back(gx(s.g_front_base), s.hood_z);
  body.emplace_back(std::max(gx(s.g_rear_base), xr + 0.1f), s.belt_z);
  // Drop duplicates that would make zero-length edges.
  std::vector<Eigen::Vector2f> clean;
  for (const auto& p : body)
    if (clean.empty() || (clean.back() - p).norm() > 1e-3f) clean.push_back(p);
  m.append(make_extrusion(clean, s.W, kPaint));
  // Greenhouse: glass on the sides and ends, paint on the roof.
  const float base_z = std::min(s.hood_z, s.belt_z) - 0.02f;
  std::vector<Eigen::Vector2f> cabin{{gx(s.g_rear_base), base_z}, {gx(s.g_front_base), base_z},
                                     {gx(s.g_front_top), s.H}, {gx(s.g_rear_top), s.H}};
  TriangleMesh g = make_extrusion(cabin, s.W * s.cabin_width, kGlass);
  for (size_t t = 0; t < g.triangles.size(); ++t) {
    const auto& tri = g.triangles[t];
    const Eigen::Vector3f n = (g.positions[size_t(tri[1])] - g.positions[size_t(tri[0])])
                                  .cross(g.positions[size_t(tri[2])] - g.positions[size_t(tri[0])])
                                  .normalized();
    if (std::abs(n.z()) > 0.95f) g.material[t] = kPaint;  // roof (and the hidden floor)
  }
  m.append(g);
  // Pillars in paint between the side windows and at the windshield's edges.
  const float cw = s.W * s.cabin_width + 0.02f;
  const float pillar_h = s.H - base_z;
  add_box(m, gx((s.g_rear_top + s.g_front_top) / 2), 0, base_z + pillar_h / 2, 0.1f, cw, pillar_h, kPaint);
  // Lights, grille and bumpers.
  const float light_z = s.nose_z - 0.1f;
  for (float side : {-1.0f, 1.0f}) {
    add_box(m, xf - 0.02f, side * (s.W / 2 - 0.28f), light_z, 0.06f, 0.34f, 0.12f, kHeadlight);
    add_box(m, xr + 0.02f, side * (s.W / 2 - 0.22f), s.tail_z - 0.18f, 0.06f, 0.3f, 0.14f, kTaillight);
  }
  add_box(m, xf - 0.01f, 0, light_z - 0.08f, 0.04f, s.W * 0.4f, 0.16f, kTrim);
  add_box(m, xf - 0.05f, 0, s.clearance + 0.1f, 0.12f, s.W * 0.96f, 0.14f, kTrim);
  add_box(m, xr + 0.05f, 0, s.clearance + 0.1f, 0.12f, s.W * 0.96f, 0.14f, kTrim);
  add_wheels(m, s, wheel_x);
  return m;
}

CarShape sedan_shape(const Eigen::Vector3f& size) {
  CarShape s{size.x(), size.y(), size.z()};
  s.wheel_r = std::clamp(0.22f * size.z(), 0.3f, 0.36f);
  s.belt_z = s.hood_z = s.tail_z = 0.64f * size.z();
  s.nose_z = 0.45f * size.z();
  return s;
}

// A slab from x_rear to x_front, z_bottom to z_top, with arches cut over the wheels.
TriangleMesh arched_slab(float x_front, float x_rear, float z_bottom, float z_top, float width,
                         const std::vector<float>& wheel_x, float wheel_r, uint16_t slot) {
  std::vector<float> inside;
  for (float wx : wheel_x)
    if (wx < x_front - wheel_r && wx > x_rear + wheel_r) inside.push_back(wx);
  std::vector<Eigen::Vector2f> bottom;
  bottom_with_arches(bottom, x_front, x_rear, z_bottom, inside, wheel_r, wheel_r + 0.05f);
  std::vector<Eigen::Vector2f> poly(bottom.rbegin(), bottom.rend());
  poly.emplace_back(x_front, z_top);
  poly.emplace_back(x_rear, z_top);
  return make_extrusion(poly, width, slot);
}

TriangleMesh box_vehicle(const Eigen::Vector3f& size, float cab_len, bool separate_cargo, bool window_band) {
  // Buses and trucks: a cab (or the whole body) with a windshield, wheels, lights.
  TriangleMesh m;
  const float L = size.x(), W = size.y(), H = size.z();
  const float clearance = 0.35f, wr = std::clamp(0.15f * H, 0.4f, 0.55f);
  CarShape s{L, W, H};
  s.wheel_r = wr;
  const float xf = L / 2, xr = -L / 2;
  std::vector<float> wheel_x{xf - std::min(1.3f, cab_len * 0.55f), xr + std::max(1.2f, L * 0.18f)};
  if (L > 9) wheel_x.push_back(xr + std::max(1.2f, L * 0.18f) + 1.35f);
  if (separate_cargo) {
    const float cab_h = std::min(H, 2.6f);
    m.append(arched_slab(xf, xf - cab_len, clearance, cab_h, W * 0.98f, wheel_x, wr, kPaint));
    add_box(m, xf + 0.005f, 0, cab_h * 0.72f, 0.02f, W * 0.85f, cab_h * 0.32f, kGlass);
    const float cargo_len = L - cab_len - 0.15f;
    m.append(arched_slab(xr + cargo_len, xr, clearance, H, W, wheel_x, wr, kPaint));
  } else {
    m.append(arched_slab(xf, xr, clearance, H, W, wheel_x, wr, kPaint));
    add_box(m, xf + 0.005f, 0, H * 0.62f, 0.02f, W * 0.9f, H * 0.42f, kGlass);
    if (window_band)
      for (float side : {-1.0f, 1.0f})
        add_box(m, -0.3f, side * (W / 2 + 0.005f), H * 0.66f, L * 0.8f, 0.02f, H * 0.3f, kGlass);
  }
  for (float side : {-1.0f, 1.0f}) {
    add_box(m, xf + 0.01f, side * (W / 2 - 0.3f), 0.75f, 0.04f, 0.35f, 0.18f, kHeadlight);
    add_box(m, xr - 0.01f, side * (W / 2 - 0.2f), 0.9f, 0.04f, 0.2f, 0.3f, kTaillight);
  }
  add_box(m, xf + 0.03f, 0, clearance + 0.15f, 0.08f, W * 0.98f, 0.25f, kTrim);
  add_wheels(m, s, wheel_x);
  return m;
}

TriangleMesh two_wheeler(const Eigen::Vector3f& size, bool motor) {
  TriangleMesh m;
  const float L = size.x(), H = size.z();
  const float r = motor ? 0.31f : 0.34f;
  const float tw = motor ? 0.12f : 0.04f;
  for (float x : {L / 2 - r, -L / 2 + r}) {
    m.append(make_cylinder(r, tw, 24, kTyre), at(x, 0, r));
    m.append(make_cylinder(r * 0.4f, tw + 0.01f, 12, kChrome), at(x, 0, r));
  }
  if (motor) {
    add_box(m, 0, 0, r + 0.15f, L * 0.5f, 0.35f, 0.4f, kPaint);               // tank and engine
    add_box(m, -L * 0.12f, 0, r + 0.42f, L * 0.35f, 0.3f, 0.1f, kTrim);        // seat
    add_box(m, L / 2 - r - 0.1f, 0, H - 0.15f, 0.08f, size.y(), 0.05f, kChrome);  // handlebar
  } else {
    add_box(m, 0, 0, r + 0.2f, L * 0.5f, 0.05f, 0.05f, kPaint);
    add_box(m, -0.1f, 0, H - 0.2f, 0.25f, 0.12f, 0.06f, kTrim);
    add_box(m, L / 2 - r - 0.05f, 0, H - 0.1f, 0.05f, size.y(), 0.04f, kChrome);
  }
  return m;
}

using Builder = AssetModel (*)(const Eigen::Vector3f&, const Rgb&);

AssetModel car_model(const std::string& name, const CarShape& s, const Rgb& paint) {
  AssetModel a;
  a.name = name;
  a.mesh = car_body(s);
  a.slots = vehicle_materials(paint);
  return a;
}

AssetModel sedan(const Eigen::Vector3f& size, const Rgb& paint) { return car_model("sedan", sedan_shape(size), paint); }

AssetModel sports(const Eigen::Vector3f& size, const Rgb& paint) {
  CarShape s = sedan_shape(size);
  s.nose_z = 0.38f * size.z();
  s.belt_z = s.hood_z = 0.62f * size.z();
  s.tail_z = 0.7f * size.z();
  s.g_rear_base = 0.08f, s.g_rear_top = 0.3f, s.g_front_top = 0.55f, s.g_front_base = 0.72f;
  s.clearance = 0.14f;
  return car_model("sports", s, paint);
}

AssetModel hatchback(const Eigen::Vector3f& size, const Rgb& paint) {
  CarShape s = sedan_shape(size);
  s.g_rear_base = 0.03f, s.g_rear_top = 0.1f, s.g_front_top = 0.58f, s.g_front_base = 0.74f;
  s.overhang_r = 0.7f;
  s.overhang_f = 0.8f;
  return car_model("hatchback", s, paint);
}

AssetModel suv(const Eigen::Vector3f& size, const Rgb& paint) {
  CarShape s = sedan_shape(size);
  s.clearance = 0.3f;
  s.wheel_r = 0.38f;
  s.belt_z = s.hood_z = s.tail_z = 0.6f * size.z();
  s.nose_z = 0.5f * size.z();
  s.g_rear_base = 0.02f, s.g_rear_top = 0.05f, s.g_front_top = 0.6f, s.g_front_base = 0.7f;
  return car_model("suv", s, paint);
}

AssetModel van(const Eigen::Vector3f& size, const Rgb& paint) {
  CarShape s = sedan_shape(size);
  s.clearance = 0.25f;
  s.wheel_r = 0.36f;
  s.belt_z = s.hood_z = s.tail_z = 0.5f * size.z();
  s.nose_z = 0.4f * size.z();
  s.overhang_f = 0.8f;
  s.g_rear_base = 0.0f, s.g_rear_top = 0.01f, s.g_front_top = 0.8f, s.g_front_base = 0.86f;
  s.cabin_width = 0.97f;
  return car_model("van", s, paint);
}

AssetModel pickup(const Eigen::Vector3f& size, const Rgb& paint) {
  CarShape s = sedan_shape(size);
  s.clearance = 0.3f;
  s.wheel_r = 0.38f;
  s.belt_z = s.hood_z = s.tail_z = 0.58f * size.z();
  s.nose_z = 0.5f * size.z();
  s.g_rear_base = 0.4f, s.g_rear_top = 0.42f, s.g_front_top = 0.66f, s.g_front_base = 0.74f;
  AssetModel a = car_model("pickup", s, paint);
  // The bed's walls above the belt line.
  const float bed_len = 0.38f * size.x(), bed_x = -size.x() / 2 + bed_len / 2 + 0.02f;
  for (float side : {-1.0f, 1.0f}) add_box(a.mesh, bed_x, side * (size.y() / 2 - 0.04f), s.belt_z + 0.1f, bed_len, 0.08f, 0.2f, kPaint);
  return a;
}

AssetModel police(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a = sedan(size, paint);
  a.name = "police";
  const float roof = size.z();
  add_box(a.mesh, -0.1f * size.x(), 0.3f, roof + 0.06f, 0.25f, 0.55f, 0.12f, kAccentA);
  add_box(a.mesh, -0.1f * size.x(), -0.3f, roof + 0.06f, 0.25f, 0.55f, 0.12f, kAccentB);
  return a;
}

AssetModel taxi(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a = sedan(size, paint);
  a.name = "taxi";
  a.slots[kAccentA] = Material::coated("sign", Rgb(0.9f, 0.85f, 0.6f), 0.2f);
  add_box(a.mesh, -0.1f * size.x(), 0, size.z() + 0.1f, 0.35f, 0.6f, 0.2f, kAccentA);
  return a;
}

AssetModel bus(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a{"bus", box_vehicle(size, size.x(), false, true), vehicle_materials(paint), kPaint};
  return a;
}

AssetModel box_truck(const Eigen::Vector3f& size, const Rgb& paint) {
  return AssetModel{"box_truck", box_vehicle(size, 2.2f, true, false), vehicle_materials(paint), kPaint};
}

AssetModel ambulance(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a{"ambulance", box_vehicle(size, 2.0f, true, false), vehicle_materials(paint), kPaint};
  for (float side : {-1.0f, 1.0f}) add_box(a.mesh, -0.6f, side * (size.y() / 2 + 0.01f), size.z() * 0.55f, 2.5f, 0.02f, 0.2f, kAccentA);
  add_box(a.mesh, size.x() / 2 - 1.0f, 0, std::min(size.z(), 2.6f) + 0.06f, 0.2f, 1.2f, 0.12f, kAccentB);
  return a;
}

AssetModel firetruck(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a{"firetruck", box_vehicle(size, 2.6f, true, false), vehicle_materials(paint), kPaint};
  add_box(a.mesh, -0.5f, 0, size.z() + 0.1f, size.x() * 0.6f, 0.5f, 0.15f, kChrome);  // ladder
  return a;
}

AssetModel motorcycle(const Eigen::Vector3f& size, const Rgb& paint) {
  return AssetModel{"motorcycle", two_wheeler(size, true), vehicle_materials(paint), kPaint};
}
AssetModel bicycle(const Eigen::Vector3f& size, const Rgb& paint) {
  return AssetModel{"bicycle", two_wheeler(size, false), vehicle_materials(paint), kPaint};
}

AssetModel cone(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a;
  a.name = "cone";
  a.slots = {Material::coated("cone", paint, 0.4f), Material::coated("reflective_band", Rgb::Constant(0.8f), 0.3f),
             Material::coated("base", Rgb::Constant(0.03f), 0.6f)};
  const float h = size.z(), r = std::min(size.x(), size.y()) * 0.35f;
  a.mesh.append(make_box({size.x(), size.y(), 0.04f}, 2), at(0, 0, 0.02f));
  Eigen::Affine3f base = at(0, 0, 0.04f);
  a.mesh.append(make_frustum(r, r * 0.55f, 0.4f * h, 20, 0), base);
  a.mesh.append(make_frustum(r * 0.55f + 0.005f, r * 0.4f + 0.005f, 0.15f * h, 20, 1), at(0, 0, 0.04f + 0.4f * h));
  a.mesh.append(make_frustum(r * 0.4f, r * 0.1f, h - 0.04f - 0.55f * h, 20, 0), at(0, 0, 0.04f + 0.55f * h));
  a.paint_slot = 0;
  return a;
}

// Red and white stripes across a barrier's board.
class StripeTexture : public Texture {
 public:
  SurfacePoint shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f&, const Eigen::Vector3f&) const override {
    SurfacePoint s = base;
    const float k = std::floor((p.x() + p.z()) / 0.25f);
    if (int(k) % 2 == 0) s.albedo = Rgb::Constant(0.8f);
    return s;
  }
};

AssetModel barrier(const Eigen::Vector3f& size, const Rgb& paint) {
  AssetModel a;
  a.name = "barrier";
  a.slots = {Material::coated("board", paint, 0.4f), Material::coated("legs", Rgb::Constant(0.6f), 0.5f)};
  a.slots[0].texture = std::make_shared<StripeTexture>();
  const float L = size.x(), W = size.y(), H = size.z();
  a.mesh.append(make_box({L, 0.05f, 0.3f}, 0), at(0, 0, H - 0.15f));
  for (float x : {-L / 2 + 0.15f, L / 2 - 0.15f}) {
    a.mesh.append(make_box({0.06f, 0.06f, H - 0.3f}, 1), at(x, 0, (H - 0.3f) / 2));
    a.mesh.append(make_box({0.1f, W, 0.05f}, 1), at(x, 0, 0.025f));
  }
  a.paint_slot = -1;  // striped: the colour is the barrier's own
  return a;
}

const std::map<std::string, Builder>& builders() {
  static const std::map<std::string, Builder> b{
      {"sedan", sedan},         {"sports", sports},   {"hatchback", hatchback}, {"suv", suv},
      {"pickup", pickup},       {"van", van},         {"bus", bus},             {"box_truck", box_truck},
      {"police", police},       {"taxi", taxi},       {"ambulance", ambulance}, {"firetruck", firetruck},
      {"motorcycle", motorcycle}, {"bicycle", bicycle}, {"cone", cone},         {"barrier", barrier}};
  return b;
}

}  // namespace

const std::vector<std::string>& parametric_shapes() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [k, v] : builders()) n.push_back(k);
    return n;
  }();
  return names;
}

bool is_parametric_shape(const std::string& shape) { return builders().count(shape) > 0; }

AssetModel build_parametric(const std::string& shape, const Eigen::Vector3f& size, const Rgb& paint) {
  const auto it = builders().find(shape);
  if (it == builders().end()) {
    std::string known;
    for (const auto& n : parametric_shapes()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("no parametric shape '" + shape + "' (there are: " + known + ")");
  }
  if (!(size.minCoeff() > 0.05f) || !size.allFinite())
    throw std::invalid_argument("parametric shape '" + shape + "': size must be positive metres");
  AssetModel a = it->second(size, paint);
  a.fit_to(size);
  return a;
}

void AssetModel::recolour(const Rgb& albedo) {
  if (paint_slot >= 0 && size_t(paint_slot) < slots.size()) slots[size_t(paint_slot)].albedo = albedo;
}

void AssetModel::fit_to(const Eigen::Vector3f& size_lwh) {
  const Eigen::AlignedBox3f b = mesh.bounds();
  if (b.isEmpty()) return;
  const Eigen::Vector3f s = b.sizes();
  const Eigen::Vector3f scale(size_lwh.x() / std::max(s.x(), 1e-6f), size_lwh.y() / std::max(s.y(), 1e-6f),
                              size_lwh.z() / std::max(s.z(), 1e-6f));
  const Eigen::Vector3f centre = b.center();
  Eigen::Affine3f xf = Eigen::Affine3f::Identity();
  xf.scale(scale);
  xf.translate(-Eigen::Vector3f(centre.x(), centre.y(), b.min().z()));
  mesh.transform(xf);
}

}  // namespace chatsim::render
