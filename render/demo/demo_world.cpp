#include "render/demo/demo_world.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "agents/foreground/asset_bank.hpp"
#include "render/demo/street_textures.hpp"

namespace chatsim::render::demo {
namespace {

Eigen::Affine3f at(float x, float y, float z) {
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(Eigen::Vector3f(x, y, z));
  return t;
}

// The lanes of one straight road: along x (a road) or along y (a cross street).
struct Corridor {
  bool along_x = true;
  float lo = 0, hi = 0;          // across the road
  float from = 0, to = 0;        // along it
  std::vector<int> lanes;        // sorted across
};

float across_of(const scene::Lane& l, bool along_x) {
  return float(along_x ? l.centerline.front().y() : l.centerline.front().x());
}

std::vector<Corridor> corridors(const scene::LaneMap& map) {
  std::vector<Corridor> out;
  for (bool along_x : {true, false}) {
    Corridor c;
    c.along_x = along_x;
    c.lo = 1e9f, c.hi = -1e9f, c.from = 1e9f, c.to = -1e9f;
    for (size_t i = 0; i < map.lanes().size(); ++i) {
      const auto& l = map.lanes()[i];
      if (l.centerline.size() < 2) continue;
      const Eigen::Vector3d d = (l.centerline.back() - l.centerline.front()).normalized();
      if (std::abs(along_x ? d.x() : d.y()) < 0.99) continue;
      c.lanes.push_back(int(i));
      const float a = across_of(l, along_x);
      c.lo = std::min(c.lo, a - float(l.width) / 2);
      c.hi = std::max(c.hi, a + float(l.width) / 2);
      for (const auto& p : l.centerline) {
        const float s = float(along_x ? p.x() : p.y());
        c.from = std::min(c.from, s);
        c.to = std::max(c.to, s);
      }
    }
    if (c.lanes.empty()) continue;
    std::sort(c.lanes.begin(), c.lanes.end(),
              [&](int a, int b) { return across_of(map.lanes()[size_t(a)], along_x) < across_of(map.lanes()[size_t(b)], along_x); });
    out.push_back(c);
  }
  return out;
}

// Lines between neighbouring lanes: dashed white between lanes of one direction, double yellow
// between opposing ones, solid white between driving and parking; gaps where another road crosses.
std::vector<MarkingLine> markings(const scene::LaneMap& map, const Corridor& c, const std::vector<Corridor>& all) {
  std::vector<MarkingLine> raw;
  const Rgb white(0.75f, 0.75f, 0.75f), yellow(0.6f, 0.45f, 0.06f);
  for (size_t k = 0; k + 1 < c.lanes.size(); ++k) {
    const auto& a = map.lanes()[size_t(c.lanes[k])];
    const auto& b = map.lanes()[size_t(c.lanes[k + 1])];
    const float pos = across_of(a, c.along_x) + float(a.width) / 2;
    if (a.type != b.type) {
      raw.push_back({c.along_x, pos, 0.15f, white, 0, 0, c.from, c.to});
    } else if (a.type == "driving") {
      const double ya = map.travel_yaw_at(c.lanes[k], 0), yb = map.travel_yaw_at(c.lanes[k + 1], 0);
      if (std::cos(ya - yb) > 0) {
        raw.push_back({c.along_x, pos, 0.15f, white, 3.0f, 6.0f, c.from, c.to});
      } else {
        raw.push_back({c.along_x, pos - 0.12f, 0.12f, yellow, 0, 0, c.from, c.to});
        raw.push_back({c.along_x, pos + 0.12f, 0.12f, yellow, 0, 0, c.from, c.to});
      }
    }
  }
  // Cut where other roads cross (1 m margin).
  std::vector<MarkingLine> out;
  for (const auto& l : raw) {
    std::vector<std::pair<float, float>> pieces{{l.from, l.to}};
    for (const auto& o : all) {
      if (o.along_x == c.along_x) continue;
      std::vector<std::pair<float, float>> next;
      for (auto [f, t] : pieces) {
        const float g0 = o.lo - 1, g1 = o.hi + 1;
        if (t <= g0 || f >= g1) {
          next.emplace_back(f, t);
          continue;
        }
        if (f < g0) next.emplace_back(f, g0);
        if (t > g1) next.emplace_back(g1, t);
      }
      pieces = next;
    }
    for (auto [f, t] : pieces) {
      MarkingLine m = l;
      m.from = f;
      m.to = t;
      out.push_back(m);
    }
  }
  return out;
}

TriangleMesh person_mesh() {
  TriangleMesh m;
  m.append(make_box({0.22f, 0.14f, 0.85f}, 0), at(0, -0.11f, 0.425f));  // legs: trousers
  m.append(make_box({0.22f, 0.14f, 0.85f}, 0), at(0, 0.11f, 0.425f));
  m.append(make_box({0.28f, 0.46f, 0.62f}, 1), at(0, 0, 1.16f));        // torso: jacket
  m.append(make_sphere(0.11f, 8, 12, 2), at(0, 0, 1.62f));              // head
  return m;
}

}  // namespace

std::optional<scene::TrackPoint> object_at_time(const scene::Scene& layout, const scene::ObjectTrack& o, double t) {
  const double f = t * layout.frame_rate_hz;
  const int f0 = int(std::floor(f));
  const double a = f - f0;
  const auto p0 = o.at(f0), p1 = o.at(f0 + 1);
  if (p0 && p1) {
    scene::TrackPoint p = *p0;
    p.center = p0->center * (1 - a) + p1->center * a;
    p.yaw = p0->yaw + a * std::remainder(p1->yaw - p0->yaw, 2 * M_PI);
    return p;
  }
  if (p0) return p0;
  return p1;
}

DemoWorld::DemoWorld(const scene::Scene& layout, const WorldOptions& o)
    : layout_(layout), o_(o), scene_(std::make_unique<RayScene>()), sky_([&] {
        SkyParams p;
        p.sun_direction = o.sun_direction.normalized();
        p.turbidity = o.turbidity;
        p.overcast = o.overcast;
        return Sky(p);
      }()) {
  sky_map_ = sky_.to_env_map(256, 128, false);  // the street has its own ground
  lighting_ = Lighting::from_sky(sky_, sky_map_);
  build_street();
  build_objects();
  scene_->commit();
}

void DemoWorld::build_street() {
  RayScene& rs = *scene_;
  std::mt19937_64 rng(o_.seed * 7919 + 13);
  std::uniform_real_distribution<float> u(0, 1);
  const auto cors = corridors(layout_.lanes);
  TriangleMesh statics;
  std::vector<uint32_t> slots;
  auto slot = [&](Material m) {
    slots.push_back(rs.add_material(std::move(m)));
    return uint16_t(slots.size() - 1);
  };
  // Ground beyond the street.
  Material grass = Material::coated("ground", Rgb(0.07f, 0.08f, 0.05f), 0.95f, 0.02f);
  grass.texture = std::make_shared<NoisyTexture>(0.3f, 0.25f, o_.seed + 1);
  const uint16_t ground = slot(grass);
  statics.append(make_quad(-600, -600, 900, 600, ground), at(0, 0, -0.03f));
  // Asphalt with the markings of every road.
  std::vector<MarkingLine> lines;
  std::vector<Crosswalk> walks;
  for (const auto& c : cors) {
    const auto m = markings(layout_.lanes, c, cors);
    lines.insert(lines.end(), m.begin(), m.end());
  }
  const Corridor* main = nullptr;
  for (const auto& c : cors)
    if (c.along_x) main = &c;
  for (const auto& c : cors)
    if (main != nullptr && !c.along_x) {
      // Zebra crossings over the main road on both sides of the crossing.
      walks.push_back({c.lo - 4.5f, main->lo, c.lo - 1.5f, main->hi, false});
      walks.push_back({c.hi + 1.5f, main->lo, c.hi + 4.5f, main->hi, false});
    }
  Material asphalt = Material::coated("asphalt", Rgb::Constant(0.085f), 0.85f, 0.03f);
  asphalt.texture = std::make_shared<AsphaltTexture>(lines, walks, o_.seed + 2);
  const uint16_t road = slot(asphalt);
  Material concrete = Material::coated("sidewalk", Rgb(0.3f, 0.29f, 0.27f), 0.9f, 0.02f);
  concrete.texture = std::make_shared<TileTexture>(o_.seed + 3, 1.0f);
  const uint16_t walk = slot(concrete);
  const float kSidewalk = 4.0f, kCurb = 0.15f;
  for (const auto& c : cors) {
    // The road surface: pieces outside roads of the other direction, to avoid overlaps.
    std::vector<std::pair<float, float>> along{{c.from, c.to}};
    std::vector<std::pair<float, float>> gaps;  // where sidewalks stop
    for (const auto& o : cors) {
      if (o.along_x == c.along_x) continue;
      gaps.emplace_back(o.lo - kSidewalk, o.hi + kSidewalk);
      if (!c.along_x) {
        std::vector<std::pair<float, float>> next;
        for (auto [f, t] : along) {
          if (t <= o.lo || f >= o.hi) next.emplace_back(f, t);
          else {
            if (f < o.lo) next.emplace_back(f, o.lo);
            if (t > o.hi) next.emplace_back(o.hi, t);
          }
        }
        along = next;
      }
    }
    for (auto [f, t] : along) {
      if (c.along_x) statics.append(make_quad(f, c.lo, t, c.hi, road));
      else statics.append(make_quad(c.lo, f, c.hi, t, road));
    }
    // Sidewalks (their road-side faces are the kerbs), broken where other roads cross.
    std::vector<std::pair<float, float>> pieces{{c.from, c.to}};
    for (auto [g0, g1] : gaps) {
      std::vector<std::pair<float, float>> next;
      for (auto [f, t] : pieces) {
        if (t <= g0 || f >= g1) next.emplace_back(f, t);
        else {
          if (f < g0) next.emplace_back(f, g0);
          if (t > g1) next.emplace_back(g1, t);
        }
      }
      pieces = next;
    }
    for (auto [f, t] : pieces)
      for (float side : {-1.0f, 1.0f}) {
        const float mid = side < 0 ? c.lo - kSidewalk / 2 : c.hi + kSidewalk / 2;
        const Eigen::Vector3f size = c.along_x ? Eigen::Vector3f(t - f, kSidewalk, kCurb) : Eigen::Vector3f(kSidewalk, t - f, kCurb);
        const Eigen::Vector3f centre = c.along_x ? Eigen::Vector3f((f + t) / 2, mid, kCurb / 2) : Eigen::Vector3f(mid, (f + t) / 2, kCurb / 2);
        statics.append(make_box(size, walk), at(centre.x(), centre.y(), centre.z()));
      }
  }
  // Buildings along the main road, trees and street lights on its sidewalks.
  if (main != nullptr) {
    const Rgb walls[] = {{0.45f, 0.2f, 0.12f}, {0.6f, 0.52f, 0.4f}, {0.4f, 0.4f, 0.42f}, {0.7f, 0.68f, 0.62f},
                         {0.3f, 0.35f, 0.42f}, {0.55f, 0.35f, 0.2f}};
    auto blocked = [&](float x0, float x1, float margin) {
      for (const auto& c : cors)
        if (!c.along_x && x1 > c.lo - margin && x0 < c.hi + margin) return true;
      return false;
    };
    for (float side : {-1.0f, 1.0f}) {
      const float front = side < 0 ? main->lo - kSidewalk : main->hi + kSidewalk;
      for (float x = main->from; x < main->to;) {
        const float width = 8 + 14 * u(rng);
        const float gap = u(rng) < 0.25f ? 3 + 6 * u(rng) : 0.3f * u(rng);
        if (!blocked(x, x + width, kSidewalk + 1.5f)) {
          FacadeStyle st;
          st.wall = walls[size_t(u(rng) * 6) % 6];
          st.height = 7 + 17 * u(rng);
          st.floor_height = 3.0f + 0.5f * u(rng);
          st.window_spacing = 2.6f + 1.2f * u(rng);
          st.window_width = 1.0f + 0.6f * u(rng);
          st.window_height = 1.3f + 0.5f * u(rng);
          st.seed = rng();
          Material m = Material::coated("building", st.wall, 0.85f, 0.03f);
          m.texture = std::make_shared<FacadeTexture>(st);
          const uint16_t b = slot(m);
          const float setback = 0.5f + 1.5f * u(rng), depth = 10 + 6 * u(rng);
          const float y = front + side * (setback + depth / 2);
          statics.append(make_box({width, depth, st.height}, b), at(x + width / 2, y, st.height / 2));
        }
        x += width + gap;
      }
    }
    // Buildings along the cross streets, beyond the main road's sidewalks.
    for (const auto& c : cors) {
      if (c.along_x) continue;
      for (float side : {-1.0f, 1.0f})
        for (float dir : {-1.0f, 1.0f}) {
          float y = dir < 0 ? main->lo - kSidewalk - 2 : main->hi + kSidewalk + 2;
          for (int k = 0; k < 4; ++k) {
            const float len = 10 + 10 * u(rng);
            FacadeStyle st;
            st.wall = walls[size_t(u(rng) * 6) % 6];
            st.height = 7 + 14 * u(rng);
            st.seed = rng();
            Material m = Material::coated("building", st.wall, 0.85f, 0.03f);
            m.texture = std::make_shared<FacadeTexture>(st);
            const uint16_t b = slot(m);
            const float depth = 10 + 5 * u(rng);
            const float x = side < 0 ? c.lo - kSidewalk - 1 - depth / 2 : c.hi + kSidewalk + 1 + depth / 2;
            statics.append(make_box({depth, len, st.height}, b), at(x, y + dir * len / 2, st.height / 2));
            y += dir * (len + 1 + 3 * u(rng));
          }
        }
    }
    Material bark = Material::coated("bark", Rgb(0.1f, 0.07f, 0.05f), 0.9f, 0.02f);
    const uint16_t trunk = slot(bark);
    Material leaves = Material::coated("foliage", Rgb(0.05f, 0.11f, 0.035f), 0.8f, 0.03f);
    leaves.texture = std::make_shared<NoisyTexture>(1.3f, 0.35f, o_.seed + 5);
    const uint16_t foliage = slot(leaves);
    const uint16_t metal = slot(Material::metal("pole", Rgb::Constant(0.45f), 0.45f));
    const uint16_t lamp = slot(Material::coated("lamp", Rgb::Constant(0.7f), 0.1f, 0.06f));
    for (float side : {-1.0f, 1.0f}) {
      const float ty = side < 0 ? main->lo - 2.6f : main->hi + 2.6f;
      for (float x = main->from + 6 * u(rng); x < main->to; x += 11 + 6 * u(rng)) {
        if (blocked(x - 3, x + 3, kSidewalk) || u(rng) < 0.3f) continue;
        const float h = 2.6f + 0.8f * u(rng);
        statics.append(make_frustum(0.16f, 0.11f, h + 0.8f, 10, trunk), at(x, ty, kCurb));
        const int blobs = 2 + int(u(rng) * 2);
        for (int k = 0; k < blobs; ++k) {
          const float r = 1.3f + 0.7f * u(rng);
          statics.append(make_sphere(r, 10, 16, foliage),
                         at(x + (u(rng) - 0.5f) * 1.6f, ty + (u(rng) - 0.5f) * 1.2f, kCurb + h + r * 0.8f + 0.6f * u(rng)));
        }
      }
      const float ly = side < 0 ? main->lo - 0.5f : main->hi + 0.5f;
      for (float x = main->from + 10 * u(rng); x < main->to; x += 30) {
        if (blocked(x - 2, x + 2, kSidewalk)) continue;
        statics.append(make_frustum(0.1f, 0.07f, 7.0f, 10, metal), at(x, ly, kCurb));
        statics.append(make_box({0.12f, 1.6f, 0.1f}, metal), at(x, ly - side * 0.8f, kCurb + 6.9f));
        statics.append(make_box({0.35f, 0.5f, 0.12f}, lamp), at(x, ly - side * 1.5f, kCurb + 6.8f));
      }
    }
  }
  rs.add_instance(rs.add_prototype(std::move(statics), slots), Eigen::Affine3f::Identity());
}

void DemoWorld::build_objects() {
  RayScene& rs = *scene_;
  for (const auto& o : layout_.objects) {
    const Eigen::Vector3f size = o.size_lwh.cast<float>();
    const std::array<int, 3> rgb = o.color_rgb.value_or(std::array<int, 3>{128, 128, 128});
    TriangleMesh mesh;
    std::vector<uint32_t> slots;
    if (o.has_category_prefix("vehicle")) {
      std::string asset = "sedan";
      if (o.has_category_prefix("vehicle.bus")) asset = "city_bus";
      else if (o.has_category_prefix("vehicle.truck")) asset = size.z() > 2.4f ? "box_truck" : "pickup_truck";
      else if (o.has_category_prefix("vehicle.motorcycle")) asset = "motorcycle";
      else if (o.has_category_prefix("vehicle.bicycle")) asset = "bicycle";
      else if (size.z() > 2.0f) asset = "van";
      else if (size.z() > 1.65f) asset = "suv";
      const auto model = agents::foreground::model_for({asset, "car", size, rgb});
      mesh = model.mesh;
      for (const auto& m : model.slots) slots.push_back(rs.add_material(m));
    } else if (o.has_category_prefix("human")) {
      mesh = person_mesh();
      const Rgb c = linear_from_srgb8(rgb[0], rgb[1], rgb[2]);
      slots = {rs.add_material(Material::coated("trousers", Rgb(0.04f, 0.05f, 0.09f), 0.8f)),
               rs.add_material(Material::coated("jacket", c, 0.7f)),
               rs.add_material(Material::coated("skin", Rgb(0.45f, 0.3f, 0.22f), 0.6f))};
      const float s = size.z() / 1.73f;
      mesh.transform(Eigen::Affine3f(Eigen::Scaling(s)));
    } else {
      mesh = make_box(size, 0);
      mesh.transform(at(0, 0, size.z() / 2));
      slots = {rs.add_material(Material::coated("object", linear_from_srgb8(rgb[0], rgb[1], rgb[2]), 0.6f))};
    }
    instances_[o.id] = rs.add_instance(rs.add_prototype(std::move(mesh), slots), Eigen::Affine3f::Identity());
  }
  place_objects(layout_.frames.empty() ? 0.0 : layout_.frames.front().timestamp_s);
}

void DemoWorld::place_objects(double t) {
  for (const auto& o : layout_.objects) {
    const auto it = instances_.find(o.id);
    if (it == instances_.end()) continue;
    const auto p = object_at_time(layout_, o, t);
    scene_->set_enabled(it->second, p.has_value() && !hidden_.count(o.id));
    if (!p) continue;
    Eigen::Affine3f xf = Eigen::Affine3f::Identity();
    xf.translate(Eigen::Vector3f(float(p->center.x()), float(p->center.y()), float(p->center.z() - o.size_lwh.z() / 2)));
    xf.rotate(Eigen::AngleAxisf(float(p->yaw), Eigen::Vector3f::UnitZ()));
    scene_->set_transform(it->second, xf);
  }
}

void DemoWorld::set_object_visible(const std::string& id, bool visible) {
  const auto it = instances_.find(id);
  if (it == instances_.end()) return;
  if (visible) hidden_.erase(id);
  else hidden_.insert(id);
  scene_->set_enabled(it->second, visible);
}

}  // namespace chatsim::render::demo
