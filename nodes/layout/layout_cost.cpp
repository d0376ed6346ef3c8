// LayoutCost and compare_layouts: the one judgement between two ways of laying out a model.
#include "nodes/layout/layout_cost.h"

#include <numeric>

namespace papercraft::layout_internal {

Verdict compare_layouts(const LayoutCost& candidate, const LayoutCost& incumbent,
                        int splits_per_page) {
  if (candidate.overflowing != incumbent.overflowing)
    return candidate.overflowing < incumbent.overflowing ? Verdict::Better : Verdict::Worse;
  const long saved = static_cast<long>(incumbent.pages) - candidate.pages;
  if (saved <= 0) return Verdict::Worse;
  const long added = static_cast<long>(candidate.pieces) - incumbent.pieces;
  return added <= splits_per_page * saved ? Verdict::Better : Verdict::TooCostly;
}

LayoutCost layout_cost(const PatternLayout& layout, int overflowing) {
  LayoutCost cost;
  cost.pages = static_cast<int>(layout.pages.size());
  cost.overflowing = overflowing;
  for (const Page& page : layout.pages) cost.pieces += static_cast<int>(page.pieces.size());
  const auto& fill = layout.stats.page_fill;
  if (!fill.empty()) cost.fill = std::accumulate(fill.begin(), fill.end(), 0.0) / fill.size();
  return cost;
}

}  // namespace papercraft::layout_internal
