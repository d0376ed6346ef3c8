#pragma once
// A triangle soup over one shared vertex array, each triangle labelled with the piece it
// belongs to, and the manifold meshes cut out of it. A cut along an iso-line and a
// segmentation both refine one surface first, so a vertex inserted on an edge exists once and
// the pieces on both sides use it (bit-identical shared boundaries); the pieces are built
// only at the end.

#include <vector>

#include "core/mesh.h"

namespace papercraft {

struct LabelledSoup {
  std::vector<OpenMesh::Vec3d> points;
  std::vector<OpenMesh::Vec2d> texcoords;  ///< empty, or one per point
  std::vector<int> input_vertex;           ///< empty, or one per point ("v:input_vertex"; -1 new)
  std::vector<Triangle> triangles;         ///< counter-clockwise like the source's faces
  std::vector<int> origin_face;            ///< face of the source mesh each triangle lies in
  std::vector<int> labels;                 ///< piece label of each triangle
};

/// The vertex arrays of `mesh` (points, texture coordinates if it has them, "v:input_vertex"
/// if it has that property) and no triangles. \pre no deleted elements.
LabelledSoup soup_of_vertices(const Mesh& mesh);

/// The pieces: for each label, the connected components (through edges) of its triangles,
/// each a Mesh with compact indices and its vertices in the soup's point order; a point where
/// one piece touches itself only at that point becomes one vertex per fan of triangles, so
/// every piece is a 2-manifold. Texture coordinates and "v:input_vertex" are carried when the
/// soup has them. Ordered by label, then by lowest origin face. The result does not depend on
/// the order of `triangles` within a piece's union, only on the triangles themselves.
/// \throws TopologyException if a piece cannot be built without a non-manifold edge.
std::vector<Mesh> build_pieces(const LabelledSoup& soup);

/// The connected components (through edges) of `mesh`, each a Mesh with compact indices;
/// vertices shared by two fans of faces are duplicated and isolated vertices dropped.
/// Texture coordinates and "v:input_vertex" are carried over. Ordered by lowest face index.
/// \pre mesh has no deleted elements. \throws InvalidInputException if it has.
std::vector<Mesh> split_connected_components(const Mesh& mesh);

}  // namespace papercraft
