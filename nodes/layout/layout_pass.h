#pragma once
// One pass of the layout: strips cut into pieces (split to fit the page, and long thin ones
// split as asked), seams paired and labelled, tabs, joining strips, labels arranged, pieces
// oriented, packed (nested by outline, or by rectangles) and placed on pages. layout_pages
// runs passes several ways and keeps the cheapest by compare_layouts (layout_cost.h).

#include <utility>
#include <vector>

#include "core/pattern.h"
#include "core/strip.h"
#include "nodes/layout/annotations.h"
#include "nodes/layout/layout_cost.h"
#include "nodes/layout/layout_types.h"

namespace papercraft::layout_internal {

/// Which long and thin strips a pass splits in parts of half a page (Fitting: those that fit
/// the page; All: every one), or splits where they bend (Bends: every one; a part that still
/// fits no page is then split to fit it).
enum class SplitLong { None, Fitting, All, Bends };

/// The long thin strips a pass found (packing badly: longer than half the page's long side
/// and thin or bent). Only nesting with split_long_strips looks for them.
struct LongStrips {
  int found = 0;     // strips that fit the page but are long and thin
  int oversize = 0;  // strips larger than the page, long and thin
  int split = 0;     // of those split_long covers, those split in more than one part
  std::vector<std::pair<double, int>> waste;  // of each long thin strip: box minus area, index
};

/// The layout of one pass, what it costs and the long thin strips it found.
struct LayoutPass {
  PatternLayout layout;
  LayoutCost cost;
  LongStrips long_strips;
};

/// Lays out `strips`, long and thin strips split as `split_long` says (of them only those
/// `chosen` marks by strip index, where given). `labels`: arranged labels shared between
/// passes (LabelCache). `divided`: the strips' triangles were divided (StripData::divided).
/// \throws InvalidInputException as layout_pages does.
LayoutPass layout_pass(const std::vector<FlatStrip>& strips, const LayoutOptions& options,
                       SplitLong split_long, const std::vector<char>* chosen = nullptr,
                       LabelCache* labels = nullptr, bool divided = false);

}  // namespace papercraft::layout_internal
