#include "nodes/merge/move_cost.h"

#include <set>

#include "core/flat_boundary.h"
#include "core/seams.h"
#include "nodes/merge/chains.h"

namespace papercraft::merge_detail {

MoveCost::MoveCost(const std::vector<FlatStrip>& strips, const std::vector<int>& touched,
                   const MergeOptions& options, double min_area)
    : options_{.mm_per_unit = options.mm_per_unit,
               .min_area_mm2 = min_area * options.mm_per_unit * options.mm_per_unit,
               .weights = options.weights},
      touched_(touched.size()) {
  const std::set<int> in(touched.begin(), touched.end());
  std::set<int> around;
  for (int s : touched)
    for (int t : strips_beside(strips, s))
      if (!in.count(t)) around.insert(t);
  local_.reserve(touched.size() + around.size());
  for (int s : touched) local_.push_back(strips[s]);
  for (int t : around) local_.push_back(strips[t]);
  for (FlatStrip& strip : local_)
    if (strip.boundary.empty()) strip.boundary = flat_boundary(strip.triangles);
  label_seams(local_);
  std::vector<int> set(touched_);
  for (std::size_t i = 0; i < touched_; ++i) set[i] = static_cast<int>(i);
  before_ = local_effort(local_, set, options_);
}

double MoveCost::gain(const std::vector<const FlatStrip*>& replacements) const {
  std::vector<FlatStrip> local;
  local.reserve(replacements.size() + local_.size() - touched_);
  std::vector<int> set;
  for (const FlatStrip* strip : replacements) {
    set.push_back(static_cast<int>(local.size()));
    local.push_back(*strip);
    if (local.back().boundary.empty()) local.back().boundary = flat_boundary(strip->triangles);
  }
  local.insert(local.end(), local_.begin() + static_cast<std::ptrdiff_t>(touched_), local_.end());
  label_seams(local);
  return before_ - local_effort(local, set, options_);
}

}  // namespace papercraft::merge_detail
