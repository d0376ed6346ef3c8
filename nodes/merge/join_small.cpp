// join_small_strips: each crumb, the smallest first, hinged whole onto a neighbour, else taken
// apart into its triangles, else cut in two, else grown from its neighbours.
#include <map>
#include <set>
#include <vector>

#include "core/flat_boundary.h"
#include "core/seams.h"
#include "nodes/merge/absorb.h"
#include "nodes/merge/band_split.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/hinge.h"
#include "nodes/merge/join_measures.h"
#include "nodes/merge/transfer.h"
#include "nodes/merge/validate.h"

namespace papercraft {

using merge_detail::absorb_by_triangles;
using merge_detail::grow_from_neighbours;
using merge_detail::GrowUntil;
using merge_detail::hinge_in_two;
using merge_detail::hinge_whole;
using merge_detail::shares_before_and_joined;
using merge_detail::smallest_below;
using merge_detail::validate;

std::vector<FlatStrip> join_small_strips(std::vector<FlatStrip> strips, double min_area,
                                         const MergeOptions& options, std::vector<int>* left,
                                         double min_width) {
  validate(strips, options);
  if (left) left->clear();
  if (!(min_area > 0.0)) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  std::set<int> given_up;  // ids of small strips no neighbour takes
  while (true) {
    // The smallest strip still to place.
    const int small = smallest_below(strips, min_area, given_up);
    if (small < 0) break;
    // Hinged whole over one of its shared edges, the one leaving the least slit.
    bool joined = hinge_whole(strips, small, options, min_width, min_area);
    if (!joined) joined = absorb_by_triangles(strips, small, options);
    if (!joined && min_width > 0.0) {
      // Cut in two, each half hinged onto a neighbour that gets no narrower than it was (or
      // than narrow_join_share).
      std::map<int, NarrowRaster> rasters;
      const auto keeps_wide = [&](int neighbour, const FlatStrip& joined_strip) {
        const auto [was, is] =
            shares_before_and_joined(strips, neighbour, joined_strip, min_width, rasters);
        return is <= std::max(was, options.narrow_join_share);
      };
      std::vector<int> changed;
      joined = hinge_in_two(strips, small, min_width, options, keeps_wide, changed);
    }
    if (!joined)
      joined = grow_from_neighbours(strips, small, GrowUntil::kMinArea, min_area, min_width,
                                    options.narrow_join_share, options);
    // Grown the most compact way it ends narrower than it began (a neighbour's fan gives thin
    // triangles whose tips add narrow area): grown again, taking first what leaves it narrow
    // over the least share.
    if (!joined && min_width > 0.0)
      joined = grow_from_neighbours(strips, small, GrowUntil::kMinArea, min_area, min_width,
                                    options.narrow_join_share, options, true);
    if (!joined) given_up.insert(strips[small].id);
  }
  if (left) left->assign(given_up.begin(), given_up.end());
  label_seams(strips);
  return strips;
}

}  // namespace papercraft
