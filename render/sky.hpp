#pragma once
// Analytic skies in SCENE_FORMAT.md radiance units: the Preetham et al. (1999) clear sky with a
// sun disc, and the CIE standard overcast sky. The demo scene is lit by one; lighting
// estimation fits one; tests compare against their closed forms.
#include <Eigen/Core>

#include "render/color.hpp"
#include "render/env_map.hpp"

namespace chatsim::render {

// The sun seen from the ground: 0.53 degrees across.
inline constexpr float kSunHalfAngleRad = 0.00465f;
float sun_solid_angle_sr();  // 6.8e-5
float sun_cos_half_angle();

// Radiance units per kcd/m^2 of luminance: chosen so exposures of a few milliseconds expose
// a sunlit street well, as for a real camera.
inline constexpr float kUnitsPerKcd = 15.0f;

struct SkyParams {
  Eigen::Vector3f sun_direction{0.5f, -0.3f, 0.81f};  // world, z up; normalised on use
  float turbidity = 3.0f;                             // 2 (very clear) .. 10 (hazy)
  bool overcast = false;                              // CIE overcast: no sun, no azimuth
  float overcast_zenith_kcd = 3.0f;
  float ground_albedo = 0.15f;                        // below the horizon
  bool compute_ground = true;                         // false: skip the ground's irradiance (fitting)
};

class Sky {
 public:
  explicit Sky(const SkyParams& params);
  const SkyParams& params() const { return p_; }
  const Eigen::Vector3f& sun_direction() const { return sun_; }
  bool has_sun() const { return !p_.overcast && sun_.z() > -0.05f; }
  // Radiance of the sky (sun disc excluded) from direction d (world, unit).
  Rgb radiance(const Eigen::Vector3f& d) const;
  // Radiance of the sun disc (zero when overcast or set).
  Rgb sun_radiance() const { return sun_radiance_; }
  // The sky without the disc as an equirect map; below the horizon, a diffuse ground lit by
  // sun and sky (with_ground), or black where the scene has its own ground geometry.
  EnvMap to_env_map(int width = 512, int height = 256, bool with_ground = true) const;

 private:
  Rgb preetham(const Eigen::Vector3f& d) const;
  SkyParams p_;
  Eigen::Vector3f sun_;
  float theta_s_ = 0;
  Eigen::Vector3f zenith_xyY_;
  float coef_[3][5]{};      // Y, x, y distribution coefficients A..E
  float norm_[3]{};         // F(0, theta_s) for Y, x, y
  Rgb sun_radiance_ = Rgb::Zero();
  Rgb ground_ = Rgb::Zero();
};

}  // namespace chatsim::render
