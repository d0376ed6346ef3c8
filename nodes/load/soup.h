#pragma once
// The triangle soup between triangulation and the Mesh: triangles over positions, each knowing
// its vertex and face numbers in the file, for the repairs and the messages.

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <array>
#include <string>
#include <vector>

namespace papercraft::load_internal {

using OpenMesh::Vec2d;
using OpenMesh::Vec3d;
/// A triangle's corners, indices into Soup::positions.
using Triangle3 = std::array<int, 3>;

/// Triangles with their source vertex and face numbers and, when the file has them, corner UVs.
struct Soup {
  std::vector<Vec3d> positions;
  std::vector<int> source_vertex;  // index in the file's vertex list
  std::vector<Triangle3> triangles;
  std::vector<int> source_face;                 // index in the file's face list
  std::vector<std::array<Vec2d, 3>> corner_uv;  // empty without UVs
};

/// The cross product a x b.
inline Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return OpenMesh::cross(a, b);
}

/// The corner (0, 1 or 2) of `t` at `vertex`; 2 when `vertex` is none of them.
inline int corner_of(const Triangle3& t, int vertex) {
  return t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2);
}

/// "12, 40, 41": the file's vertex numbers of a triangle's corners, for messages.
inline std::string vertex_list(const std::vector<int>& source_vertex, const Triangle3& t) {
  return std::to_string(source_vertex[t[0]]) + ", " + std::to_string(source_vertex[t[1]]) + ", " +
         std::to_string(source_vertex[t[2]]);
}

}  // namespace papercraft::load_internal
