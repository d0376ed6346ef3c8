// One merge of a whole model's unfolded strips, every pass in order.
#include "nodes/merge/merge_model_node.h"

#include <utility>

#include "nodes/merge/collect_node.h"

namespace papercraft {

Merged merge_model(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded,
                   const MergeOptions& options, const PieceLimits& limits) {
  Merged merged;
  merged.strips = collect_model_strips(std::move(unfolded));
  merged.strips.flat = drop_double_covered_triangles(std::move(merged.strips.flat), &merged.twice);
  merged.strips.flat = merge_congruent(std::move(merged.strips.flat), options);
  merged.strips.flat = join_small_and_narrow_strips(std::move(merged.strips.flat), limits.min_area,
                                                    limits.min_width, options, &merged.small);
  return merged;
}

}  // namespace papercraft
