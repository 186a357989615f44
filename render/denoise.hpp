#pragma once
// Edge-aware smoothing of a render's diffuse illumination (the part of each pixel's light that
// varies slowly over a surface, divided by the surface's albedo), guided by normals and depth:
// an a-trous wavelet filter. Texture detail stays sharp because the albedo is multiplied back
// afterwards; sunlight and reflections are never filtered.
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::render {

// illumination: CV_32FC3; normal: CV_32FC3 (camera frame, unit; zero where nothing);
// depth: CV_32FC1 (z-depth, +inf where nothing); valid: CV_8UC1 (non-zero where the
// illumination is defined). The camera gives the pixels' rays (region: where the images sit in
// the full frame).
cv::Mat smooth_illumination(const cv::Mat& illumination, const cv::Mat& normal, const cv::Mat& depth,
                            const cv::Mat& valid, const scene::Camera& camera, cv::Point region_origin,
                            int iterations = 4);

}  // namespace chatsim::render
