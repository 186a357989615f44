#include "agents/render/render_pipeline.hpp"

#include <chrono>
#include <fstream>

#include "agents/core/scene_cache.hpp"
#include "agents/render/render_cache.hpp"
#include "agents/render/render_job.hpp"
#include "agents/render/result_writer.hpp"
#include "render/image_io.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/preset_names.hpp"

namespace chatsim::agents::render {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Runs one stage: skipped when its folder is complete, else asked of the agent in chunks of
// images (or all at once), marked complete at the end.
struct StageRun {
  bool reused = false;
  double seconds = 0;
  json answers = json::array();
};

StageRun run_stage(const manager::AgentCaller& call, const manager::FanoutCaller& fanout, const std::string& kind,
                   const std::string& action, const std::string& scene, RenderJob job,
                   const std::vector<std::vector<int>>& chunks, const std::string& stage, const json& key,
                   const PipelineProgress& progress, double timeout_s) {
  StageRun run;
  const auto t0 = std::chrono::steady_clock::now();
  if (stage_complete(job.out)) {
    run.reused = true;
    if (progress) progress(stage, 1.0, stage + ": unchanged since an earlier round, reused");
    return run;
  }
  fs::remove_all(job.out);
  fs::create_directories(job.out);
  auto take = [&](const AgentOutcome& out) {
    if (!out.ok) throw std::runtime_error("the " + kind + " agent failed (" + stage + "): " + out.message);
    run.answers.push_back(out.result);
  };
  auto finish = [&] {
    run.seconds = seconds_since(t0);
    mark_stage_complete(job.out, {{"key", key}, {"seconds", run.seconds}, {"answers", run.answers}});
    if (progress) progress(stage, 1.0, stage + ": done in " + std::to_string(int(run.seconds)) + " s");
    return run;
  };
  if (fanout && chunks.size() > 1) {
    // Every chunk at once, spread over the workers of this kind.
    std::vector<AgentCall> calls;
    for (const auto& c : chunks) {
      job.frames = c;
      calls.push_back(AgentCall{action, scene, job.to_json(), timeout_s});
    }
    if (progress) progress(stage, 0, stage + ": " + std::to_string(chunks.size()) + " chunks over the " + kind + " workers");
    const auto outs = fanout(kind, calls);
    for (const auto& out : outs) take(out);
    return finish();
  }
  for (size_t k = 0; k < chunks.size(); ++k) {
    job.frames = chunks[k];
    if (progress) progress(stage, double(k) / double(chunks.size()), stage + ": frames " + std::to_string(chunks[k].front()) + "-" + std::to_string(chunks[k].back()));
    take(call(kind, AgentCall{action, scene, job.to_json(), timeout_s}));
  }
  return finish();
}

// Cameras left to right for the video: by the yaw of their optical axis in the ego frame.
std::vector<std::string> cameras_left_to_right(const scene::Scene& s) {
  std::vector<std::string> order;
  for (const auto& c : s.cameras) order.push_back(c.name);
  auto yaw = [&](const std::string& n) {
    const Eigen::Vector3d z = s.camera(n)->sensor_to_ego.linear().col(2);
    return std::atan2(z.y(), z.x());
  };
  std::sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) { return yaw(a) > yaw(b); });
  return order;
}

// What composition wrote, for result.json.
struct Composed {
  size_t images = 0, frames = 0;
  std::vector<std::string> cameras;  // left to right
  std::string codec;
};

