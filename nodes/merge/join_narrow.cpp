// join_narrow_strips: each band, the narrowest first, hinged whole onto a neighbour where the
// union is less narrow, else cut in two (or more) and each part hinged on, else grown.
#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "core/flat_boundary.h"
#include "core/piece_width.h"
#include "core/seams.h"
#include "nodes/merge/band_split.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/move_cost.h"
#include "nodes/merge/join_measures.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/transfer.h"
#include "nodes/merge/validate.h"

namespace papercraft {

using merge_detail::exact_key;
using merge_detail::grow_from_neighbours;
using merge_detail::GrowUntil;
using merge_detail::hinge_in_two;
using merge_detail::hinges_of;
using merge_detail::PairCandidate;
using merge_detail::rim_of;
using merge_detail::shared_boundaries;
using merge_detail::shares_before_and_joined;
using merge_detail::MoveCost;
using merge_detail::slit_points;
using merge_detail::try_merge;
using merge_detail::validate;

std::vector<FlatStrip> join_narrow_strips(std::vector<FlatStrip> strips, double min_width,
                                          double narrow_share, const MergeOptions& options,
                                          int most_hinges, double min_area) {
  validate(strips, options);
  if (!(min_width > 0.0) || !(narrow_share >= 0.0) || most_hinges < 1) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  auto share_of = [&](const FlatStrip& strip) {
    return narrow_area_fraction(strip.vertices2d, strip.triangles, min_width);
  };
  std::vector<double> share(strips.size());
  for (std::size_t s = 0; s < strips.size(); ++s) share[s] = share_of(strips[s]);
  std::set<int> given_up;  // ids of narrow strips no neighbour takes
  // A strip given up beside a union is tried again: the union is less narrow than the
  // neighbour it folded onto was, or has new edges for a hinge.
  const auto retry_beside = [&](const FlatStrip& joined) {
    const std::set<std::array<double, 6>> rim = rim_of(joined);
    for (const FlatStrip& strip : strips) {
      if (!given_up.count(strip.id)) continue;
      for (const BoundaryEdge& e : strip.boundary)
        if (rim.count(exact_key(strip.vertices3d[e.v0], strip.vertices3d[e.v1]))) {
          given_up.erase(strip.id);
          break;
        }
    }
  };
  while (true) {
    // The narrowest strip still to place.
    int narrow = -1;
    for (int s = 0; s < static_cast<int>(strips.size()); ++s)
      if (share[s] > narrow_share && !given_up.count(strips[s].id) &&
          (narrow < 0 || share[s] > share[narrow]))
        narrow = s;
    if (narrow < 0) break;
    const std::vector<PairCandidate> pairs = shared_boundaries(strips, narrow);
    const auto hinges = hinges_of(pairs, strips, [&](const PairCandidate& pair) {
      return pair.x == narrow || pair.y == narrow;
    });
    // Of the hinges that give a union less narrow than the strip, and either no narrower than
    // the neighbour was (or than the bound) or narrow over no more area than the two together
    // (a band kept whole beside a wide neighbour: one seam fewer, no tab on the band), the one
    // that leaves the least slit; with a print scale, of the first kMostJudged that lay it flat,
    // the one whose MoveCost gain is largest.
    constexpr int kMostJudged = 16;
    const bool by_effort = options.mm_per_unit > 0.0;
    std::map<int, std::unique_ptr<MoveCost>> costs;  // per pair
    FlatStrip best;
    int best_hinge = -1, best_slit = 0, judged = 0;
    double best_share = 0.0, best_gain = 0.0;
    const int tries = std::min(static_cast<int>(hinges.size()), most_hinges);
    for (int h = 0; h < tries; ++h) {
      const PairCandidate& pair = pairs[hinges[h].pair];
      const int other = pair.x == narrow ? pair.y : pair.x;
      FlatStrip merged;
      if (!try_merge(strips[pair.x], strips[pair.y], {hinges[h].edge}, options, merged,
                     by_effort))
        continue;
      int slit = 0;
      double gain = 0.0;
      if (by_effort) {
        if (best_hinge >= 0 && judged >= kMostJudged) break;
        auto& cost = costs[hinges[h].pair];
        if (!cost) cost = std::make_unique<MoveCost>(strips, std::vector<int>{pair.x, pair.y}, options, min_area);
        gain = cost->gain(merged);
        ++judged;
        if (best_hinge >= 0 && gain <= best_gain) continue;
      } else {
        slit = slit_points(merged, strips[pair.x].vertices2d.size(), min_width);
        if (best_hinge >= 0 && slit >= best_slit) continue;
      }
      const double joined_share = share_of(merged);
      if (!(joined_share < share[narrow])) continue;
      if (joined_share > std::max(share[other], narrow_share) &&
          joined_share * flat_area(merged) >
              share[narrow] * flat_area(strips[narrow]) + share[other] * flat_area(strips[other]))
        continue;
      best = std::move(merged);
      best_hinge = h, best_slit = slit, best_share = joined_share, best_gain = gain;
      if (!by_effort && slit == 0) break;
    }
    if (best_hinge < 0) {
      // No hinge takes it whole: cut in two, each half hinged onto a neighbour, where the
      // union is less narrow than the strip and no narrower than the neighbour was (or than
      // the bound).
      std::vector<int> changed;
      std::map<int, NarrowRaster> rasters;
      const auto keeps_wide = [&](int neighbour, const FlatStrip& joined) {
        const auto [was, is] =
            shares_before_and_joined(strips, neighbour, joined, min_width, rasters);
        return is < share[narrow] && is <= std::max(was, narrow_share);
      };
      if (hinge_in_two(strips, narrow, min_width, options, keeps_wide, changed)) {
        share.erase(share.begin() + narrow);
        for (int s : changed) share[s] = share_of(strips[s]);
        for (int s : changed) retry_beside(strips[s]);
      } else {
        given_up.insert(strips[narrow].id);
      }
      continue;
    }
    const PairCandidate& pair = pairs[hinges[best_hinge].pair];
    best.boundary = flat_boundary(best.triangles);
    strips[pair.x] = std::move(best);
    share[pair.x] = best_share;
    strips.erase(strips.begin() + pair.y);
    share.erase(share.begin() + pair.y);
    retry_beside(strips[pair.x]);  // x < y: the union kept x's place
  }
  // A strip still narrow grows instead, as a crumb does, until it is no longer narrow (a
  // neighbour it takes from keeps min_area and gets no narrower than it was or than the
  // bound). share[] of a neighbour taken from goes stale but stays an upper bound.
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    if (share[s] > narrow_share)
      grow_from_neighbours(strips, s, GrowUntil::kWide, min_area, min_width, narrow_share, options);
  label_seams(strips);
  return strips;
}

}  // namespace papercraft
