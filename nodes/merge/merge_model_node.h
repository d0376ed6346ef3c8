#pragma once
// One merge of a whole model's unfolded strips, as the merge node runs it: the triangles
// printed twice dropped, congruent boundaries merged, crumbs and narrow pieces joined in the
// plane.

#include <cstddef>
#include <memory>
#include <vector>

#include "core/piece_limits.h"
#include "graph/messages.h"
#include "nodes/merge/congruent.h"

namespace papercraft {

/// A merge of a whole model and what it left.
struct Merged {
  ModelStrips strips;
  std::vector<int> small;  // ids of the flat strips left under min_area
  std::size_t twice = 0;   // triangles printed twice, dropped
};

/// collect_model_strips, drop_double_covered_triangles, merge_congruent and
/// join_small_and_narrow_strips at the model's piece limits (model units).
/// \throws InvalidInputException as merge_congruent.
Merged merge_model(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded,
                   const MergeOptions& options, const PieceLimits& limits);

}  // namespace papercraft
