#pragma once
// Triangle meshes with a material slot per triangle, and the shapes everything else is built
// from (boxes, cylinders, spheres, extruded profiles).
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

namespace chatsim::render {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;     // per vertex; empty: flat shading
  std::vector<Eigen::Vector2f> uvs;         // per vertex; empty: none
  std::vector<Eigen::Vector3i> triangles;
  std::vector<uint16_t> material;           // per triangle: a slot of the owner's material list

  size_t triangle_count() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }
  // Appends another mesh, transformed (normals by the rotation part).
  void append(const TriangleMesh& other, const Eigen::Affine3f& transform = Eigen::Affine3f::Identity());
  void transform(const Eigen::Affine3f& transform);
  void set_material(uint16_t slot);
  Eigen::AlignedBox3f bounds() const;
  // Per-vertex normals averaged from faces meeting at a vertex (only for shared vertices).
  void compute_smooth_normals();
};

// An axis-aligned box centred at the origin, flat faces; uv per face in metres.
TriangleMesh make_box(const Eigen::Vector3f& size, uint16_t material = 0);
// A cylinder along +y centred at the origin, with caps; smooth sides.
TriangleMesh make_cylinder(float radius, float length, int segments, uint16_t material = 0, bool caps = true);
// A cone frustum along +z from z = 0 (radius r0) to z = height (radius r1).
TriangleMesh make_frustum(float r0, float r1, float height, int segments, uint16_t material = 0);
// A smooth sphere (latitude-longitude) centred at the origin.
TriangleMesh make_sphere(float radius, int rings, int segments, uint16_t material = 0);
// A quad in the z = 0 plane spanning [x0, x1] x [y0, y1], facing +z, uv = (x, y) in metres.
TriangleMesh make_quad(float x0, float y0, float x1, float y1, uint16_t material = 0);
// A closed prism: a convex or concave simple polygon in the x-z plane (counter-clockwise seen
// from +y... either order works) extruded from y = -width/2 to +width/2.
TriangleMesh make_extrusion(const std::vector<Eigen::Vector2f>& profile_xz, float width, uint16_t material = 0);

}  // namespace chatsim::render
