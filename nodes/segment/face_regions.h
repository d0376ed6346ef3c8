#pragma once
// Internal to the segment stage: the dual graph of a mesh (faces joined across their shared
// edges) and the clean-up every segmentation ends with (each region connected, none smaller
// than a minimum area).

#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// One interior edge of the mesh seen as an arc between its two faces.
struct FaceArc {
  int face_a = -1;
  int face_b = -1;
  int vertex_a = -1;  ///< endpoints of the shared edge
  int vertex_b = -1;
  double length = 0;             ///< of the shared edge
  double angle = 0;              ///< between the two face normals, radians in [0, pi]
  bool concave = false;          ///< the surface folds inwards across the edge
  double centroid_distance = 0;  ///< geodesic between the centroids (b unfolded onto a's plane)
};

struct FaceGraph {
  std::vector<Vec3> centroids;
  std::vector<Vec3> normals;  ///< unit, or zero for a degenerate face
  std::vector<double> areas;
  std::vector<FaceArc> arcs;                ///< one per interior edge, in edge order
  std::vector<std::vector<int>> face_arcs;  ///< arcs at each face
  double total_area = 0;
  double mean_edge_length = 0;  ///< over all edges, boundary ones included

  int other_face(int arc, int face) const {
    return arcs[arc].face_a == face ? arcs[arc].face_b : arcs[arc].face_a;
  }
};

/// The dual graph of `mesh`. \pre mesh has no deleted elements.
FaceGraph face_graph(const Mesh& mesh);

/// Throws InvalidInputException (naming `function`) if mesh has no faces or deleted elements.
void require_segmentable(const Mesh& mesh, const char* function);

/// Turns a face labelling into regions that are connected through edges and, where a
/// neighbour exists, have area >= min_area: of each label's connected pieces the largest keeps
/// the label, the others, and then every region below min_area (smallest first), are merged
/// into the neighbour with which they share the longest boundary (ties: lowest region).
/// A region without neighbours (a whole connected component of the mesh) is kept whatever its
/// area. Faces labelled < 0 are left out (as if absent) and keep the label -1.
/// \return #F labels 0..k-1, numbered in the order of each region's lowest face.
std::vector<int> consolidate_regions(const FaceGraph& graph, const std::vector<int>& labels,
                                     double min_area);

/// Connected components of the faces through arcs, numbered by lowest face.
std::vector<int> face_components(const FaceGraph& graph);

}  // namespace papercraft
