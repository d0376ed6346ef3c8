#pragma once
// What a hinge changes in what the pieces cost a person: the gain by which the merge chooses
// among the hinges that lay a piece flat, and decides whether a legal but modest piece is worth
// hinging at all (local_effort, core/piece_effort.h). A hinge in the middle of a shared chain
// opens a slit on both sides of it; one too thin for a glue flap costs a joining strip, and a
// short one two or three sawtooth corners, so the piece saved is weighed against them.

#include <vector>

#include "core/piece_effort.h"
#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// The gain of hinging strips[x] and strips[y] into one: local_effort of the two and of the
/// strips beside them (whose seams with them count too) less that with the union in their
/// place. Positive: the hinge pays. Built once per pair and asked for each union tried.
/// \pre options.mm_per_unit > 0; strip ids distinct.
class HingeCost {
 public:
  /// `min_area` (model units squared): a piece under it counts as small (0: not counted).
  HingeCost(const std::vector<FlatStrip>& strips, int x, int y, const MergeOptions& options,
            double min_area);
  /// `joined`: the union of strips[x] and strips[y] (its boundary is found where empty).
  double gain(const FlatStrip& joined) const;

 private:
  PieceEffortOptions options_;
  std::vector<FlatStrip> local_;  // x, y, then the strips beside them
  double before_ = 0.0;
};

}  // namespace papercraft::merge_detail
