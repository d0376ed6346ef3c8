#pragma once
// What a move changes in what the pieces cost a person: the gain by which the merge chooses
// among the hinges that lay a piece flat, decides whether a legal but modest piece is worth
// hinging at all, and whether handing a triangle across a seam pays (local_effort,
// core/piece_effort.h). A hinge in the middle of a shared chain opens a slit on both sides of it;
// one too thin for a glue flap costs a joining strip, and a short one two or three sawtooth
// corners, so the piece saved is weighed against them.

#include <vector>

#include "core/piece_effort.h"
#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// The gain of replacing strips[touched] by other strips over the same triangles (a union, or
/// two pieces with a triangle moved between them): local_effort of the touched strips and of the
/// strips beside them (whose seams with them count too) less that with the replacements in their
/// place. Positive: the move pays. Built once per set of touched strips, asked for each
/// replacement tried.
/// \pre options.mm_per_unit > 0; strip ids distinct, replacements' ids distinct from the
///      untouched strips'.
class MoveCost {
 public:
  /// `min_area` (model units squared): a piece under it counts as small (0: not counted).
  MoveCost(const std::vector<FlatStrip>& strips, const std::vector<int>& touched,
           const MergeOptions& options, double min_area);
  /// Replacements' boundaries are found where empty.
  double gain(const std::vector<const FlatStrip*>& replacements) const;
  /// The gain of a hinge: `joined` in place of the (two) touched strips.
  double gain(const FlatStrip& joined) const { return gain(std::vector<const FlatStrip*>{&joined}); }

 private:
  PieceEffortOptions options_;
  std::vector<FlatStrip> local_;  // the touched strips, then the strips beside them
  std::size_t touched_ = 0;
  double before_ = 0.0;
};

}  // namespace papercraft::merge_detail
