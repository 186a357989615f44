// A scene's frames as the light estimator's views and ground boxes, and the clip's estimate.
#include <algorithm>

#include "common/scene/camera_model.hpp"
#include "common/scene/objects.hpp"
#include "render/image_io.hpp"
#include "render/light/light_estimate.hpp"

namespace chatsim::render::light {

std::vector<LightView> scene_light_views(const scene::Scene& s, int frame) {
  std::vector<LightView> out;
  for (const auto& f : s.frames) {
    if (f.index != frame) continue;
    for (const auto& [name, ref] : f.images) {
      const auto* cam = s.camera(name);
      if (cam == nullptr) continue;
      out.push_back({*cam, s.camera_to_world(f, *cam), read_rgb8(s.dir / ref.path), ref.exposure_s.value_or(1.0), frame});
    }
  }
  return out;
}

std::vector<GroundBox> scene_ground_boxes(const scene::Scene& s, int frame) {
  std::vector<GroundBox> out;
  for (const auto& o : s.objects)
    if (o.has_category_prefix("vehicle"))
      if (const auto p = o.at(frame)) out.push_back({p->center, o.size_lwh, p->yaw, frame, o.has_category_prefix("vehicle.car")});
  return out;
}

std::vector<int> scene_light_frames(const scene::Scene& s, int frames) {
  std::vector<int> out;
  const int n = int(s.frames.size()), m = std::min(std::max(frames, 1), n);
  // The middle frame of each of m equal parts of the clip.
  for (int k = 0; k < m; ++k) out.push_back(s.frames[size_t((2 * k + 1) * n / (2 * m))].index);
  return out;
}

LightEstimate estimate_scene_light(const scene::Scene& s, int frames) {
  std::vector<LightView> views;
  std::vector<GroundBox> boxes;
  for (const int f : scene_light_frames(s, frames)) {
    for (auto& v : scene_light_views(s, f)) views.push_back(std::move(v));
    for (const auto& b : scene_ground_boxes(s, f)) boxes.push_back(b);
  }
  return estimate_light(views, boxes);
}

}  // namespace chatsim::render::light
