#pragma once
// Packing rectangles onto as few pages as possible: next-fit decreasing height shelves and
// maximal rectangles (the rectangle packing behind pack_rectangles, declared in pages.h).

#include <vector>

#include "nodes/layout/layout_types.h"

namespace papercraft::layout_internal {

/// Where pack_with_spacing put each rectangle (in input order) and how many bins it used.
struct PackResult {
  std::vector<PackedRectangle> placements;
  int pages = 0;
};

/// Packs rectangles (width, height) into bins of bin_width x bin_height with `spacing`
/// between them, by `method` (MaxRects tries several orders and rules and the shelves too).
/// \throws InvalidInputException for a bin without area, a negative spacing, a non-positive
///         size or a rectangle that fits the bin in neither orientation.
PackResult pack_with_spacing(const std::vector<Vec2>& sizes, double bin_width, double bin_height,
                             double spacing, PackingMethod method);

}  // namespace papercraft::layout_internal
