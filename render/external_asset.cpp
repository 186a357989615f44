// External assets: glTF/GLB through tinygltf, OBJ through tinyobjloader, normalised to the
// asset convention (metres, bottom-centre origin, +x front, z up) with per-triangle colours
// grouped into material slots and the body's colour chosen as the paint.
#include <cmath>
#include <map>
#include <stdexcept>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "render/asset_model.hpp"
#include "render/color.hpp"

namespace chatsim::render {
namespace fs = std::filesystem;
namespace {

struct Soup {
  std::vector<Eigen::Vector3f> corners;  // 3 per triangle
  std::vector<Rgb> colour;               // linear, per triangle
  std::vector<std::string> material;     // the file's material name, per triangle
};

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
  throw std::runtime_error(file.string() + ": " + what);
}

// --- glTF ---

// Reads element i of an accessor as up to 4 floats (normalised integers become 0..1).
Eigen::Vector4f read_element(const tinygltf::Model& m, const tinygltf::Accessor& acc, size_t i) {
  const auto& view = m.bufferViews.at(size_t(acc.bufferView));
  const auto& buf = m.buffers.at(size_t(view.buffer));
  const int comps = tinygltf::GetNumComponentsInType(uint32_t(acc.type));
  const int comp_size = tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType));
  const size_t stride = view.byteStride ? view.byteStride : size_t(comps * comp_size);
  const size_t off = view.byteOffset + acc.byteOffset + i * stride;
  if (off + size_t(comps * comp_size) > buf.data.size()) throw std::out_of_range("accessor reads past its buffer");
  const unsigned char* p = buf.data.data() + off;
  Eigen::Vector4f v(0, 0, 0, 1);
  for (int c = 0; c < comps && c < 4; ++c) {
    switch (acc.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p + c * 4, 4); v[c] = f; break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v[c] = float(p[c]) / (acc.normalized ? 255.0f : 1.0f); break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t s; std::memcpy(&s, p + c * 2, 2); v[c] = float(s) / (acc.normalized ? 65535.0f : 1.0f); break; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t s; std::memcpy(&s, p + c * 4, 4); v[c] = float(s); break; }
      case TINYGLTF_COMPONENT_TYPE_BYTE: v[c] = std::max(float(int8_t(p[c])) / (acc.normalized ? 127.0f : 1.0f), -1.0f); break;
      case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t s; std::memcpy(&s, p + c * 2, 2); v[c] = std::max(float(s) / (acc.normalized ? 32767.0f : 1.0f), -1.0f); break; }
      default: throw std::runtime_error("unsupported accessor component type");
    }
  }
  return v;
}

uint32_t read_index(const tinygltf::Model& m, const tinygltf::Accessor& acc, size_t i) {
  return uint32_t(read_element(m, acc, i).x());
}

