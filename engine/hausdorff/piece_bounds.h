#pragma once
// Upper bounds of the distance from a triangle piece of the source to the target surface,
// for certified_hausdorff (bounded.h): from the exact distances at its corners, their nearest
// target triangles and the Voronoi regions of its corners, and, for a piece over a finer
// target patch, by projecting the patch onto the piece's plane.

#include <array>
#include <vector>

#include "core/bvh.h"
#include "core/triangle_mesh.h"

namespace papercraft::hausdorff_internal {

/// A corner of a piece with its exact distance to the target surface.
struct Corner {
  Vec3 point;
  double distance;  // exact distance to the target surface
  int nearest;      // a target triangle at that distance
};

/// Across each edge of the target: face_edge[3 t + k] for edge k (corner k -> k + 1) of
/// triangle t is the one other triangle holding that edge in the opposite direction, when the
/// edge is held by exactly these two (-1: by t alone; -2: any other case). Lets the projection
/// bound check a patch's consistency in linear time.
std::vector<int> edge_neighbours(const TriangleMesh& mesh);

/// An upper bound of max_{x in piece} d(x, target): the cascade of the header comment,
/// stopping at the first bound <= threshold.
/// `neighbours`: edge_neighbours of the target.
double piece_upper_bound(const std::array<Corner, 3>& c, const TriangleBvh& target,
                         const std::vector<int>& neighbours, double threshold);

}  // namespace papercraft::hausdorff_internal
