#pragma once
// Measures of a join that decide between hinges: how much of the seam it leaves is a slit, and
// how narrow the neighbour was and the union is.

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "core/piece_width.h"
#include "core/strip.h"

namespace papercraft::merge_detail {

/// How much of the seam a hinge leaves between the two strips `merged` joined is a slit: the
/// number of points it took from the second strip (at `first_added` and after) that lie closer
/// than `width` in the plane to a point of the first with the same 3D point. A band folded
/// out beside the edge it shares runs along it with a thin wedge between them, too narrow for
/// a tab over its length; one that leaves the edge at an angle opens at once.
int slit_points(const FlatStrip& merged, std::size_t first_added, double width);

/// How narrow strips[neighbour] was and `joined` (it with triangles appended, its own in
/// place: a union keeps the first strip's frame) is: the shares narrower than `min_width`,
/// both on the neighbour's raster (narrow_raster; `rasters` keeps them by index into `strips`,
/// once measured). The union differs from the neighbour only within min_width of what it took,
/// so only that box is rastered again: the share is exactly the one the whole union has on
/// that grid.
std::pair<double, double> shares_before_and_joined(const std::vector<FlatStrip>& strips,
                                                   int neighbour, const FlatStrip& joined,
                                                   double min_width,
                                                   std::map<int, NarrowRaster>& rasters);

}  // namespace papercraft::merge_detail
