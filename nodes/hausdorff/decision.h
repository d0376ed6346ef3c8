#pragma once
// What the hausdorff node adapters share: turning a decision about (part, strip) into an
// accept or a reject with a witness, including the paper's rules that are not about the
// error (a degenerate strip is never accepted; a part with holes is always split).

#include <functional>

#include "core/mesh.h"
#include "core/strip.h"
#include "nodes/hausdorff/bounded.h"

namespace papercraft {

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

/// Decides one strip. `decide(part, strip, tau)` is the implementation's decision.
StripVerdict judge_strip(
    const Mesh& part, const RuledStrip& strip, int hole_count, double tolerance,
    const std::function<HausdorffResult(const TriangleMesh&, const TriangleMesh&, double)>& decide);

}  // namespace papercraft
