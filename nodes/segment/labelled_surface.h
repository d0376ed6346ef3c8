#pragma once
// Internal to the segment stage: the whole model as one triangle soup over a shared vertex
// array, each triangle labelled with its part. Boundaries are refined on this one surface, so
// a vertex inserted on an edge exists once and both parts beside it use it (bit-identical
// shared boundaries); the parts are cut out only at the end.

#include <vector>

#include "core/mesh.h"

namespace papercraft {

struct LabelledSurface {
  std::vector<OpenMesh::Vec3d> points;
  std::vector<OpenMesh::Vec2d> texcoords;  ///< empty if the model has none
  std::vector<int> input_vertex;           ///< per point; -1 for points made by a refinement
  std::vector<Triangle> triangles;         ///< counter-clockwise like the model's faces
  std::vector<int> origin_face;            ///< model face each triangle lies in
  std::vector<int> labels;                 ///< part of each triangle
};

/// The model's faces with the given labels (#F). input_vertex is the model's "v:input_vertex"
/// property where it has one, else the vertex index. \pre no deleted elements.
LabelledSurface labelled_surface(const Mesh& mesh, const std::vector<int>& face_labels);

/// The parts: for each label, the connected components (through edges) of its triangles, each
/// a Mesh with compact indices, vertices in the surface's point order; a vertex where one part
/// touches itself only at that vertex is duplicated, so every part is a 2-manifold. Carries
/// texture coordinates and "v:input_vertex". Ordered by label, then by lowest origin face.
/// \throws TopologyException if a part cannot be built without a non-manifold edge.
std::vector<Mesh> parts_of(const LabelledSurface& surface);

}  // namespace papercraft
