#pragma once
// Where the refinement cuts a rejected part (the engine's cut step, refine.h):
//   1. on parts of up to `search_max_faces` faces, the maximal-strip search (the largest
//      piece next to a boundary that one strip covers, if it is at least
//      `search_min_fraction` of the part);
//   2. else through the hole the decision named, or through the worst point (paper 3.2.2);
//   3. if nothing splits the part, any certified strip next to a boundary, however thin.
// With piece limits, every one of these keeps the pieces a person can cut and glue where it can.
// Crossings within `snap_tolerance`·tolerance of a vertex snap to it.

#include <vector>

#include "core/mesh.h"
#include "engine/cut/through_witness.h"
#include "engine/refine/decide.h"
#include "engine/ruled/twist_dp.h"

namespace papercraft {

struct RejectedCutOptions {
  RejectedCutOptions() { cut.harmonic.clamp_negative_weights = true; }
  WitnessCutOptions cut;
  int search_steps = 4;
  long search_max_faces = 4000;
  double search_min_fraction = 0.1;
  double snap_tolerance = 0.01;
};

/// Cuts a part whose strip between `first` and `second` (vertex indices, as in
/// harmonic_field) was rejected at `tolerance`, with its worst point at `witness`, or, when
/// `hole` is non-null, because of that unused boundary loop. Returns no pieces when no cut
/// makes progress. The maximal-strip search builds and decides its probes with `twist` and
/// `decide`, as the refinement does. With `limits`, no cut leaves a piece narrower or smaller
/// than they allow where another iso-value would not (through_witness.h); the search keeps
/// only strips whose pieces meet them. `one_strip`, where given, looks ahead: a piece under
/// twice min_area must be one strip that reaches min_area on paper (cut_shortfall,
/// through_witness.h). `holes`, where given, counts a piece's holes: a cut through `hole` that
/// leaves more of them than the cut through its middle is not taken (cut_through_hole).
WitnessCut cut_rejected_part(const Mesh& part, const std::vector<int>& first, bool first_closed,
                             const std::vector<int>& second, bool second_closed,
                             const std::vector<int>* hole, const Vec3& witness, double tolerance,
                             const RejectedCutOptions& options, const TwistOptions& twist,
                             const DecideOptions& decide, const PieceLimits& limits = {},
                             const OneStrip& one_strip = {}, const HoleCount& holes = {});

}  // namespace papercraft
