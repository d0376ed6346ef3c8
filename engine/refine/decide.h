#pragma once
// Step 3 of the refinement: is the strip within the tolerance of its part? The paper's rules
// that are not about the error come first (a part with holes is always split; a degenerate
// strip is never accepted), then the configured decision: the certified branch and bound of
// hausdorff.bounded or the sampled estimate of hausdorff.sampled.

#include "core/mesh.h"
#include "core/strip.h"
#include "engine/hausdorff/bounded.h"
#include "engine/hausdorff/sampled.h"

namespace papercraft {

struct DecideOptions {
  /// Metro-like sampling (uncertified: hausdorff.sampled) instead of the certified bound.
  bool sampled = false;
  BoundedHausdorffOptions bounded;
  SampledHausdorffOptions sampling;
};

/// "H(part, strip) <= tau?" by the configured method.
HausdorffResult decide_within(const TriangleMesh& part, const TriangleMesh& strip, double tau,
                              const DecideOptions& options);

struct StripVerdict {
  bool accept = false;
  double upper_bound = 0.0;  // on accept
  bool certified = true;
  Vec3 witness = Vec3::Zero();  // on reject by error
  double witness_error = 0.0;
  int witness_side = 0;       // 0: the witness lies on the part, 1: on the strip
  int witness_triangle = -1;  // triangle of that surface containing the witness
  int hole = -1;              // on reject because the part has a hole (index into the holes list)
};

/// Strips with less area than this fraction of their part's area are degenerate (a segment
/// between two points): they are rejected with the part's farthest vertex as witness.
inline constexpr double kDegenerateStripArea = 1e-9;

/// Decides one strip of a part with `hole_count` unused boundary loops.
StripVerdict judge_strip(const Mesh& part, const RuledStrip& strip, int hole_count,
                         double tolerance, const DecideOptions& options);

}  // namespace papercraft
