#pragma once
// A plain indexed triangle mesh: the exchange format of the geometric kernels (BVH,
// Hausdorff, unfolding). Parts being refined live in the OpenMesh `Mesh` (core/mesh.h).

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace papercraft {

using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
using Triangle = std::array<int, 3>;

/// Vertices #V, triangles #F of indices into vertices (counter-clockwise seen from outside).
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;

  bool empty() const { return triangles.empty(); }
};

/// Sum of triangle areas.
double surface_area(const TriangleMesh& mesh);

/// Axis-aligned bounding box of the vertices; returns {min, max}. \pre not empty.
std::array<Vec3, 2> bounding_box(const std::vector<Vec3>& points);

}  // namespace papercraft
