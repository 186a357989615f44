#include "render/mesh.hpp"

#include <cmath>
#include <map>

#include "render/sampling.hpp"

namespace chatsim::render {

void TriangleMesh::append(const TriangleMesh& other, const Eigen::Affine3f& xf) {
  const int base = int(positions.size());
  const bool keep_normals = (normals.size() == positions.size()) && (other.normals.size() == other.positions.size());
  const bool keep_uvs = (uvs.size() == positions.size()) && (other.uvs.size() == other.positions.size());
  if (!keep_normals && !positions.empty()) normals.clear();
  if (!keep_uvs && !positions.empty()) uvs.clear();
  const bool first = positions.empty();
  const Eigen::Matrix3f normal_xf = xf.linear().inverse().transpose();
  for (const auto& p : other.positions) positions.push_back(xf * p);
  if (first ? other.normals.size() == other.positions.size() : keep_normals)
    for (const auto& n : other.normals) normals.push_back((normal_xf * n).normalized());
  if (first ? other.uvs.size() == other.positions.size() : keep_uvs) uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (const auto& t : other.triangles) triangles.emplace_back(t.array() + base);
  material.insert(material.end(), other.material.begin(), other.material.end());
}

void TriangleMesh::transform(const Eigen::Affine3f& xf) {
  const Eigen::Matrix3f normal_xf = xf.linear().inverse().transpose();
  for (auto& p : positions) p = xf * p;
  for (auto& n : normals) n = (normal_xf * n).normalized();
}

void TriangleMesh::set_material(uint16_t slot) { material.assign(triangles.size(), slot); }

Eigen::AlignedBox3f TriangleMesh::bounds() const {
  Eigen::AlignedBox3f b;
  for (const auto& p : positions) b.extend(p);
  return b;
}

void TriangleMesh::compute_smooth_normals() {
  normals.assign(positions.size(), Eigen::Vector3f::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3f n = (positions[size_t(t[1])] - positions[size_t(t[0])])
                                  .cross(positions[size_t(t[2])] - positions[size_t(t[0])]);  // area-weighted
    for (int k = 0; k < 3; ++k) normals[size_t(t[k])] += n;
  }
  for (auto& n : normals) n = n.norm() > 0 ? n.normalized() : Eigen::Vector3f::UnitZ();
}

namespace {

// Adds a flat quad (corners counter-clockwise seen from where it faces).
void add_quad(TriangleMesh& m, const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
              const Eigen::Vector3f& d, uint16_t mat) {
  const int base = int(m.positions.size());
  const Eigen::Vector3f n = (b - a).cross(d - a).normalized();
  for (const auto* p : {&a, &b, &c, &d}) {
    m.positions.push_back(*p);
    m.normals.push_back(n);
  }
  const float w = (b - a).norm(), h = (d - a).norm();
  m.uvs.insert(m.uvs.end(), {{0, 0}, {w, 0}, {w, h}, {0, h}});
  m.triangles.emplace_back(base, base + 1, base + 2);
  m.triangles.emplace_back(base, base + 2, base + 3);
  m.material.insert(m.material.end(), {mat, mat});
}

}  // namespace

TriangleMesh make_box(const Eigen::Vector3f& size, uint16_t mat) {
  TriangleMesh m;
  const Eigen::Vector3f h = size / 2;
  auto P = [&](float sx, float sy, float sz) { return Eigen::Vector3f(sx * h.x(), sy * h.y(), sz * h.z()); };
  add_quad(m, P(-1, -1, 1), P(1, -1, 1), P(1, 1, 1), P(-1, 1, 1), mat);      // +z
  add_quad(m, P(-1, 1, -1), P(1, 1, -1), P(1, -1, -1), P(-1, -1, -1), mat);  // -z
  add_quad(m, P(1, -1, -1), P(1, 1, -1), P(1, 1, 1), P(1, -1, 1), mat);      // +x
  add_quad(m, P(-1, 1, -1), P(-1, -1, -1), P(-1, -1, 1), P(-1, 1, 1), mat);  // -x
  add_quad(m, P(1, 1, -1), P(-1, 1, -1), P(-1, 1, 1), P(1, 1, 1), mat);      // +y
  add_quad(m, P(-1, -1, -1), P(1, -1, -1), P(1, -1, 1), P(-1, -1, 1), mat);  // -y
  return m;
}

TriangleMesh make_cylinder(float radius, float length, int segments, uint16_t mat, bool caps) {
  TriangleMesh m;
  const float h = length / 2;
  for (int i = 0; i <= segments; ++i) {
    const float a = 2 * kPi * float(i) / float(segments);
    const Eigen::Vector3f n(std::cos(a), 0, std::sin(a));
    for (float y : {-h, h}) {
      m.positions.emplace_back(radius * n.x(), y, radius * n.z());
      m.normals.push_back(n);
      m.uvs.emplace_back(a * radius, y + h);
    }
  }
  for (int i = 0; i < segments; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    m.triangles.emplace_back(a, c, b);
    m.triangles.emplace_back(b, c, d);
    m.material.insert(m.material.end(), {mat, mat});
  }
  if (caps) {
    for (float side : {-1.0f, 1.0f}) {
      const int centre = int(m.positions.size());
      const Eigen::Vector3f n(0, side, 0);
      m.positions.emplace_back(0, side * h, 0);
      m.normals.push_back(n);
      m.uvs.emplace_back(0, 0);
      for (int i = 0; i <= segments; ++i) {
        const float a = 2 * kPi * float(i) / float(segments);
        m.positions.emplace_back(radius * std::cos(a), side * h, radius * std::sin(a));
        m.normals.push_back(n);
        m.uvs.emplace_back(radius * std::cos(a), radius * std::sin(a));
      }
      for (int i = 0; i < segments; ++i) {
        if (side > 0) m.triangles.emplace_back(centre, centre + 2 + i, centre + 1 + i);
        else m.triangles.emplace_back(centre, centre + 1 + i, centre + 2 + i);
        m.material.push_back(mat);
      }
    }
  }
  return m;
}

TriangleMesh make_frustum(float r0, float r1, float height, int segments, uint16_t mat) {
  TriangleMesh m;
  const float slope = (r0 - r1) / height;
  for (int i = 0; i <= segments; ++i) {
    const float a = 2 * kPi * float(i) / float(segments);
    const Eigen::Vector3f n = Eigen::Vector3f(std::cos(a), std::sin(a), slope).normalized();
    m.positions.emplace_back(r0 * std::cos(a), r0 * std::sin(a), 0);
    m.positions.emplace_back(r1 * std::cos(a), r1 * std::sin(a), height);
    m.normals.insert(m.normals.end(), {n, n});
    m.uvs.insert(m.uvs.end(), {Eigen::Vector2f(a * r0, 0), Eigen::Vector2f(a * r1, height)});
  }
  for (int i = 0; i < segments; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    m.triangles.emplace_back(a, c, b);
    m.triangles.emplace_back(b, c, d);
    m.material.insert(m.material.end(), {mat, mat});
  }
  return m;
}

TriangleMesh make_sphere(float radius, int rings, int segments, uint16_t mat) {
  TriangleMesh m;
  for (int r = 0; r <= rings; ++r) {
    const float th = kPi * float(r) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      const float ph = 2 * kPi * float(s) / float(segments);
      const Eigen::Vector3f n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      m.positions.push_back(n * radius);
      m.normals.push_back(n);
      m.uvs.emplace_back(ph * radius, th * radius);
    }
  }
  const int row = segments + 1;
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const int a = r * row + s, b = a + 1, c = a + row, d = c + 1;
      if (r > 0) {
        m.triangles.emplace_back(a, c, b);
        m.material.push_back(mat);
      }
      if (r < rings - 1) {
        m.triangles.emplace_back(b, c, d);
        m.material.push_back(mat);
      }
    }
  return m;
}

