#pragma once
// Removing labelled objects from a scene's images. The ground an object covered is seen, in
// other frames and cameras, where the object was not in the way: those views are gathered into
// a bird's-eye map of the ground around the object's track (in radiance units, so differently
// exposed cameras agree), what no view saw is filled there by exemplar inpainting (lane
// markings and kerbs continue straight in that view), and every image takes its fill from the
// one map, so the fill cannot flicker from frame to frame. Pixels whose rays do not end on that
// ground (what stood behind the object) come from a renderer without the object when one is
// given (unless what it renders there lies before the object: the object itself, misplaced),
// else from 2D inpainting that copies from beside the hole and never from objects that stay.
// The fill's level is matched to the image around it (seam_blend.hpp) and the seam is feathered.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::render::gs {
class RadianceField;
struct GsImage;
}

namespace chatsim::render::inpaint {

// Raised when what a deletion fills with changes (cached deletion stages key on it).
// 2: the fill's level matched to its surroundings; a rendered view's ground along a removed
// car's path cleared where the render and the ground map differ; the field's render in the
// image's own exposure; hidden objects take the background's ghosts in their swept space.
// 3: no ground-map fill where the ray meets the ground at a grazing angle.
// 4: 2D inpainting copies from beside the hole, never from kept objects; the field does not fill
// where its surface lies before the removed box.
inline constexpr int kDeletionVersion = 4;

struct DeletionImage {
  int frame = 0;
  std::string camera;
  scene::Camera cam;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double time = 0;
  double exposure = 1;
  cv::Mat radiance;      // CV_32FC3, linear scene radiance (pixel linear value / exposure)
  // A view the radiance field rendered (not a captured image): its z-depth (CV_32FC1, m). The
  // field learned a moving object's shadow smeared along the object's whole path, so there the
  // ground under that path is replaced too, not only the object's outline at this time.
  cv::Mat rendered_depth;
};

struct DeletionOptions {
  double bev_resolution_m = 0.04;
  double margin_m = 0.8;                         // ground around each footprint that may hold its shadow
  double context_m = 1.5;                        // seen ground around that, which the fill continues
  std::optional<Eigen::Vector3d> sun_direction;  // to follow the shadow (world, toward the sun)
  int feather_px = 3;
  int box_pad_px = 4;
  // A rendered view's ground along a removed car's path is replaced where the field's render
  // and the ground map differ by more than this (|log| of their smoothed radiance, in any
  // channel); 0: all of it.
  double path_min_log_step = 0.15;
  // The ground map fills a pixel only where its ray meets the ground at least this steeply. At
  // grazing angles a few centimetres of ground height (a kerb, a slope, a box's bottom) move the
  // point metres away, and the map's texture smears into streaks: the field's render, or 2D
  // inpainting of what the image shows around the hole, fills it instead. 4.5 deg is about 20 m
  // from a 1.6 m camera.
  double min_ground_depression_deg = 4.5;
  // 2D inpainting copies from beside each hole pixel (exemplar_inpaint.hpp's beside_slope; 0:
  // from anywhere near).
  double fill_beside_slope = 0.1;
  // The field's render fills behind the objects unless, over more than this share of the
  // pixels whose rays meet a deleted object's box, its surface lies in front of that box (it
  // renders the object itself, misplaced, not what stood behind it): then 2D inpainting does
  // (1: always the field).
  double max_field_in_front_share = 0.5;
  // Only boxes nearer than this count. Farther, a box covers few pixels and the field's depth is
  // loose: on the demo, a car 100 m away renders about 10 m and more before its box, yet the
  // field's colours fill it better than 2D inpainting (19.2 against 16.9 dB).
  double field_depth_check_max_m = 60;
};

// An image's view without the deleted objects (the radiance field), in the image's own units
// (its radiance x its exposure is the pixel), and its z-depth (CV_32FC1, m; infinite where
// nothing is). Either may be empty.
struct BackgroundView {
  cv::Mat radiance;
  cv::Mat depth;
};
using BackgroundRenderer = std::function<BackgroundView(const DeletionImage&, const std::vector<std::string>& hidden)>;

struct DeletionStats {
  int images_edited = 0;
  double ground_seen = 0;        // share of the ground map some view saw
  double seconds = 0;
  int fallback_pixels = 0;       // pixels not on the ground map
  int field_fills = 0;           // images whose fallback pixels the field's render filled
  int field_rejected = 0;        // images where its surface lay in front of the deleted boxes
};

// Where the objects (boxes and their shadows, padded) cover an image: CV_8UC1.
cv::Mat deletion_mask(const scene::Scene& scene, const DeletionImage& image, const std::vector<std::string>& ids,
                      const DeletionOptions& options = {});

// Edits `targets` in place; `sources` are every image the ground may be gathered from (targets
// may be among them: their masked pixels are never used).
DeletionStats delete_objects(const scene::Scene& scene, const std::vector<std::string>& ids, std::vector<DeletionImage>& targets,
                             const std::vector<DeletionImage>& sources, const DeletionOptions& options = {},
                             const BackgroundRenderer& background = nullptr);

// The radiance field's view without the hidden objects, rendered only around their masks (as
// the deletion agent fills what the ground map cannot). `scene` must outlive the renderer.
// `keep`, when given, is handed each render as the field made it (its depth serves the caller
// without a second render).
using RenderKeeper = std::function<void(const DeletionImage&, const gs::GsImage&)>;
BackgroundRenderer field_renderer(std::shared_ptr<const gs::RadianceField> model, const scene::Scene& scene,
                                  const DeletionOptions& options = {}, RenderKeeper keep = nullptr);

// What the field's radiance is multiplied by to be in an image's own units: a captured image
// divided by its recorded exposure differs from the field by the correction it learned for it.
double field_to_image_units(const gs::RadianceField& field, const scene::Scene& scene, const DeletionImage& image);

// A scene's captured images as deletion inputs (linear radiance at the recorded poses). With a
// radiance field, in its units: each image divided by the exposure the field learned for it
// (as the background stage's images are), else by its recorded exposure_s.
std::vector<DeletionImage> scene_images(const scene::Scene& scene, const gs::RadianceField* field = nullptr);

// The same images in a radiance field's units (its learned exposure per image), without reading
// them again.
std::vector<DeletionImage> in_field_units(std::vector<DeletionImage> images, const scene::Scene& scene, const gs::RadianceField& field);

}  // namespace chatsim::render::inpaint