// The last stage's images into dir: PNG frames and depth per camera, the side-by-side video,
// labels (JSON, KITTI) and edit.json.
Composed compose_result(const scene::Scene& s, const RenderJob& job, const fs::path& last, const json& edit, const fs::path& dir,
                        const PipelineProgress& progress) {
  Composed c;
  const auto images = view_images(s, job, nullptr);
  c.images = images.size();
  c.cameras = cameras_left_to_right(s);
  std::map<int, std::map<std::string, cv::Mat>> by_frame;
  size_t done = 0;
  for (const auto& im : images) {
    const cv::Mat radiance = chatsim::render::read_float_image(radiance_file(last, im.camera, im.frame));
    const double exposure = read_exposure(last, im.camera, im.frame);
    const cv::Mat rgb = chatsim::render::encode_srgb8(radiance, float(exposure));
    char name[32];
    std::snprintf(name, sizeof name, "%06d", im.frame);
    chatsim::render::write_rgb8(dir / "frames" / im.camera / (std::string(name) + ".png"), rgb);
    const fs::path d = depth_file(last, im.camera, im.frame);
    if (fs::exists(d)) {
      fs::create_directories(dir / "depth" / im.camera);
      fs::copy_file(d, dir / "depth" / im.camera / (std::string(name) + ".exr"));
    }
    by_frame[im.frame][im.camera] = rgb;
    if (progress && (++done % 12 == 0 || done == images.size()))
      progress("composition", double(done) / double(images.size()), "composition: " + std::to_string(done) + "/" + std::to_string(images.size()) + " images");
  }
  c.frames = by_frame.size();
  std::vector<std::vector<cv::Mat>> video;
  for (const auto& [f, cams] : by_frame) {
    std::vector<cv::Mat> row;
    for (const auto& n : c.cameras)
      if (cams.count(n)) row.push_back(cams.at(n));
    if (row.size() == c.cameras.size()) video.push_back(row);
  }
  if (progress) progress("encoding", 0, "encoding: video and labels");
  c.codec = write_side_by_side_video(dir / "video.mp4", video, s.frame_rate_hz);
  const json labels = edited_labels(s, edit, images);
  fs::create_directories(dir / "labels");
  std::ofstream(dir / "labels" / "labels.json") << labels.dump(1) << "\n";
  write_kitti_labels(labels, images, dir / "labels" / "kitti");
  std::ofstream(dir / "edit.json") << edit.dump(1) << "\n";
  return c;
}

}  // namespace

RenderPreset render_preset(const std::string& name) {
  if (name == "draft") return {"draft", 8};
  if (name.empty() || name == "fast") return {"fast", 32};
  if (name == "quality") return {"quality", 128};
  throw std::invalid_argument("unknown rendering preset '" + name + "' (use " + std::string(kPresetChoices) + ")");
}