TriangleMesh make_quad(float x0, float y0, float x1, float y1, uint16_t mat) {
  TriangleMesh m;
  add_quad(m, {x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}, mat);
  for (size_t i = 0; i < 4; ++i) m.uvs[i] = m.positions[i].head<2>();
  return m;
}

namespace {

// Ear clipping of a simple polygon (counter-clockwise); returns index triples.
std::vector<Eigen::Vector3i> triangulate(const std::vector<Eigen::Vector2f>& poly) {
  std::vector<int> idx(poly.size());
  for (size_t i = 0; i < poly.size(); ++i) idx[i] = int(i);
  auto cross = [](const Eigen::Vector2f& o, const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector3i> out;
  int guard = 0;
  while (idx.size() > 3 && guard++ < 10000) {
    bool clipped = false;
    for (size_t i = 0; i < idx.size(); ++i) {
      const int a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i], c = idx[(i + 1) % idx.size()];
      if (cross(poly[size_t(a)], poly[size_t(b)], poly[size_t(c)]) <= 1e-9f) continue;  // reflex
      bool inside = false;
      for (int k : idx) {
        if (k == a || k == b || k == c) continue;
        const auto& p = poly[size_t(k)];
        if (cross(poly[size_t(a)], poly[size_t(b)], p) >= 0 && cross(poly[size_t(b)], poly[size_t(c)], p) >= 0 &&
            cross(poly[size_t(c)], poly[size_t(a)], p) >= 0) {
          inside = true;
          break;
        }
      }
      if (inside) continue;
      out.emplace_back(a, b, c);
      idx.erase(idx.begin() + long(i));
      clipped = true;
      break;
    }
    if (!clipped) break;  // degenerate input: stop rather than loop
  }
  if (idx.size() == 3) out.emplace_back(idx[0], idx[1], idx[2]);
  return out;
}

}  // namespace

TriangleMesh make_extrusion(const std::vector<Eigen::Vector2f>& profile_xz, float width, uint16_t mat) {
  std::vector<Eigen::Vector2f> poly = profile_xz;
  float area = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  if (area < 0) std::reverse(poly.begin(), poly.end());
  TriangleMesh m;
  const float h = width / 2;
  // Side walls: one quad per profile edge, facing outward.
  for (size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    add_quad(m, {b.x(), -h, b.y()}, {a.x(), -h, a.y()}, {a.x(), h, a.y()}, {b.x(), h, b.y()}, mat);
  }
  // Caps: the profile (x, z) at y = +h facing +y and at y = -h facing -y.
  const auto tris = triangulate(poly);
  for (float side : {-1.0f, 1.0f}) {
    const int base = int(m.positions.size());
    for (const auto& p : poly) {
      m.positions.emplace_back(p.x(), side * h, p.y());
      m.normals.emplace_back(0, side, 0);
      m.uvs.emplace_back(p.x(), p.y());
    }
    for (const auto& t : tris) {
      // Counter-clockwise in (x, z) faces -y (x cross z = -y), so +y caps flip the order.
      if (side > 0) m.triangles.emplace_back(base + t[0], base + t[2], base + t[1]);
      else m.triangles.emplace_back(base + t[0], base + t[1], base + t[2]);
      m.material.push_back(mat);
    }
  }
  return m;
}

}  // namespace chatsim::render
