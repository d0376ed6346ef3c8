// join_small_and_narrow_strips: the merge node's joins after merge_congruent, in order.
#include <algorithm>
#include <utility>
#include <vector>

#include "core/flat_boundary.h"
#include "nodes/merge/congruent.h"

namespace papercraft {

std::vector<FlatStrip> join_small_and_narrow_strips(std::vector<FlatStrip> strips, double min_area,
                                                    double min_width, const MergeOptions& options,
                                                    std::vector<int>* left) {
  std::vector<int> small;
  strips = join_small_strips(std::move(strips), min_area, options, &small, min_width);
  strips = join_narrow_strips(std::move(strips), min_width, options.narrow_join_share, options, 256,
                              min_area);
  if (!small.empty())
    strips = join_small_strips(std::move(strips), min_area, options, &small, min_width);
  if (options.modest_join_factor > 1.0)
    strips = hinge_modest_strips(std::move(strips), options.modest_join_factor * min_area, options,
                                 min_width);
  strips = smooth_seams(std::move(strips), min_area, min_width, options.narrow_join_share, options);
  if (left) {
    // The crumbs left are those of `small` still under min_area (a hinge above may have
    // joined one).
    left->clear();
    for (const FlatStrip& strip : strips)
      if (std::find(small.begin(), small.end(), strip.id) != small.end() &&
          flat_area(strip) < min_area)
        left->push_back(strip.id);
  }
  return strips;
}

}  // namespace papercraft
