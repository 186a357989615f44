#pragma once
// Physically based surfaces: a diffuse base under a dielectric GGX coat (paint, plastic,
// asphalt, rubber, window glass), GGX metal (chrome), emitters (lamps), and the shadow
// catcher (an invisible ground that only records shadows).
#include <memory>
#include <string>

#include "render/color.hpp"

namespace chatsim::render {

enum class MaterialKind { Coated, Metal, Emissive, ShadowCatcher };

// What a texture says about a point: overrides for the material's constants.
struct SurfacePoint {
  Rgb albedo;
  float roughness;
  float specular;  // normal-incidence reflectance of the coat (0.04 for most dielectrics)
};

// Procedural or image textures: called at every shading point.
class Texture {
 public:
  virtual ~Texture() = default;
  virtual SurfacePoint shade(const SurfacePoint& base, const Eigen::Vector3f& world_position,
                             const Eigen::Vector2f& uv, const Eigen::Vector3f& normal) const = 0;
};

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::Coated;
  Rgb albedo{0.5f, 0.5f, 0.5f};   // diffuse base (Coated) or F0 colour (Metal)
  float roughness = 0.5f;          // GGX alpha = roughness^2
  float specular = 0.04f;          // coat reflectance at normal incidence (Coated)
  Rgb emission = Rgb::Zero();      // Emissive, in radiance units
  std::shared_ptr<const Texture> texture;

  static Material diffuse(std::string name, const Rgb& albedo);
  static Material coated(std::string name, const Rgb& albedo, float roughness, float specular = 0.04f);
  static Material metal(std::string name, const Rgb& f0, float roughness);
  static Material emissive(std::string name, const Rgb& radiance);
  static Material shadow_catcher(const Rgb& albedo = Rgb::Constant(0.15f));
};

// A material evaluated at one point, in the local shading frame (z = normal).
struct Bsdf {
  MaterialKind kind = MaterialKind::Coated;
  Rgb albedo;
  float alpha = 0.25f;
  float specular = 0.04f;

  Bsdf(const Material& m, const SurfacePoint& p);
  // f(wo, wi) * cos(theta_i), both directions local and pointing away from the surface.
  Rgb eval(const Eigen::Vector3f& wo, const Eigen::Vector3f& wi) const;
  // The same, split into the diffuse base and the specular coat (or metal).
  void eval_lobes(const Eigen::Vector3f& wo, const Eigen::Vector3f& wi, Rgb& diffuse, Rgb& specular) const;
  float pdf(const Eigen::Vector3f& wo, const Eigen::Vector3f& wi) const;
  struct Sample {
    Eigen::Vector3f wi;
    Rgb weight;   // f cos / pdf
    float pdf = 0;
    bool specular = false;  // which lobe drew it
  };
  // False when no direction could be drawn (below the surface).
  bool sample(const Eigen::Vector3f& wo, float u0, float u1, float u2, Sample& out) const;

 private:
  float specular_probability(const Eigen::Vector3f& wo) const;
};

}  // namespace chatsim::render
