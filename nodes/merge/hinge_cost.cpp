#include "nodes/merge/hinge_cost.h"

#include <set>

#include "core/flat_boundary.h"
#include "core/seams.h"
#include "nodes/merge/chains.h"

namespace papercraft::merge_detail {

HingeCost::HingeCost(const std::vector<FlatStrip>& strips, int x, int y,
                     const MergeOptions& options, double min_area)
    : options_{.mm_per_unit = options.mm_per_unit,
               .min_area_mm2 = min_area * options.mm_per_unit * options.mm_per_unit,
               .weights = options.weights} {
  std::set<int> around;
  for (int s : {x, y})
    for (int t : strips_beside(strips, s))
      if (t != x && t != y) around.insert(t);
  local_.reserve(around.size() + 2);
  local_.push_back(strips[x]);
  local_.push_back(strips[y]);
  for (int t : around) local_.push_back(strips[t]);
  for (FlatStrip& strip : local_)
    if (strip.boundary.empty()) strip.boundary = flat_boundary(strip.triangles);
  label_seams(local_);
  before_ = local_effort(local_, {0, 1}, options_);
}

double HingeCost::gain(const FlatStrip& joined) const {
  std::vector<FlatStrip> local;
  local.reserve(local_.size() - 1);
  local.push_back(joined);
  if (local.back().boundary.empty()) local.back().boundary = flat_boundary(joined.triangles);
  local.insert(local.end(), local_.begin() + 2, local_.end());
  label_seams(local);
  return before_ - local_effort(local, {0}, options_);
}

}  // namespace papercraft::merge_detail
