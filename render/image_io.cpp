#include "render/image_io.hpp"

#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <unistd.h>

#include "render/color.hpp"

namespace chatsim::render {
namespace fs = std::filesystem;

fs::path partial_name(const fs::path& file) {
  return file.parent_path() / ("." + file.filename().string() + ".part" + std::to_string(getpid()));
}

void write_exr(const fs::path& file, const cv::Mat& image, ExrCompression compression) {
  if (image.depth() != CV_32F) throw std::invalid_argument("write_exr: " + file.string() + ": not a float image");
  if (!file.parent_path().empty()) fs::create_directories(file.parent_path());
  const cv::Mat img = image.isContinuous() ? image : image.clone();
  // The temporary keeps the .exr extension: OpenImageIO picks the format from it.
  const fs::path tmp = file.parent_path() / ("." + file.stem().string() + ".part" + std::to_string(getpid()) + ".exr");
  auto out = OIIO::ImageOutput::create(tmp.string());
  if (!out) throw std::runtime_error("cannot write " + file.string() + ": " + OIIO::geterror());
  OIIO::ImageSpec spec(img.cols, img.rows, img.channels(), OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", compression == ExrCompression::Zip ? "zip" : "none");
  if (!out->open(tmp.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, img.ptr<float>()) || !out->close())
    throw std::runtime_error("cannot write " + file.string() + ": " + out->geterror());
  fs::rename(tmp, file);
}

cv::Mat read_float_image(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error("cannot read " + file.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  cv::Mat img(spec.height, spec.width, CV_32FC(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.ptr<float>()))
    throw std::runtime_error("cannot read " + file.string() + ": " + in->geterror());
  in->close();
  return img;
}

void write_rgb8(const fs::path& file, const cv::Mat& rgb, int jpeg_quality) {
  if (!file.parent_path().empty()) fs::create_directories(file.parent_path());
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<uchar> bytes;
  const std::string ext = file.extension().string();
  std::vector<int> params;
  if (ext == ".jpg" || ext == ".jpeg") params = {cv::IMWRITE_JPEG_QUALITY, jpeg_quality};
  if (!cv::imencode(ext, bgr, bytes, params)) throw std::runtime_error("cannot encode " + file.string());
  const fs::path tmp = partial_name(file);
  {
    FILE* f = std::fopen(tmp.c_str(), "wb");
    if (f == nullptr) throw std::runtime_error("cannot write " + file.string());
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (std::fclose(f) != 0 || !ok) throw std::runtime_error("cannot write " + file.string());
  }
  fs::rename(tmp, file);
}

cv::Mat read_rgb8(const fs::path& file) {
  cv::Mat bgr = cv::imread(file.string(), cv::IMREAD_COLOR);
  if (bgr.empty()) throw std::runtime_error(file.string() + ": not a readable image (missing or corrupt)");
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return rgb;
}

cv::Mat encode_srgb8(const cv::Mat& radiance, float exposure) {
  cv::Mat out(radiance.rows, radiance.cols, CV_8UC3);
  for (int y = 0; y < radiance.rows; ++y) {
    const auto* src = radiance.ptr<cv::Vec3f>(y);
    auto* dst = out.ptr<cv::Vec3b>(y);
    for (int x = 0; x < radiance.cols; ++x)
      for (int c = 0; c < 3; ++c) dst[x][c] = uchar(std::lround(srgb_oetf(src[x][c] * exposure) * 255.0f));
  }
  return out;
}

cv::Mat decode_srgb8(const cv::Mat& rgb8) {
  const auto& table = srgb_to_linear_table();
  cv::Mat out(rgb8.rows, rgb8.cols, CV_32FC3);
  for (int y = 0; y < rgb8.rows; ++y) {
    const auto* src = rgb8.ptr<cv::Vec3b>(y);
    auto* dst = out.ptr<cv::Vec3f>(y);
    for (int x = 0; x < rgb8.cols; ++x)
      for (int c = 0; c < 3; ++c) dst[x][c] = table[src[x][c]];
  }
  return out;
}

}  // namespace chatsim::render
