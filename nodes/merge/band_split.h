#pragma once
// A band no hinge takes whole, cut across its inner edges into two to four parts, each hinged
// onto a neighbour (join_narrow_strips' cut, join_small_strips' third try).

#include <functional>
#include <vector>

#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// Whether the union of strips[neighbour] (its index in the strips given) and the parts of a
/// band it took is wide enough to keep.
using KeepsWide = std::function<bool(int neighbour, const FlatStrip& joined)>;

/// A band no hinge takes whole (its neighbours' edges bend where it is straight in the plane:
/// any hinge lays the rest of it over the neighbour), cut in two across one of its inner edges
/// and each half hinged onto a neighbour, the halves folding onto different edges. Cuts are
/// tried the most even first (at most 48, evenly spread over the rest), each half's
/// shared edges the longest first (at most 12 with each neighbour): a half is kept on a
/// hinge that gives a union `keeps_wide` accepts (given the neighbour's index in `strips` and the
/// union, which may hold the other half too), of those the one leaving the least slit. Kept only
/// when both halves find a place; then the band is erased from `strips` and the neighbours that
/// took a half are replaced by the unions, their indices (after the erase) going to `changed`.
/// Where no cut places both halves and `cuts_after` > 0, a half that finds a place is kept and the
/// other half cut in two again, with one cut fewer after it (a band whose neighbours turn more than
/// once along it: into at most options.most_band_pieces, as a wall round a square hole is cut at
/// three of its corners into four). Otherwise `strips` is left as it was and false returned.
/// A band of fewer than 2 or more than 2,048 triangles is not cut.
bool hinge_in_two(std::vector<FlatStrip>& strips, int band, double min_width,
                  const MergeOptions& options, const KeepsWide& keeps_wide,
                  std::vector<int>& changed, int cuts_after = -1);

}  // namespace papercraft::merge_detail
