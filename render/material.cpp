#include "render/material.hpp"

#include <algorithm>
#include <cmath>

#include "render/sampling.hpp"

namespace chatsim::render {

Material Material::diffuse(std::string name, const Rgb& albedo) {
  Material m;
  m.name = std::move(name);
  m.albedo = albedo;
  m.roughness = 1.0f;
  m.specular = 0.0f;
  return m;
}
Material Material::coated(std::string name, const Rgb& albedo, float roughness, float specular) {
  Material m;
  m.name = std::move(name);
  m.albedo = albedo;
  m.roughness = roughness;
  m.specular = specular;
  return m;
}
Material Material::metal(std::string name, const Rgb& f0, float roughness) {
  Material m;
  m.name = std::move(name);
  m.kind = MaterialKind::Metal;
  m.albedo = f0;
  m.roughness = roughness;
  return m;
}
Material Material::emissive(std::string name, const Rgb& radiance) {
  Material m;
  m.name = std::move(name);
  m.kind = MaterialKind::Emissive;
  m.albedo = Rgb::Zero();
  m.emission = radiance;
  return m;
}
Material Material::shadow_catcher(const Rgb& albedo) {
  Material m = diffuse("shadow_catcher", albedo);
  m.kind = MaterialKind::ShadowCatcher;
  return m;
}

namespace {

float ggx_d(float cos_h, float a2) {
  const float c2 = cos_h * cos_h;
  const float d = c2 * (a2 - 1) + 1;
  return a2 / (kPi * d * d);
}
float smith_g1(float cos_v, float a2) {
  const float c = std::max(cos_v, 1e-6f);
  return 2 * c / (c + std::sqrt(a2 + (1 - a2) * c * c));
}
float schlick(float f0, float cos_t) {
  const float m = std::clamp(1 - cos_t, 0.0f, 1.0f);
  const float m2 = m * m;
  return f0 + (1 - f0) * m2 * m2 * m;
}
Rgb schlick(const Rgb& f0, float cos_t) {
  const float m = std::clamp(1 - cos_t, 0.0f, 1.0f);
  const float m5 = m * m * m * m * m;
  return f0 + (Rgb::Ones() - f0) * m5;
}

}  // namespace

Bsdf::Bsdf(const Material& m, const SurfacePoint& p)
    : kind(m.kind), albedo(p.albedo), alpha(std::max(0.02f * 0.02f, p.roughness * p.roughness)), specular(p.specular) {}

float Bsdf::specular_probability(const Eigen::Vector3f& wo) const {
  if (kind == MaterialKind::Metal) return 1.0f;
  if (specular <= 0) return 0.0f;
  const float fs = schlick(specular, wo.z());
  const float diffuse = (1 - fs) * std::max(luminance(albedo), 0.01f);
  return std::clamp(fs / (fs + diffuse), 0.05f, 0.95f);
}

void Bsdf::eval_lobes(const Eigen::Vector3f& wo, const Eigen::Vector3f& wi, Rgb& diffuse, Rgb& spec) const {
  diffuse.setZero();
  spec.setZero();
  if (wo.z() <= 0 || wi.z() <= 0 || kind == MaterialKind::Emissive) return;
  const float a2 = alpha * alpha;
  const Eigen::Vector3f h = (wo + wi).normalized();
  const float spec_common = ggx_d(h.z(), a2) * smith_g1(wo.z(), a2) * smith_g1(wi.z(), a2) / (4 * wo.z());
  if (kind == MaterialKind::Metal) {
    spec = schlick(albedo, wi.dot(h)) * spec_common;
    return;
  }
  if (specular > 0) spec = Rgb::Constant(schlick(specular, wi.dot(h)) * spec_common);
  // The diffuse base sees what the coat lets through, in and out.
  const float through = specular > 0 ? (1 - schlick(specular, wi.z())) * (1 - schlick(specular, wo.z())) : 1.0f;
  diffuse = albedo * (through * wi.z() / kPi);
}

Rgb Bsdf::eval(const Eigen::Vector3f& wo, const Eigen::Vector3f& wi) const {
  Rgb d, s;
  eval_lobes(wo, wi, d, s);
  return d + s;
}

float Bsdf::pdf(const Eigen::Vector3f& wo, const Eigen::Vector3f& wi) const {
  if (wo.z() <= 0 || wi.z() <= 0 || kind == MaterialKind::Emissive) return 0.0f;
  const float ps = specular_probability(wo);
  float p = 0;
  if (ps > 0) {
    const Eigen::Vector3f h = (wo + wi).normalized();
    p += ps * ggx_d(h.z(), alpha * alpha) * h.z() / (4 * std::max(wo.dot(h), 1e-6f));
  }
  if (ps < 1) p += (1 - ps) * wi.z() / kPi;
  return p;
}

bool Bsdf::sample(const Eigen::Vector3f& wo, float u0, float u1, float u2, Sample& out) const {
  if (wo.z() <= 0 || kind == MaterialKind::Emissive) return false;
  const float ps = specular_probability(wo);
  out.specular = u0 < ps;
  if (out.specular) {
    // GGX normal distribution sampling: D(h) cos(h).
    const float a2 = alpha * alpha;
    const float cos2 = (1 - u1) / (1 + (a2 - 1) * u1);
    const float cos_h = std::sqrt(std::max(cos2, 0.0f)), sin_h = std::sqrt(std::max(0.0f, 1 - cos2));
    const float phi = 2 * kPi * u2;
    const Eigen::Vector3f h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
    out.wi = 2 * wo.dot(h) * h - wo;
  } else {
    out.wi = sample_cosine_hemisphere(u1, u2);
  }
  if (out.wi.z() <= 0) return false;
  out.pdf = pdf(wo, out.wi);
  if (out.pdf <= 0) return false;
  out.weight = eval(wo, out.wi) / out.pdf;
  return out.weight.allFinite();
}

}  // namespace chatsim::render
