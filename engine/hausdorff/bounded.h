#pragma once
// Certified two-sided Hausdorff distance between triangle meshes (DESIGN.md, "Certified
// Hausdorff"): branch and bound over triangle pieces of both surfaces.
//
// Per piece T of a source surface, with corner distances d_i to the target surface B:
//   lower(T) = max_i d_i (exact point-to-surface distances);
//   upper(T) >= max_{x in T} d(x, B), the least of a cascade (cheapest first):
//     - all corners have the same nearest triangle t: d(., t) is convex, so max_i d_i is exact;
//     - Lipschitz: d(., B) is 1-Lipschitz; on the Voronoi region R_i of corner i inside T,
//       d(x, B) <= d_i + max_{y in R_i} |y - v_i| (circumradius-type radius);
//     - convexity over candidate triangles t in {t_0, t_1, t_2} (Tang et al. 2009), whole
//       piece and then per Voronoi region: d(x, B) <= max over the region's vertices of d(., t);
//     - projection, for a large piece over a finer target (the strip -> part direction): when
//       the target triangles near T form a consistently oriented patch facing T whose
//       boundary does not project onto T, T lies in the patch's projection along its normal
//       and the distance along the normal to each patch triangle, affine on each cell, bounds
//       d(x, B) (see bounded.cpp for the argument).
// Pieces whose upper bound is undecided are split (longest-edge bisection or 4-way midpoint
// split), largest upper bound first. A decision rejects as soon as a lower bound exceeds
// tau and accepts when every upper bound is <= tau; on reject it goes on refining until the
// maximum is located to within precision * tau (the witness drives the cut stage).
// Related: CGAL::Polygon_mesh_processing::bounded_error_Hausdorff_distance; Sacht and
// Jacobson 2024 (cascading upper bounds).
//
// Guarantees hold up to floating-point rounding of the distance computations (relative
// errors of order 1e-15 of the coordinates).

#include <cstddef>

#include "core/bvh.h"
#include "core/triangle_mesh.h"

namespace papercraft {

enum class PieceSplit {
  /// Split the longest edge at its midpoint: one new distance query per split; adapts to
  /// long thin triangles (the rulings of a strip).
  longest_edge,
  /// 4-way midpoint subdivision: three new queries, four similar children.
  midpoints,
};

struct BoundedHausdorffOptions {
  /// On reject, the witness distance is within precision * tau of the maximum.
  double precision = 0.05;
  /// On reject, keep refining to locate the maximum (false: return at the first point
  /// farther than tau; its distance is still a valid lower bound).
  bool locate_maximum = true;
  PieceSplit split = PieceSplit::longest_edge;
  /// Caps so that a pathological input cannot run away; when one trips before the
  /// question is settled, the result has certified == false.
  std::size_t max_evaluations = 20'000'000;  // exact point-to-surface distance queries
  int max_depth = 60;                        // splits of one input triangle
  /// Pieces processed per round (in parallel). Results do not depend on the thread count.
  std::size_t batch_size = 64;
};

/// A point of one surface far from the other.
struct HausdorffWitness {
  Vec3 point = Vec3::Zero();
  /// 0: point lies on mesh a (far from b); 1: point lies on mesh b (far from a).
  int side = 0;
  /// Triangle of that mesh containing `point`.
  int triangle = -1;
  /// The exact distance of `point` to the other surface (a lower bound of H).
  double distance_lower_bound = 0.0;
};

struct HausdorffResult {
  /// Decision: H(a, b) <= tau proven. Value mode: the requested error bound was reached.
  bool within = false;
  /// lower <= H(a, b) <= upper.
  double lower = 0.0;
  double upper = 0.0;
  /// The point attaining `lower` (a point of maximal error once located).
  HausdorffWitness witness;
  /// False when a cap (max_evaluations, max_depth) tripped before the question was settled,
  /// or for the sampled (uncertified) baseline.
  bool certified = true;
  /// Exact point-to-surface distance queries made.
  std::size_t evaluations = 0;
};

/// Decides whether the two-sided Hausdorff distance H(a, b) = max(h(a, b), h(b, a)), with
/// h(a, b) = max_{x in a} min_{y in b} |x - y| over the triangles (not just vertices), is at
/// most tau.
/// Returns within == true with upper <= tau (a certified bound), or within == false with
/// lower > tau and the witness; when options.locate_maximum also upper - lower <=
/// precision * tau (witness within precision * tau of the maximum). When a cap trips first:
/// within == false, certified == false.
/// \pre a and b have at least one triangle, valid indices, finite coordinates; tau > 0;
/// precision > 0. \throws InvalidInputException otherwise.
HausdorffResult certified_hausdorff_within(const TriangleMesh& a, const TriangleMesh& b, double tau,
                                           const BoundedHausdorffOptions& options = {});

/// certified_hausdorff_within over prebuilt trees (reuse one tree for many candidates).
HausdorffResult certified_hausdorff_within(const TriangleBvh& a, const TriangleBvh& b, double tau,
                                           const BoundedHausdorffOptions& options = {});

/// Two-sided Hausdorff distance with lower <= H <= upper and upper - lower <= error_bound
/// (within == certified == true), unless a cap trips (both false). options.precision and
/// locate_maximum are ignored.
/// \pre as certified_hausdorff_within, error_bound > 0. \throws InvalidInputException.
HausdorffResult certified_hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                             double error_bound,
                                             const BoundedHausdorffOptions& options = {});
HausdorffResult certified_hausdorff_distance(const TriangleBvh& a, const TriangleBvh& b,
                                             double error_bound,
                                             const BoundedHausdorffOptions& options = {});

/// One-sided variants: h(a, b) = max_{x in a} d(x, b) only (witnesses have side 0). Only the
/// target needs a tree (e.g. a part against its whole model's tree).
HausdorffResult certified_one_sided_hausdorff_within(const TriangleMesh& a, const TriangleBvh& b,
                                                     double tau,
                                                     const BoundedHausdorffOptions& options = {});
HausdorffResult certified_one_sided_hausdorff_distance(const TriangleMesh& a, const TriangleBvh& b,
                                                       double error_bound,
                                                       const BoundedHausdorffOptions& options = {});

}  // namespace papercraft
