#pragma once
// A strip hinged whole onto a neighbour over one shared edge (join_small_strips' first try,
// hinge_modest_strips' only one), and the order the passes take strips in.

#include <set>
#include <vector>

#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// Strip `s` hinged whole onto a neighbour over one shared edge, where the union overlaps
/// nowhere: the union replaces the lower index of the two and the other is erased. Edges are
/// tried those at an end of an open shared chain first, then the longest; of the first that
/// lays it flat and the 16 tried after it (kMostWholeHinges), the one leaving the least slit
/// (slit_points at `slit_width`; the earlier on a tie) is kept: a hinge in the middle of a chain
/// that does not weld opens a thin wedge on both sides of it, one at its end only on one.
/// `slit_width` <= 0: the first that lays it flat. With options.mm_per_unit > 0, of the same
/// hinges the one with the largest MoveCost gain (`min_area` the limit a piece is small under),
/// and with `must_gain` only one whose gain is positive. False (strips unchanged) when no hinge
/// lays it flat (or pays).
bool hinge_whole(std::vector<FlatStrip>& strips, int s, const MergeOptions& options,
                 double slit_width, double min_area = 0.0, bool must_gain = false);

/// The index of the smallest strip of less than `bound` whose id is not in `given_up`, or -1.
int smallest_below(const std::vector<FlatStrip>& strips, double bound,
                   const std::set<int>& given_up);

}  // namespace papercraft::merge_detail