Eigen::Matrix4f node_matrix(const tinygltf::Node& n) {
  Eigen::Matrix4f t = Eigen::Matrix4f::Identity();
  if (n.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) t(r, c) = float(n.matrix[size_t(c * 4 + r)]);  // column-major
    return t;
  }
  Eigen::Affine3f a = Eigen::Affine3f::Identity();
  if (n.translation.size() == 3) a.translate(Eigen::Vector3f(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
  if (n.rotation.size() == 4)
    a.rotate(Eigen::Quaternionf(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
  if (n.scale.size() == 3) a.scale(Eigen::Vector3f(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
  return a.matrix();
}

Rgb sample_texture(const tinygltf::Image& img, float u, float v) {
  if (img.width <= 0 || img.height <= 0 || img.image.empty() || img.component < 3) return Rgb::Ones();
  u -= std::floor(u);
  v -= std::floor(v);
  const int x = std::clamp(int(u * float(img.width)), 0, img.width - 1);
  const int y = std::clamp(int(v * float(img.height)), 0, img.height - 1);
  const size_t at = (size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.component);
  if (img.bits != 8 || at + 2 >= img.image.size()) return Rgb::Ones();
  return linear_from_srgb8(img.image[at], img.image[at + 1], img.image[at + 2]);
}

void add_gltf_node(const tinygltf::Model& m, int node_index, const Eigen::Matrix4f& parent, Soup& soup, int depth) {
  if (depth > 64) throw std::runtime_error("node hierarchy deeper than 64 (a cycle?)");
  const auto& node = m.nodes.at(size_t(node_index));
  const Eigen::Matrix4f world = parent * node_matrix(node);
  if (node.mesh >= 0) {
    for (const auto& prim : m.meshes.at(size_t(node.mesh)).primitives) {
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;  // points and lines draw nothing
      const auto pos_it = prim.attributes.find("POSITION");
      if (pos_it == prim.attributes.end()) continue;
      const auto& pos = m.accessors.at(size_t(pos_it->second));
      const auto uv_it = prim.attributes.find("TEXCOORD_0");
      const tinygltf::Accessor* uv = uv_it != prim.attributes.end() ? &m.accessors.at(size_t(uv_it->second)) : nullptr;
      Rgb factor = Rgb::Ones();
      const tinygltf::Image* tex = nullptr;
      std::string mat_name;
      if (prim.material >= 0) {
        const auto& mat = m.materials.at(size_t(prim.material));
        mat_name = mat.name;
        const auto& f = mat.pbrMetallicRoughness.baseColorFactor;
        if (f.size() >= 3) factor = Rgb(float(f[0]), float(f[1]), float(f[2]));
        const int ti = mat.pbrMetallicRoughness.baseColorTexture.index;
        if (ti >= 0 && size_t(ti) < m.textures.size()) {
          const int src = m.textures[size_t(ti)].source;
          if (src >= 0 && size_t(src) < m.images.size()) tex = &m.images[size_t(src)];
        }
      }
      std::vector<uint32_t> idx;
      if (prim.indices >= 0) {
        const auto& ia = m.accessors.at(size_t(prim.indices));
        for (size_t i = 0; i < ia.count; ++i) idx.push_back(read_index(m, ia, i));
      } else {
        for (size_t i = 0; i < pos.count; ++i) idx.push_back(uint32_t(i));
      }
      for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        Eigen::Vector2f uvc = Eigen::Vector2f::Zero();
        for (int k = 0; k < 3; ++k) {
          if (idx[t + size_t(k)] >= pos.count) throw std::runtime_error("an index points past the vertices");
          const Eigen::Vector4f p = read_element(m, pos, idx[t + size_t(k)]);
          soup.corners.push_back((world * Eigen::Vector4f(p.x(), p.y(), p.z(), 1)).head<3>());
          if (uv != nullptr) uvc += read_element(m, *uv, idx[t + size_t(k)]).head<2>() / 3.0f;
        }
        Rgb c = factor;
        if (tex != nullptr && uv != nullptr) c = c.cwiseProduct(sample_texture(*tex, uvc.x(), uvc.y()));
        soup.colour.push_back(c);
        soup.material.push_back(mat_name);
      }
    }
  }
  for (int child : node.children) add_gltf_node(m, child, world, soup, depth + 1);
}

Soup load_gltf(const fs::path& file) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                         : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
  if (!ok) fail(file, "not a readable glTF file: " + (err.empty() ? std::string("unknown error") : err));
  Soup soup;
  try {
    std::vector<int> roots;
    if (!model.scenes.empty()) {
      const size_t s = model.defaultScene >= 0 ? size_t(model.defaultScene) : 0;
      roots = model.scenes.at(s).nodes;
    } else {
      for (size_t i = 0; i < model.nodes.size(); ++i) roots.push_back(int(i));
    }
    for (int r : roots) add_gltf_node(model, r, Eigen::Matrix4f::Identity(), soup, 0);
  } catch (const std::exception& e) {
    fail(file, std::string("malformed glTF: ") + e.what());
  }
  return soup;
}

// --- OBJ ---

Soup load_obj(const fs::path& file) {
  tinyobj::ObjReaderConfig cfg;
  cfg.triangulate = true;
  cfg.mtl_search_path = file.parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(file.string(), cfg))
    fail(file, "not a readable OBJ file: " + (reader.Error().empty() ? std::string("unknown error") : reader.Error()));
  const auto& attrib = reader.GetAttrib();
  const auto& mats = reader.GetMaterials();
  Soup soup;
  for (const auto& shape : reader.GetShapes()) {
    const auto& ids = shape.mesh.material_ids;
    for (size_t f = 0; f + 2 < shape.mesh.indices.size(); f += 3) {
      for (int k = 0; k < 3; ++k) {
        const int vi = shape.mesh.indices[f + size_t(k)].vertex_index;
        if (vi < 0 || size_t(3 * vi + 2) >= attrib.vertices.size()) fail(file, "a face points past the vertices");
        soup.corners.emplace_back(attrib.vertices[size_t(3 * vi)], attrib.vertices[size_t(3 * vi + 1)], attrib.vertices[size_t(3 * vi + 2)]);
      }
      const int mid = f / 3 < ids.size() ? ids[f / 3] : -1;
      if (mid >= 0 && size_t(mid) < mats.size()) {
        const auto& d = mats[size_t(mid)].diffuse;
        soup.colour.emplace_back(d[0], d[1], d[2]);
        soup.material.push_back(mats[size_t(mid)].name);
      } else {
        soup.colour.emplace_back(0.6f, 0.6f, 0.6f);
        soup.material.emplace_back();
      }
    }
  }
  return soup;
}

Eigen::Vector3f axis_vector(const std::string& axis, const fs::path& file) {
  if (axis.size() != 2 || (axis[0] != '+' && axis[0] != '-') || axis[1] < 'x' || axis[1] > 'z')
    fail(file, "axis '" + axis + "' is not one of +x, -x, +y, -y, +z, -z");
  Eigen::Vector3f v = Eigen::Vector3f::Zero();
  v[axis[1] - 'x'] = axis[0] == '+' ? 1.0f : -1.0f;
  return v;
}

bool glass_like(const Rgb& c) {
  // Window colours in low-poly palettes: light, and bluer than red.
  return luminance(c) > 0.35f && c.z() > c.x() * 1.15f && c.z() >= c.y();
}

// The body's colour in a model without named materials: the largest group of similar hues
// among saturated colours (a palette's gradient gives one body several shades), else, for a
// white, grey or black car, the largest colour that is neither glass nor near-black.
std::vector<bool> find_paint(const std::vector<Material>& slots, const std::vector<float>& area) {
  struct Hsv {
    float h, s, v;
  };
  auto hsv = [](const Rgb& lin) {
    const Rgb c(srgb_oetf(lin.x()), srgb_oetf(lin.y()), srgb_oetf(lin.z()));
    const float mx = c.maxCoeff(), mn = c.minCoeff(), d = mx - mn;
    float h = 0;
    if (d > 1e-6f) {
      if (mx == c.x()) h = 60 * std::fmod((c.y() - c.z()) / d, 6.0f);
      else if (mx == c.y()) h = 60 * ((c.z() - c.x()) / d + 2);
      else h = 60 * ((c.x() - c.y()) / d + 4);
    }
    return Hsv{h < 0 ? h + 360 : h, mx > 0 ? d / mx : 0, mx};
  };
  auto hue_gap = [](float a, float b) {
    const float d = std::abs(a - b);
    return std::min(d, 360 - d);
  };
  std::vector<Hsv> c(slots.size());
  float total = 0;
  for (size_t s = 0; s < slots.size(); ++s) {
    c[s] = hsv(slots[s].albedo);
    total += area[s];
  }
  auto chromatic = [&](size_t s) { return slots[s].name != "glass" && c[s].s > 0.3f && c[s].v > 0.2f; };
  // The hue with the most saturated area within 25 degrees of it.
  float best_area = 0, best_hue = 0;
  for (size_t s = 0; s < slots.size(); ++s) {
    if (!chromatic(s)) continue;
    float around = 0;
    for (size_t k = 0; k < slots.size(); ++k)
      if (chromatic(k) && hue_gap(c[s].h, c[k].h) < 25) around += area[k];
    if (around > best_area) {
      best_area = around;
      best_hue = c[s].h;
    }
  }
  std::vector<bool> paint(slots.size(), false);
  if (best_area > 0.15f * total) {
    for (size_t k = 0; k < slots.size(); ++k) paint[k] = chromatic(k) && hue_gap(best_hue, c[k].h) < 25;
    return paint;
  }
  size_t best = slots.size();
  for (size_t s = 0; s < slots.size(); ++s)
    if (slots[s].name != "glass" && luminance(slots[s].albedo) > 0.02f && (best == slots.size() || area[s] > area[best])) best = s;
  if (best < slots.size()) paint[best] = true;
  return paint;
}

}  // namespace

AssetModel load_external_asset(const fs::path& file, const ExternalAssetOptions& o) {
  if (!fs::exists(file)) fail(file, "no such file");
  std::string ext = file.extension().string();
  for (auto& ch : ext) ch = char(std::tolower(ch));
  Soup soup;
  if (ext == ".glb" || ext == ".gltf") soup = load_gltf(file);
  else if (ext == ".obj") soup = load_obj(file);
  else fail(file, "unknown asset format '" + ext + "' (use .glb, .gltf or .obj)");
  if (soup.colour.empty()) fail(file, "no triangles in the file");
  // Orientation: the file's front becomes +x, its up +z.
  const Eigen::Vector3f front = axis_vector(o.front_axis, file), up = axis_vector(o.up_axis, file);
  if (std::abs(front.dot(up)) > 0.5f) fail(file, "front axis " + o.front_axis + " and up axis " + o.up_axis + " are not perpendicular");
  Eigen::Matrix3f rot;
  rot.row(0) = front.transpose();
  rot.row(1) = up.cross(front).transpose();
  rot.row(2) = up.transpose();
  // Colours into slots: one per distinct colour (quantised), or per named paint material.
  AssetModel a;
  a.name = file.stem().string();
  std::map<std::array<int, 3>, uint16_t> slot_of;
  std::vector<float> area;
  for (size_t t = 0; t < soup.colour.size(); ++t) {
    const Rgb c = soup.colour[t];
    const std::array<int, 3> key{int(srgb_oetf(c.x()) * 31.99f), int(srgb_oetf(c.y()) * 31.99f), int(srgb_oetf(c.z()) * 31.99f)};
    auto it = slot_of.find(key);
    if (it == slot_of.end()) {
      if (slot_of.size() >= 60000) fail(file, "too many distinct colours");
      const bool glass = glass_like(c);
      Material m = glass ? Material::coated("glass", Rgb(0.015f, 0.02f, 0.025f), 0.03f, 0.06f)
                         : Material::coated("colour_" + std::to_string(slot_of.size()), c, 0.45f, 0.04f);
      a.slots.push_back(m);
      area.push_back(0);
      it = slot_of.emplace(key, uint16_t(a.slots.size() - 1)).first;
    }
    const int base = int(a.mesh.positions.size());
    for (int k = 0; k < 3; ++k) a.mesh.positions.push_back(rot * soup.corners[3 * t + size_t(k)]);
    a.mesh.triangles.emplace_back(base, base + 1, base + 2);
    a.mesh.material.push_back(it->second);
    const auto& p = a.mesh.positions;
    area[it->second] += 0.5f * (p[size_t(base + 1)] - p[size_t(base)]).cross(p[size_t(base + 2)] - p[size_t(base)]).norm();
  }
  // The paint: the named material's triangles, else the body colour found by colour.
  std::vector<bool> is_paint(a.slots.size(), false);
  if (o.paint_material) {
    bool found = false;
    for (size_t t = 0; t < soup.material.size(); ++t)
      if (soup.material[t] == *o.paint_material) found = is_paint[a.mesh.material[t]] = true;
    if (!found) fail(file, "no material named '" + *o.paint_material + "' for the paint");
  } else {
    is_paint = find_paint(a.slots, area);
  }
  // All paint triangles share one slot, its colour their area-weighted mean.
  Rgb mean = Rgb::Zero();
  float paint_area = 0;
  for (size_t s = 0; s < a.slots.size(); ++s)
    if (is_paint[s]) {
      mean += a.slots[s].albedo * area[s];
      paint_area += area[s];
    }
  a.paint_slot = -1;
  if (paint_area > 0) {
    a.slots.push_back(Material::coated("paint", mean / paint_area, 0.18f, 0.05f));
    a.paint_slot = int(a.slots.size() - 1);
    for (auto& m : a.mesh.material)
      if (is_paint[m]) m = uint16_t(a.paint_slot);
  }
  const Eigen::AlignedBox3f b = a.mesh.bounds();
  if (b.isEmpty() || !b.sizes().allFinite()) fail(file, "the mesh has no extent");
  a.fit_to(o.size_lwh.value_or(b.sizes()));
  return a;
}

}  // namespace chatsim::render
