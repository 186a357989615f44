// chatsim eval deletion: vehicle deletion against the demo scene's clean plates.
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"
#include "render/gs/model.hpp"
#include "render/inpaint/deletion_eval.hpp"
#include "render/inpaint/moved_view_eval.hpp"

namespace chatsim::cli {
namespace {

struct EvalDeletionArgs {
  std::string scene, out, save, model;
  std::vector<std::string> objects;
  int max_objects = 0;
  bool moved_views = false, force = false;
};

int run_eval_deletion(const EvalDeletionArgs& a) {
  return exit_code_of([&] {
    if (a.moved_views && a.model.empty()) throw std::invalid_argument("--moved-views needs --model: the views are the radiance field's renders");
    // Where the results go, checked before any work.
    if (!a.out.empty()) prepare_output_file(a.out);
    std::optional<StagedOutputDir> save;
    if (!a.save.empty()) save.emplace(a.save, "images", a.force, "--save");
    const std::string save_dir = save ? save->path().string() : "";
    const auto s = scene::load_scene(a.scene);
    if (a.moved_views) {
      const auto r = render::inpaint::evaluate_moved_view_deletion(
          s, std::make_shared<render::gs::RadianceField>(render::gs::RadianceField::load(a.model)), save_dir);
      if (save) save->commit();
      if (!a.out.empty()) std::ofstream(a.out) << r.dump(1) << "\n";
      std::cout << r.dump(1) << "\n";
      return exit_code::kOk;
    }
    render::inpaint::DeletionEvalOptions o;
    o.progress = [](const std::string& line) { std::cerr << "deletion: " << line << std::endl; };
    o.objects = a.objects;
    if (!a.model.empty()) {
      // As the deletion agent does: the field's view without the vehicle, where the map ends.
      o.background = render::inpaint::field_renderer(std::make_shared<render::gs::RadianceField>(render::gs::RadianceField::load(a.model)), s);
    }
    o.max_objects = a.max_objects;
    o.save_dir = save_dir;
    const auto r = render::inpaint::evaluate_deletion(s, o);
    if (save) save->commit();
    if (!a.out.empty()) std::ofstream(a.out) << r.dump(1) << "\n";
    std::cout << r.dump(1) << "\n";
    return exit_code::kOk;
  });
}

}  // namespace

void add_eval_deletion_command(CLI::App& eval, int& result) {
  auto a = std::make_shared<EvalDeletionArgs>();
  auto* cmd = eval.add_subcommand("deletion", "Remove each demo-scene vehicle in turn and compare with the clean plates "
                                              "inside the mask (PSNR, SSIM), temporal flicker and time per image, against "
                                              "cv::inpaint (Telea) on the same masks; JSON");
  cmd->add_option("--scene", a->scene, "a rendered demo scene (with ground_truth/clean_plates.json)")->required();
  cmd->add_option("--objects", a->objects, "object ids (default: every vehicle with plates)");
  cmd->add_option("--max-objects", a->max_objects, "at most this many (largest plates first)");
  cmd->add_option("--out", a->out, "also write the JSON here (replaced)");
  cmd->add_option("--save", a->save, "write before / after / baseline / plate images into this folder (new, empty, or "
                                     "images chatsim wrote)");
  cmd->add_flag("--force", a->force, kForceHelp);
  cmd->add_option("--model", a->model,
                  "a radiance field of this scene (chatsim train): fill what the ground map cannot from it, as the deletion "
                  "agent does (default: 2D inpainting)")->check(CLI::ExistingFile);
  cmd->add_flag("--moved-views", a->moved_views,
               "instead: remove every vehicle from the field's renders of the shifted ground-truth views (as in a moved view) "
               "and score against the truth where the deletion changed the render (needs --model)");
  cmd->callback([a, &result] { result = run_eval_deletion(*a); });
}

}  // namespace chatsim::cli
