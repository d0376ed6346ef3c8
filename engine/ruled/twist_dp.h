#pragma once
// Twist-minimising triangulated ruled surface (TRS) between two polylines: the `ruled`
// stage's algorithm (paper section 3.2.2; DESIGN.md "Ruled strip").
//
// A correspondence is a monotone path in the (i, j) grid of A's and B's vertices; every
// node (i, j) is a ruling a_i b_j and every step adds one triangle. The path minimises
//   sum over rulings of (1 - <n_a, n_b>) + ruling_length_weight * |a_i - b_j| / diameter,
// with n_a = (a_i - b_j) x d_a / |...|, n_b = (a_i - b_j) x d_b / |...| and d the central
// difference tangent of the polyline at the vertex (one-sided at open ends).
//
// Closed-closed: the starting correspondence is free. Optimal paths for different starts
// can be chosen so that they do not cross, so the path for the middle start is searched
// only between its neighbours' paths (Maes 1990, "On a cyclic string-to-string correction
// problem"; the usual contour-tiling divide and conquer): O(n m log min(n, m)) time.

#include <cstddef>

#include "core/strip.h"

namespace papercraft {

struct TwistOptions {
  /// Weight of the ruling length (divided by the bounding-box diagonal of both polylines)
  /// added to every ruling's twist. Breaks the exact ties of planar or cylindrical input
  /// (where every correspondence has zero twist) in favour of short rulings; small enough
  /// not to override a real twist difference. 0 gives the paper's objective exactly.
  double ruling_length_weight = 1e-4;
  /// Closed-closed only: also match B traversed backwards and keep the cheaper strip (the
  /// two boundary loops of a part come in opposite orientations).
  bool try_reversed_b = true;
  /// Closed-closed only: match B only as given (+1) or only backwards (-1), whatever the
  /// cost; 0 leaves the choice to try_reversed_b. Only one of the two makes a strip that
  /// faces one way all over, as the part between two of its boundary loops does: the caller
  /// who knows the part picks it (build_strip, engine/refine/refine.h).
  int b_direction = 0;
  /// Closed-closed only: when the optimum is a double fan (see below), the best path that is
  /// not one is searched for every start if (n + 1)(m + 1) min(n, m) is at most this (exact),
  /// else by the divide and conquer (not proven optimal for this restricted problem).
  std::size_t max_each_start_work = std::size_t{1} << 23;
};

/// The twist-minimising strip between polylines `a` and `b`.
///
/// Cases: open-open (a_0 is matched to b_0 and the last points to each other; n + m - 2
/// triangles); closed-closed (free start, B in both directions unless disabled; n + m
/// triangles); a single point against a polyline (a fan: n - 1 triangles, n if closed;
/// twist_cost 0, a cone being developable); point-point (one degenerate triangle
/// (a, b, b), twist_cost 0).
///
/// Result: vertices are A's points then B's points, both in the order given (also when B
/// was matched backwards); uvs are copied when both polylines have them. The strip is
/// consistently oriented with A's edges appearing as (a_{i+1}, a_i), so when A is a
/// boundary loop of a part (part on the right, core/mesh.h boundary_loops) the strip's
/// normals agree with the part's. twist_cost is the sum of (1 - <n_a, n_b>) alone; a
/// ruling whose normal is undefined (the ruling is parallel to a tangent, has zero length,
/// or a tangent vanishes) counts 1, as if the normals were orthogonal.
///
/// \pre Each polyline has at least one point; a closed one at least 3; `uvs` is empty or
///      has one entry per point; all coordinates are finite.
/// \throws InvalidInputException if a precondition fails or one polyline is closed and the
///         other open (neither being a single point).
/// Closed-closed strips exclude "double fans" (a full turn of one polyline against a single
/// vertex of the other: the path has at most 3 straight runs and uses one ruling twice, so
/// the strip would be non-manifold); the result is the best correspondence without one.
/// Known limits: O(n m) memory (one byte per searched cell, a cost table of up to 2^25
/// cells); above 2^22 cells the table holds floats, so the path is optimal for costs
/// rounded to ~1e-7. Non-generic input (collinear points, an apex on the polyline) can give
/// zero-area triangles.
RuledStrip twist_minimizing_strip(const Polyline& a, const Polyline& b,
                                  const TwistOptions& options = {});

}  // namespace papercraft
