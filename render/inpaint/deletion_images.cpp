// The scene's captured images for deletion, and their radiance in the field's units.
#include "render/gs/model.hpp"
#include "render/image_io.hpp"
#include "render/inpaint/deletion.hpp"

namespace chatsim::render::inpaint {

double field_to_image_units(const gs::RadianceField& field, const scene::Scene& s, const DeletionImage& im) {
  return field.exposure(s, im.frame, im.camera) / im.exposure;
}

std::vector<DeletionImage> in_field_units(std::vector<DeletionImage> images, const scene::Scene& s, const gs::RadianceField& field) {
  for (auto& im : images) {
    const double exposure = field.exposure(s, im.frame, im.camera);
    // A new buffer (assigning the product would write into the one the caller's copy shares);
    // the same pixels: radiance x exposure is kept.
    const cv::Mat scaled = im.radiance * (im.exposure / exposure);
    im.radiance = scaled;
    im.exposure = exposure;
  }
  return images;
}

std::vector<DeletionImage> scene_images(const scene::Scene& s, const gs::RadianceField* field) {
  std::vector<DeletionImage> out;
  for (const auto& f : s.frames)
    for (const auto& [name, ref] : f.images) {
      const auto* cam = s.camera(name);
      if (cam == nullptr) continue;
      DeletionImage im;
      im.frame = f.index;
      im.camera = name;
      im.cam = *cam;
      im.pose = s.camera_to_world(f, *cam);
      im.time = ref.timestamp_s;
      im.exposure = ref.exposure_s.value_or(1.0);
      im.radiance = decode_srgb8(read_rgb8(s.dir / ref.path)) / im.exposure;
      out.push_back(std::move(im));
    }
  return field ? in_field_units(std::move(out), s, *field) : out;
}

}  // namespace chatsim::render::inpaint
