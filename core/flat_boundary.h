#pragma once
// The boundary edges and the orientation of a flat strip's triangles, shared by `unfold`,
// `merge` and `layout`.

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

/// The most a weld (points that lie together on paper snapped into one) may move a flat edge
/// off its 3D length, as a share of it: a seam's two sides are checked equal to 1e-9.
inline constexpr double kWeldLengthTolerance = 1e-10;

/// Whether moving a flat strip's points from `before` to `after` (both indexed like
/// `points3d`) keeps every edge of each triangle that moves at its 3D length, to
/// kWeldLengthTolerance of it (or as close as it was before). A weld snaps points that lie
/// within rounding of each other, and the gap between them goes into the edges beside them:
/// on a short edge that is more than a seam's sides may differ by. Triangles that `after`
/// leaves with two corners on one point (the weld drops them) are not asked.
bool weld_keeps_lengths(const std::vector<Vec3>& points3d, const std::vector<Triangle>& triangles,
                        const std::vector<Vec2>& before, const std::vector<Vec2>& after);

/// The area of a flat strip's triangles in the plane (each counted by its absolute value).
double flat_area(const FlatStrip& strip);

/// The area of `triangles` over the plane `points` (each counted by its absolute value).
double flat_area(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles);

/// Round each vertex inside a seam chain that `a` shares with `b` (a vertex of a on two of its
/// seam edges whose neighbour is b's id, and of b on two of its seam edges to a; matched by
/// their exact 3D points, and where a strip holds the point twice, its copy with the least
/// corner), the corners of a's and b's triangles there summed, in degrees: the largest such
/// sum, 0 where the chains have no inner vertex. Over 360, the surface is a saddle there: a
/// hinge over an edge at that vertex lays the two over each other round it, and no union of
/// the two lies flat with the seam closed there. (A hinge over an edge further along the seam
/// may still lie flat: folds_flat_onto tries them.)
double widest_corner_round_a_seam_vertex(const FlatStrip& a, const FlatStrip& b);

/// Whether `a` folded out of `b` over some seam edge it shares with it lies flat beside it:
/// a's edge laid on b's edge with the same two 3D points (exactly), a on the other side, and
/// no triangle of a then overlapping one of b's deeper than `relative` times the mean length of
/// their edges. False where they share no seam edge. What a hinge in the merge tries first (it
/// also asks that the union not overlap other strips it takes).
bool folds_flat_onto(const FlatStrip& a, const FlatStrip& b, double relative = 1e-6);

/// The first triangle that turns clockwise in `points`, i.e. whose cross product is below
/// -`relative` times its longest edge squared, or -1 if none does. Not judged: triangles
/// with a repeated index, and triangles whose longest edge is under 1e-6 of the bounding-box
/// diagonal of `points` (slivers left where cuts met near a vertex: rounding decides their
/// orientation). Scale-invariant.
int first_clockwise_triangle(const std::vector<Vec2>& points,
                             const std::vector<Triangle>& triangles, double relative);

}  // namespace papercraft
