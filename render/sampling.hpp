#pragma once
// Seeded random numbers and the sampling routines the renderers share. Every pixel's generator
// is seeded from (image seed, pixel), so a render is the same whatever the thread count.
#include <cmath>
#include <cstdint>
#include <numbers>

#include <Eigen/Core>

namespace chatsim::render {

inline constexpr float kPi = std::numbers::pi_v<float>;

// PCG32 (O'Neill): small state, good statistics, cheap to seed per pixel.
class Rng {
 public:
  explicit Rng(uint64_t seed, uint64_t stream = 1) : inc_((stream << 1u) | 1u) {
    next();
    state_ += seed;
    next();
  }
  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const auto xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
  }
  // Uniform in [0, 1).
  float uniform() { return float(next() >> 8) * (1.0f / 16777216.0f); }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

// A 64-bit mix (splitmix64's finaliser), for seeds made of several numbers.
inline uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
inline uint64_t hash_seed(uint64_t a, uint64_t b, uint64_t c = 0, uint64_t d = 0) {
  return mix64(a ^ mix64(b ^ mix64(c ^ mix64(d))));
}

// An orthonormal frame around a unit normal (Duff et al. 2017).
struct Frame {
  Eigen::Vector3f t, b, n;
  explicit Frame(const Eigen::Vector3f& normal) : n(normal) {
    const float sign = std::copysign(1.0f, n.z());
    const float a = -1.0f / (sign + n.z());
    const float bb = n.x() * n.y() * a;
    t = Eigen::Vector3f(1.0f + sign * n.x() * n.x() * a, sign * bb, -sign * n.x());
    b = Eigen::Vector3f(bb, sign + n.y() * n.y() * a, -n.y());
  }
  Eigen::Vector3f to_world(const Eigen::Vector3f& v) const { return t * v.x() + b * v.y() + n * v.z(); }
  Eigen::Vector3f to_local(const Eigen::Vector3f& v) const { return {v.dot(t), v.dot(b), v.dot(n)}; }
};

// Cosine-weighted direction on the +z hemisphere; pdf = cos / pi.
inline Eigen::Vector3f sample_cosine_hemisphere(float u1, float u2) {
  const float r = std::sqrt(u1);
  const float phi = 2 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1 - u1))};
}

// Uniform direction inside a cone of half-angle acos(cos_max) around +z; pdf = 1 / solid angle.
inline Eigen::Vector3f sample_cone(float u1, float u2, float cos_max) {
  const float c = 1 - u1 * (1 - cos_max);
  const float s = std::sqrt(std::max(0.0f, 1 - c * c));
  const float phi = 2 * kPi * u2;
  return {s * std::cos(phi), s * std::sin(phi), c};
}
inline float cone_solid_angle(float cos_max) { return 2 * kPi * (1 - cos_max); }

// The power heuristic (beta = 2) for multiple importance sampling.
inline float mis_weight(float pdf_a, float pdf_b) {
  const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  return a + b > 0 ? a / (a + b) : 0.0f;
}

}  // namespace chatsim::render
