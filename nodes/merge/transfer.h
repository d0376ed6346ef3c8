#pragma once
// Triangles moved from one piece to another: a strip grown from its neighbours' triangles
// (the last try for a crumb or a band no hinge takes). The 3D surface is unchanged; only which
// piece prints a triangle moves.

#include <vector>

#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// Triangle `gone` of `strip` taken away, with whatever it alone held to the rest (a ruled
/// strip is a path of triangles: taking one takes the end beyond it too): `rest` is the
/// largest piece left (by area; its boundary left empty), `taken` the triangle with the smaller
/// pieces. False when nothing is left or the rest would meet the part taken only at a point of
/// its own.
bool take_triangle(const FlatStrip& strip, std::size_t gone, FlatStrip& rest, FlatStrip& taken);

/// What grow_from_neighbours grows a strip until: min_area, or wide enough.
enum class GrowUntil { kMinArea, kWide };

/// A strip grown from its neighbours (a crumb no neighbour takes, a band no hinge takes): it
/// takes their triangles that share an edge with it, one at a time, each folded out of it
/// across every edge it shares; of those that find a place, the one leaving it most compact
/// (with `least_narrow_first`, of those leaving it narrow over the least share, the most
/// compact). A triangle takes with it the part of its strip it alone held on (the end of a ruled
/// strip). It is taken only where it lands on no triangle of the strip, every edge shared welds (no
/// slit opens in the strip) and what is left of the neighbour is at least min_area. Grows
/// until the strip reaches min_area (kMinArea) or is narrower than min_width over at most
/// narrow_share of its area (kWide), and neither the strip nor a neighbour it took from is
/// narrower than min_width over more than narrow_share of its area (or more than it was).
/// Kept only when that is reached within 128 triangles taken (kMostTaken), giving up once 16 in
/// a row bring it no closer; otherwise `strips` is left as it was and false returned.
bool grow_from_neighbours(std::vector<FlatStrip>& strips, int index, GrowUntil until,
                          double min_area, double min_width, double narrow_share,
                          const MergeOptions& options, bool least_narrow_first = false);

}  // namespace papercraft::merge_detail
