// chatsim asset list / preview: what the asset bank holds, and a picture of one asset.
#include <filesystem>
#include <iostream>

#include <opencv2/imgproc.hpp>

#include "agents/asset/catalog.hpp"
#include "agents/foreground/asset_bank.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/commands.hpp"
#include "render/image_io.hpp"
#include "render/path_tracer.hpp"

namespace chatsim::cli {
namespace {

struct PreviewArgs {
  std::string asset;
  std::string out = "asset.png";
  std::vector<int> color;
  int width = 480, height = 320, spp = 32;
};

int run_list() {
  try {
    const auto& c = agents::asset::Catalog::instance();
    for (const auto& e : c.entries()) {
      std::cout << e.asset << "\t" << e.type << "\t" << (e.brand.empty() ? "-" : e.brand) << "\t" << e.size_lwh[0] << "x"
                << e.size_lwh[1] << "x" << e.size_lwh[2] << " m\t"
                << (e.external ? e.external->file.string() : "parametric " + e.shape) << "\n";
    }
    return exit_code::kOk;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
}

int run_preview(const PreviewArgs& a) {
  try {
    prepare_output_file(a.out);  // before rendering
    std::array<int, 3> rgb{200, 30, 30};
    if (a.color.size() == 3) rgb = {a.color[0], a.color[1], a.color[2]};
    render::AssetModel model;
    const std::filesystem::path as_file(a.asset);
    if (as_file.has_extension() && std::filesystem::exists(as_file)) {
      model = agents::foreground::model_from_file(a.asset, rgb);
    } else {
      const auto* e = agents::asset::Catalog::instance().find(a.asset);
      if (e == nullptr) {
        std::cerr << "error: no asset '" << a.asset << "' in the catalogue and no such file (chatsim asset list shows them)\n";
        return exit_code::kUsage;
      }
      if (a.color.size() != 3) rgb = e->color_rgb;
      model = agents::foreground::model_for({e->asset, e->type,
                                             Eigen::Vector3f(float(e->size_lwh[0]), float(e->size_lwh[1]), float(e->size_lwh[2])), rgb});
    }
    render::RayScene rs;
    std::vector<uint32_t> slots;
    for (const auto& m : model.slots) slots.push_back(rs.add_material(m));
    const uint32_t ground = rs.add_material(render::Material::diffuse("ground", render::Rgb::Constant(0.2f)));
    rs.add_instance(rs.add_prototype(render::make_quad(-100, -100, 100, 100), {ground}), Eigen::Affine3f::Identity());
    rs.add_instance(rs.add_prototype(model.mesh, slots), Eigen::Affine3f::Identity());
    rs.commit();
    render::SkyParams sp;
    sp.sun_direction = Eigen::Vector3f(0.4f, 0.6f, 0.7f);
    const render::Sky sky(sp);
    const render::EnvMap map = sky.to_env_map(256, 128);
    const auto lighting = render::Lighting::from_sky(sky, map);
    // A three-quarter view from the front left, far enough to frame the whole asset.
    const Eigen::Vector3f size = model.size();
    const double dist = 1.6 * std::max({size.x(), size.y(), size.z()}) + 2;
    const Eigen::Vector3d target(0, 0, size.z() * 0.45);
    const Eigen::Vector3d eye = target + Eigen::Vector3d(0.75, 0.55, 0.3).normalized() * dist;
    const Eigen::Vector3d z = (target - eye).normalized(), x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
    Eigen::Isometry3d c2w = Eigen::Isometry3d::Identity();
    c2w.linear() << x, z.cross(x), z;
    c2w.translation() = eye;
    scene::Camera cam;
    cam.width = a.width;
    cam.height = a.height;
    cam.fx = cam.fy = a.width / 2.0 / std::tan(22.5 * M_PI / 180);
    cam.cx = a.width / 2.0;
    cam.cy = a.height / 2.0;
    render::RenderSettings s;
    s.spp = a.spp;
    s.clamp_indirect = 20 * render::luminance(map.irradiance(Eigen::Vector3f::UnitZ())) / float(M_PI);
    const auto view = render::render_view(rs, lighting, cam, c2w, s);
    // Auto-exposure: the median pixel at mid-grey.
    cv::Mat lum;
    cv::cvtColor(view.radiance, lum, cv::COLOR_RGB2GRAY);
    std::vector<float> v(lum.begin<float>(), lum.end<float>());
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    const float exposure = 0.18f / std::max(v[v.size() / 2], 1e-6f);
    render::write_rgb8(a.out, render::encode_srgb8(view.radiance, exposure));
    std::cout << "wrote " << a.out << ": " << model.mesh.triangle_count() << " triangles, " << size.x() << " x "
              << size.y() << " x " << size.z() << " m\n";
    return exit_code::kOk;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
}

}  // namespace

void add_asset_command(CLI::App& app, int& result) {
  auto* asset = app.add_subcommand("asset", "The asset bank: list assets, render a preview of one");
  asset->require_subcommand(1);
  auto* list = asset->add_subcommand("list", "Every asset in the catalogue (assets/catalog.json and $CHATSIM_ASSETS): "
                                             "name, type, brand, size, model");
  list->callback([&result] { result = run_list(); });
  auto args = std::make_shared<PreviewArgs>();
  auto* preview = asset->add_subcommand("preview", "Path-trace one asset (a catalogue name or a .glb/.gltf/.obj file) "
                                                   "on a grey ground under a clear sky");
  preview->add_option("asset", args->asset, "catalogue name or model file")->required();
  preview->add_option("--out", args->out, "PNG to write (replaced)")->capture_default_str();
  preview->add_option("--color", args->color, "paint colour R G B (0..255)")->expected(3);
  preview->add_option("--width", args->width, "image width")->check(CLI::Range(16, 8192));
  preview->add_option("--height", args->height, "image height")->check(CLI::Range(16, 8192));
  preview->add_option("--spp", args->spp, "samples per pixel")->check(CLI::Range(1, 4096));
  preview->callback([args, &result] { result = run_preview(*args); });
}

}  // namespace chatsim::cli
