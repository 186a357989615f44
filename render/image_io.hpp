#pragma once
// Float image files: OpenEXR (and reading Radiance .hdr) through OpenImageIO, 8-bit PNG/JPEG
// through OpenCV. Writes go to a temporary name first and are renamed when complete, so a
// crash never leaves a half-written file under the final name.
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace chatsim::render {

// A float image of any channel count (CV_32FC1..4) as EXR (float). Zip by default; None for
// intermediate files read back at once: zip costs about 70 ms per 640x426 RGB image, which
// over a pipeline's stages is seconds, for a file only 1.3 times smaller.
enum class ExrCompression { Zip, None };
void write_exr(const std::filesystem::path& file, const cv::Mat& image, ExrCompression compression = ExrCompression::Zip);
// Any float image file OpenImageIO reads (EXR, HDR, ...); channels as stored (RGB order).
cv::Mat read_float_image(const std::filesystem::path& file);

// 8-bit RGB images (cv::Mat CV_8UC3 in RGB order, not OpenCV's BGR) as PNG or JPEG by extension.
void write_rgb8(const std::filesystem::path& file, const cv::Mat& rgb, int jpeg_quality = 95);
cv::Mat read_rgb8(const std::filesystem::path& file);  // throws naming the file when unreadable

// Linear radiance (CV_32FC3, RGB) x exposure through the sRGB OETF to 8 bits, clipped.
cv::Mat encode_srgb8(const cv::Mat& radiance, float exposure);
// 8-bit sRGB (RGB) back to linear values (radiance x exposure).
cv::Mat decode_srgb8(const cv::Mat& rgb8);

// The temporary name a file is written under before it is renamed into place.
std::filesystem::path partial_name(const std::filesystem::path& file);

}  // namespace chatsim::render
