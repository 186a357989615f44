#pragma once
// The radiance field's far field: radiance by direction only (the sky and anything too far to
// show parallax), an equirect texture of log radiance, bilinearly sampled.
#include <vector>

#include <Eigen/Core>

namespace chatsim::render::gs {

class SkyTexture {
 public:
  SkyTexture(int width = 128, int height = 64, float log_radiance = 0.0f);
  int width() const { return w_; }
  int height() const { return h_; }
  std::vector<float>& data() { return texels_; }              // w * h * 3 log radiance
  const std::vector<float>& data() const { return texels_; }

  struct Taps {
    int index[4];
    float weight[4];
  };
  Taps taps(const Eigen::Vector3f& direction) const;
  Eigen::Vector3f radiance(const Eigen::Vector3f& direction) const;   // linear
  Eigen::Vector3f radiance(const Taps& t) const;
  // Accumulates dL/d(log texel) given dL/d(radiance) at a direction with these taps.
  void backward(const Taps& t, const Eigen::Vector3f& grad_radiance, const Eigen::Vector3f& radiance,
                float* grad_texels) const;

 private:
  int w_, h_;
  std::vector<float> texels_;
};

}  // namespace chatsim::render::gs
