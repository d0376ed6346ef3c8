#include "engine/refine/decide.h"

#include "core/bvh.h"

namespace papercraft {

HausdorffResult decide_within(const TriangleMesh& part, const TriangleMesh& strip, double tau,
                              const DecideOptions& options) {
  return options.sampled ? sampled_hausdorff_within(part, strip, tau, options.sampling)
                         : certified_hausdorff_within(part, strip, tau, options.bounded);
}

StripVerdict judge_strip(const Mesh& part, const RuledStrip& strip, int hole_count,
                         double tolerance, const DecideOptions& options) {
  StripVerdict verdict;
  if (hole_count > 0) {
    // Holes are split off regardless of the error (paper 3.2.2): a strip between two
    // boundaries cannot have holes, and measuring it would only locate the largest hole.
    verdict.hole = 0;
    return verdict;
  }
  const TriangleMesh part_mesh = to_triangle_mesh(part);
  if (strip.mesh.empty() ||
      surface_area(strip.mesh) <= kDegenerateStripArea * surface_area(part_mesh)) {
    TriangleBvh bvh(strip.mesh.empty() ? TriangleMesh{{strip.mesh.vertices.front()}, {{0, 0, 0}}}
                                       : strip.mesh);
    for (const Vec3& p : part_mesh.vertices) {
      const double d = bvh.closest(p).distance;
      if (d >= verdict.witness_error) {
        verdict.witness_error = d;
        verdict.witness = p;
        verdict.witness_side = 0;
      }
    }
    return verdict;
  }
  const HausdorffResult result = decide_within(part_mesh, strip.mesh, tolerance, options);
  verdict.certified = result.certified;
  if (!result.within) {
    verdict.witness = result.witness.point;
    verdict.witness_error = result.witness.distance_lower_bound;
    verdict.witness_side = result.witness.side;
    verdict.witness_triangle = result.witness.triangle;
    return verdict;
  }
  verdict.accept = true;
  verdict.upper_bound = result.upper;
  return verdict;
}

}  // namespace papercraft
