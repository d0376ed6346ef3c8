#pragma once
// The boundary edges of a flat strip's triangles, shared by `unfold` and `merge`.

#include <vector>

#include "core/strip.h"

namespace papercraft {

/// Boundary edges of a set of triangles: every directed edge (v0, v1) of a triangle whose
/// reverse (v1, v0) belongs to no triangle, so the triangles lie on its left when they are
/// counter-clockwise. Edges come chained into loops (each edge's v1 is the next one's v0),
/// the loops in order of their smallest edge; kind Cut, no neighbour, no label.
///
/// `triangles` #F by 3 vertex indices (any non-negative values).
/// Known limit: at a vertex where the boundary touches itself (two outgoing boundary edges)
/// the loop follows the first unused edge, so such a loop may be split differently.
std::vector<BoundaryEdge> flat_boundary(const std::vector<Triangle>& triangles);

}  // namespace papercraft
