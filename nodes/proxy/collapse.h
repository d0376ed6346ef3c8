#pragma once
// Edge-collapse decimation of an indexed triangle mesh, in passes of independent collapses.
//
// Each pass gathers every interior edge whose halfedge collapse (one end moves onto the other,
// which keeps its position) stays under the error bound, sorts them by that error and collapses
// them in order, skipping any with an end in the one-ring of the removed vertex of an earlier
// collapse of the same pass; the stars of the ends of a collapse are therefore unchanged since
// the pass began, so its checks read the pass's adjacency exactly. Passes repeat until one collapses nothing. There is
// no priority queue to keep up: a pass is a sort and a sweep, O(F log F), and the mesh shrinks
// from pass to pass, so the whole costs a few passes over the input (Garland and Heckbert 1997
// for the error; the pass structure is that of meshoptimizer's simplifier).
//
// The error of a collapse is the area-weighted mean squared distance of the kept position to the
// planes of the input faces merged into its two ends (Garland-Heckbert quadrics divided by the
// area they gather, a squared length). A collapse is made only when
// - that error is at most bound^2;
// - the removed vertex is not on a boundary or a non-manifold edge (those vertices stay);
// - the edge has two triangles and the ends share no neighbour but those triangles' third
//   vertices (the link condition, Dey et al. 1999: the topology stays);
// - no remaining triangle of the removed vertex turns by more than max_normal_deviation_deg or
//   becomes degenerate.
// The result is deterministic (ties break by vertex index) and independent of threads.

#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

struct CollapseDecimation {
  TriangleMesh mesh;               // kept vertices (compacted) and the remaining triangles
  std::vector<int> source_vertex;  // kept vertex i is input vertex source_vertex[i]
  int passes = 0;
  std::size_t collapses = 0;
};

/// Decimates `input` as described above. \pre every triangle has three distinct vertex indices
/// into input.vertices; bound >= 0.
CollapseDecimation collapse_decimation(const TriangleMesh& input, double bound,
                                       double max_normal_deviation_deg = 60.0);

}  // namespace papercraft
