#include "render/demo/street_textures.hpp"

#include <cmath>

#include "render/noise.hpp"

namespace chatsim::render::demo {
namespace {
float positive_mod(float a, float m) {
  const float r = std::fmod(a, m);
  return r < 0 ? r + m : r;
}
}  // namespace

SurfacePoint AsphaltTexture::shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f&,
                                   const Eigen::Vector3f&) const {
  SurfacePoint s = base;
  // Patches at a few metres, a faint grain at decimetres: enough to look like asphalt, smooth
  // enough that a radiance field can represent it.
  const float v = 1 + 0.16f * fbm(Eigen::Vector3f(p.x() * 0.25f, p.y() * 0.25f, 0), seed_, 3) +
                  0.05f * fbm(Eigen::Vector3f(p.x() * 2.5f, p.y() * 2.5f, 0), seed_ + 17, 2);
  s.albedo = base.albedo * v;
  for (const auto& l : lines_) {
    const float across = l.along_x ? p.y() : p.x();
    const float along = l.along_x ? p.x() : p.y();
    if (std::abs(across - l.position) > l.width / 2 || along < l.from || along > l.to) continue;
    if (l.dash_on > 0 && positive_mod(along - l.from, l.dash_on + l.dash_off) > l.dash_on) continue;
    s.albedo = l.colour * (0.92f + 0.08f * v);
    s.roughness = 0.6f;
    s.specular = 0.05f;
    return s;
  }
  for (const auto& c : crosswalks_) {
    if (p.x() < c.x0 || p.x() > c.x1 || p.y() < c.y0 || p.y() > c.y1) continue;
    const float across = c.stripes_along_x ? p.y() - c.y0 : p.x() - c.x0;
    if (positive_mod(across, 1.0f) < 0.5f) {
      s.albedo = Rgb::Constant(0.72f) * (0.92f + 0.08f * v);
      s.roughness = 0.6f;
      s.specular = 0.05f;
    }
    return s;
  }
  return s;
}

SurfacePoint TileTexture::shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f&,
                                const Eigen::Vector3f& n) const {
  SurfacePoint s = base;
  if (std::abs(n.z()) < 0.7f) return s;  // kerb faces: plain concrete
  const float fx = p.x() / tile_, fy = p.y() / tile_;
  const int ix = int(std::floor(fx)), iy = int(std::floor(fy));
  const float gx = fx - float(ix), gy = fy - float(iy);
  const float joint = 0.03f / tile_;
  if (gx < joint || gy < joint) {
    s.albedo = base.albedo * 0.6f;
    return s;
  }
  s.albedo = base.albedo * (0.9f + 0.2f * lattice_value(ix, iy, 0, seed_));
  return s;
}

SurfacePoint FacadeTexture::shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f& uv,
                                  const Eigen::Vector3f& n) const {
  SurfacePoint s = base;
  if (std::abs(n.z()) > 0.7f) {
    s.albedo = s_.roof;
    s.roughness = 0.9f;
    return s;
  }
  s.albedo = s_.wall * (1 + 0.08f * fbm(p * 0.7f, s_.seed, 2));
  s.roughness = 0.85f;
  s.specular = 0.03f;
  const float u = uv.x(), v = uv.y();
  bool window = false;
  if (v < s_.ground_floor) {
    window = positive_mod(u, 6.0f) > 0.8f && positive_mod(u, 6.0f) < 5.2f && v > 0.5f && v < s_.ground_floor - 0.6f;
  } else if (v < s_.height - 0.9f) {
    const float fu = positive_mod(u, s_.window_spacing), fv = positive_mod(v - s_.ground_floor, s_.floor_height);
    const float margin = (s_.window_spacing - s_.window_width) / 2;
    window = fu > margin && fu < margin + s_.window_width && fv > 0.8f && fv < 0.8f + s_.window_height;
  }
  if (window) {
    s.albedo = Rgb(0.03f, 0.035f, 0.045f);
    s.roughness = 0.05f;
    s.specular = 0.07f;
  }
  return s;
}

SurfacePoint NoisyTexture::shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f&,
                                 const Eigen::Vector3f&) const {
  SurfacePoint s = base;
  s.albedo = base.albedo * std::max(0.2f, 1 + amount_ * 2 * fbm(p * scale_, seed_, 3));
  return s;
}

}  // namespace chatsim::render::demo
