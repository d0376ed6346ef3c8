#pragma once
// The mesh type of the pipeline: OpenMesh, double precision, with per-vertex texture
// coordinates and status bits (for deletion/garbage collection during cuts).
//

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

struct MeshTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
  typedef OpenMesh::Vec2d TexCoord2D;
  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::PrevHalfedge);
};

using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

/// Name of the int vertex property mapping a vertex to the input vertex it is (its index in
/// the loaded file), or -1 where a cut created it. Set by the loader, carried by every stage.
inline constexpr const char* kInputVertexProperty = "v:input_vertex";

/// Throws InvalidInputException naming `function` if `mesh` has deleted elements (the
/// algorithms index vertices and faces densely; call garbage_collection() first).
void require_no_deleted_elements(const Mesh& mesh, const char* function);

inline Vec3 to_eigen(const OpenMesh::Vec3d& p) {
  return Vec3(p[0], p[1], p[2]);
}
inline OpenMesh::Vec3d to_openmesh(const Vec3& p) {
  return OpenMesh::Vec3d(p[0], p[1], p[2]);
}

/// Copy of the geometry as an indexed triangle mesh (vertex i = OpenMesh vertex i).
/// \pre mesh has no deleted elements (call garbage_collection() first).
TriangleMesh to_triangle_mesh(const Mesh& mesh);

/// Build an OpenMesh mesh from indexed triangles. Throws TopologyException if a triangle
/// cannot be added without creating a non-manifold configuration.
Mesh to_mesh(const TriangleMesh& mesh);

/// Boundary loops as vertex index sequences, each loop following OpenMesh's boundary
/// halfedges (h -> next(h)), so the mesh lies on the right of each step (its faces are
/// counter-clockwise). Sorted by descending loop length.
std::vector<std::vector<int>> boundary_loops(const Mesh& mesh);

/// V - E + F.
int euler_characteristic(const Mesh& mesh);

/// Number of connected components (through edges).
int connected_components(const Mesh& mesh);

/// Sum of face areas.
double surface_area(const Mesh& mesh);

}  // namespace papercraft
