#pragma once
// A crumb taken apart into its triangles, each folded out of a neighbour (join_small_strips'
// second try).

#include <vector>

#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// A strip no neighbour takes whole, taken apart into its triangles, each hinged to a
/// neighbour across one of its edges (a triangle whose neighbours are all its own siblings
/// waits until a sibling has been taken): where the union of the whole would overlap a
/// neighbour (a notch narrower in the plane than on the surface, at a saddle), single
/// triangles often still fold out on the free side. Kept only when every triangle finds a
/// place and at most one of the strip's inner edges is opened; a strip of 2 to 64 triangles
/// only. Otherwise `strips` is left as
/// it was and false returned.
bool absorb_by_triangles(std::vector<FlatStrip>& strips, int small, const MergeOptions& options);

}  // namespace papercraft::merge_detail
