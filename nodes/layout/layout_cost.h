#pragma once
// What a layout costs, and the one place two layouts are compared. The layout is made several
// ways (long thin strips split or not, triangles divided or not); each way is a candidate
// judged against the best so far by compare_layouts alone.

#include "core/pattern.h"

namespace papercraft::layout_internal {

struct LayoutCost {
  int pages = 0;
  /// Pieces larger than the printable area: each overflows a page of its own.
  int overflowing = 0;
  /// Pieces printed of the model (joining strips apart): a split adds pieces.
  int pieces = 0;
  /// Mean fill of the pages (LayoutStats::page_fill); reported, not compared (a tie keeps
  /// the incumbent).
  double fill = 0.0;
};

enum class Verdict {
  Better,     // the candidate replaces the incumbent
  Worse,      // the incumbent stays
  TooCostly,  // the incumbent stays: the candidate saves pages, but too many pieces for them
};

/// Fewer overflowing pieces wins outright (more loses). At as many, the candidate is Better
/// where it saves pages and adds at most `splits_per_page` pieces for each page it saves,
/// TooCostly where it saves pages at a higher price, else Worse.
/// \pre splits_per_page >= 1.
Verdict compare_layouts(const LayoutCost& candidate, const LayoutCost& incumbent,
                        int splits_per_page);

/// The cost of `layout` with `overflowing` pieces larger than the printable area.
LayoutCost layout_cost(const PatternLayout& layout, int overflowing);

}  // namespace papercraft::layout_internal
