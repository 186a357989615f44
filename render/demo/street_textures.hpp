#pragma once
// Procedural textures of the demo street: asphalt with lane markings and crosswalks, sidewalk
// tiles, building facades with windows, foliage and grass. All deterministic in world position.
#include <vector>

#include "render/color.hpp"
#include "render/material.hpp"

namespace chatsim::render::demo {

struct MarkingLine {
  bool along_x = true;          // the line runs along x (at y = position) or along y
  float position = 0;
  float width = 0.15f;
  Rgb colour{0.75f, 0.75f, 0.75f};
  float dash_on = 0, dash_off = 0;  // 0: solid
  float from = 0, to = 0;       // extent along the line
};

struct Crosswalk {
  float x0, y0, x1, y1;         // the area; stripes run along x, 0.5 m wide every 1 m across y
  bool stripes_along_x = true;
};

class AsphaltTexture : public Texture {
 public:
  AsphaltTexture(std::vector<MarkingLine> lines, std::vector<Crosswalk> crosswalks, uint64_t seed)
      : lines_(std::move(lines)), crosswalks_(std::move(crosswalks)), seed_(seed) {}
  SurfacePoint shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f& uv,
                     const Eigen::Vector3f& n) const override;

 private:
  std::vector<MarkingLine> lines_;
  std::vector<Crosswalk> crosswalks_;
  uint64_t seed_;
};

class TileTexture : public Texture {
 public:
  explicit TileTexture(uint64_t seed, float tile = 1.0f) : seed_(seed), tile_(tile) {}
  SurfacePoint shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f& uv,
                     const Eigen::Vector3f& n) const override;

 private:
  uint64_t seed_;
  float tile_;
};

struct FacadeStyle {
  Rgb wall{0.5f, 0.4f, 0.3f};
  Rgb roof{0.2f, 0.2f, 0.2f};
  float floor_height = 3.2f;
  float window_spacing = 3.0f, window_width = 1.3f, window_height = 1.5f;
  float ground_floor = 3.6f;
  float height = 12.0f;
  uint64_t seed = 1;
};

class FacadeTexture : public Texture {
 public:
  explicit FacadeTexture(const FacadeStyle& s) : s_(s) {}
  SurfacePoint shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f& uv,
                     const Eigen::Vector3f& n) const override;

 private:
  FacadeStyle s_;
};

// Albedo varied by fractal noise (foliage, grass, bark).
class NoisyTexture : public Texture {
 public:
  NoisyTexture(float scale, float amount, uint64_t seed) : scale_(scale), amount_(amount), seed_(seed) {}
  SurfacePoint shade(const SurfacePoint& base, const Eigen::Vector3f& p, const Eigen::Vector2f& uv,
                     const Eigen::Vector3f& n) const override;

 private:
  float scale_, amount_;
  uint64_t seed_;
};

}  // namespace chatsim::render::demo