AgentOutcome render_edit(const manager::AgentCaller& call, const RenderTask& task, const PipelineProgress& progress,
                         const manager::FanoutCaller& fanout) {
  const auto t_all = std::chrono::steady_clock::now();
  try {
    if (task.output_dir.empty()) return AgentOutcome::failure(ErrorKind::BadRequest, "no output folder given (--out DIR)");
    const auto s = cached_scene(task.scene_dir);
    if (s->layout_only)
      return AgentOutcome::failure(ErrorKind::BadRequest, s->dir.string() + " is a layout-only scene: it has no images to render "
                                                                           "(render the demo scene without --layout-only)");
    // Before any work: a folder it may not write is refused now, not after training.
    refuse_output_over_input(task.output_dir, s->dir, "--out", "--scene");
    StagedOutputDir staged(task.output_dir, "result", task.force_output);
    const json& edit = task.edit_state;
    const view::ViewState view = view::view_state_from_json(edit.value("view", json::object()));
    std::vector<std::string> removed = edit.value("removed", std::vector<std::string>{});
    std::sort(removed.begin(), removed.end());
    const json added = edit.value("added", json::array());
    std::vector<int> frames;
    for (const auto& f : s->frames) frames.push_back(f.index);
    std::vector<std::vector<int>> chunks;
    const size_t per_chunk = size_t(std::max(1, task.chunk / std::max<int>(1, int(s->cameras.size()))));
    for (size_t i = 0; i < frames.size(); i += per_chunk)
      chunks.emplace_back(frames.begin() + long(i), frames.begin() + long(std::min(frames.size(), i + per_chunk)));
    const std::string skey = scene_key(*s);
    const fs::path stages = cache_root() / "renders" / skey;
    json timings = json::object(), reuse = json::object();

    // The radiance field: needed for a new view, for what deleted vehicles hid, and for the
    // depth and surroundings of added ones. Trained once per scene.
    std::string model;
    const bool need_model = !is_original_view(view) || !removed.empty() || !added.empty();
    if (need_model) {
      const auto t0 = std::chrono::steady_clock::now();
      if (progress) progress("background", 0, "background: the scene's radiance field (trained on first use, then cached)");
      const AgentOutcome m = call("background", AgentCall{"ensure_model", task.scene_dir, {{"preset", task.preset}}, 6 * 3600.0});
      if (!m.ok) throw std::runtime_error("the background agent could not provide a radiance field: " + m.message);
      model = m.result["model"];
      timings["training"] = seconds_since(t0);
      reuse["training"] = !m.result.value("trained", false);
    }
    // The scene's light, for deletion's shadows and the added vehicles: estimated once here (and
    // cached), not by every worker of those stages at once. An agent that cannot (a mock) leaves
    // it to the stages.
    if (!removed.empty() || !added.empty()) {
      const auto t0 = std::chrono::steady_clock::now();
      if (progress) progress("light", 0, "light: the scene's sky and sun (estimated on first use, then cached)");
      const AgentOutcome l = call("foreground", AgentCall{"light", task.scene_dir, json::object(), 600.0});
      // Gone or not running: the foreground stage could not run either, so say so now.
      if (!l.ok && l.error == ErrorKind::Unavailable) throw std::runtime_error("the foreground agent failed (light): " + l.message);
      timings["light"] = seconds_since(t0);
      reuse["light"] = l.ok && !l.result.value("estimated", false);
      if (progress) progress("light", 1.0, l.ok ? "light: " + l.result.value("sky_type", std::string("?")) + " sky, sun from " + l.result.value("sun_cue", std::string("?"))
                                                : "light: not estimated ahead (" + l.message + "); the stages estimate it");
    }
    RenderJob job;
    job.view = view;
    job.model = model;
    // Background.
    const json bg_key{{"scene", skey}, {"view", view::to_json(view)}, {"model", model}};
    job.out = stages / ("background-" + json_hash(bg_key));
    const StageRun bg = run_stage(call, fanout, "background", "render", task.scene_dir, job, chunks, "background", bg_key, progress, 3600);
    timings["background"] = bg.seconds, reuse["background"] = bg.reused;
    fs::path last = job.out;
    json last_key = bg_key;
    // Deletion: one request for all frames, so one ground map serves every frame.
    if (!removed.empty()) {
      // The fill's and the light estimator's versions too: a stage made by older code is not reused.
      const json key = deletion_stage_key(last_key, removed);
      RenderJob dj = job;
      dj.in = last;
      dj.removed = removed;
      dj.out = stages / ("deletion-" + json_hash(key));
      const StageRun del = run_stage(call, fanout, "deletion", "inpaint", task.scene_dir, dj, {frames}, "deletion", key, progress, 3600);
      timings["deletion"] = del.seconds, reuse["deletion"] = del.reused;
      last = dj.out, last_key = key;
    }
    // Added vehicles.
    if (!added.empty()) {
      const json key = foreground_stage_key(last_key, added, task.foreground_spp);
      RenderJob fj = job;
      fj.in = last;
      fj.removed = removed;
      fj.added = added;
      fj.spp = task.foreground_spp;
      fj.out = stages / ("foreground-" + json_hash(key));
      const StageRun fg = run_stage(call, fanout, "foreground", "render", task.scene_dir, fj, chunks, "foreground", key, progress, 3600);
      timings["foreground"] = fg.seconds, reuse["foreground"] = fg.reused;
      last = fj.out, last_key = key;
    }
    // Composition and encoding into the result folder (complete or absent: written aside first).
    const auto t_enc = std::chrono::steady_clock::now();
    const Composed c = compose_result(*s, job, last, edit, staged.path(), progress);
    timings["composition_and_encoding"] = seconds_since(t_enc);
    timings["total"] = seconds_since(t_all);
    const fs::path& out = staged.target();
    const json summary{{"scene", s->dir.string()}, {"images", c.images}, {"frames", c.frames}, {"cameras", c.cameras},
                       {"video", (out / "video.mp4").string()}, {"video_codec", c.codec}, {"seconds", timings},
                       {"reused", reuse}, {"model", model}};
    std::ofstream(staged.path() / "result.json") << summary.dump(1) << "\n";
    staged.commit();
    if (progress) progress("encoding", 1, "done: " + (out / "video.mp4").string());
    json result = summary;
    result["output_dir"] = out.string();
    return AgentOutcome::success(result);
  } catch (const scene::SceneError& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
  } catch (const OutputDirError& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, e.what());
  } catch (const std::exception& e) {
    return AgentOutcome::failure(ErrorKind::Internal, e.what());
  }
}

}  // namespace chatsim::agents::render
