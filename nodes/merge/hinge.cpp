// Hinging a strip whole onto a neighbour: hinge_whole, and hinge_modest_strips, which hinges
// every piece under a bound that way.
#include "nodes/merge/hinge.h"

#include <algorithm>
#include <map>
#include <memory>
#include <utility>

#include "core/flat_boundary.h"
#include "core/seams.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/move_cost.h"
#include "nodes/merge/join_measures.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/validate.h"

namespace papercraft {
namespace merge_detail {

bool hinge_whole(std::vector<FlatStrip>& strips, int s, const MergeOptions& options,
                 double slit_width, double min_area, bool must_gain) {
  constexpr int kMostWholeHinges = 16;
  const std::vector<PairCandidate> pairs = shared_boundaries(strips, s);
  auto hinges = hinges_of(pairs, strips,
                          [&](const PairCandidate& pair) { return pair.x == s || pair.y == s; });
  std::stable_partition(hinges.begin(), hinges.end(), [](const Hinge& h) { return h.chain_end; });
  const bool by_effort = options.mm_per_unit > 0.0;
  std::map<int, std::unique_ptr<MoveCost>> costs;  // per pair
  FlatStrip best;
  int best_pair = -1, best_slit = 0, tried = 0;
  double best_gain = 0.0;
  for (const Hinge& hinge : hinges) {
    if (best_pair >= 0 && ((slit_width <= 0.0 && !by_effort) || ++tried > kMostWholeHinges))
      break;
    const PairCandidate& pair = pairs[hinge.pair];
    FlatStrip merged;
    if (!try_merge(strips[pair.x], strips[pair.y], {hinge.edge}, options, merged, by_effort))
      continue;
    if (by_effort) {
      auto& cost = costs[hinge.pair];
      if (!cost) cost = std::make_unique<MoveCost>(strips, std::vector<int>{pair.x, pair.y}, options, min_area);
      const double gain = cost->gain(merged);
      if ((must_gain && !(gain > 0.0)) || (best_pair >= 0 && gain <= best_gain)) continue;
      best = std::move(merged), best_pair = hinge.pair, best_gain = gain;
      continue;
    }
    const int slit =
        slit_width > 0.0 ? slit_points(merged, strips[pair.x].vertices2d.size(), slit_width) : 0;
    if (best_pair >= 0 && slit >= best_slit) continue;
    best = std::move(merged), best_pair = hinge.pair, best_slit = slit;
    if (slit == 0) break;
  }
  if (best_pair < 0) return false;
  const PairCandidate& pair = pairs[best_pair];
  best.boundary = flat_boundary(best.triangles);
  strips[pair.x] = std::move(best);
  strips.erase(strips.begin() + pair.y);
  return true;
}

int smallest_below(const std::vector<FlatStrip>& strips, double bound,
                   const std::set<int>& given_up) {
  int smallest = -1;
  double least = bound;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    const double area = flat_area(strips[s]);
    if (area < least && !given_up.count(strips[s].id)) smallest = s, least = area;
  }
  return smallest;
}

}  // namespace merge_detail

using merge_detail::hinge_whole;
using merge_detail::smallest_below;
using merge_detail::validate;

std::vector<FlatStrip> hinge_modest_strips(std::vector<FlatStrip> strips, double below_area,
                                           const MergeOptions& options, double min_width) {
  validate(strips, options);
  if (!(below_area > 0.0)) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  std::set<int> given_up;  // ids of strips no neighbour takes
  while (true) {
    const int modest = smallest_below(strips, below_area, given_up);
    if (modest < 0) break;
    // Hinged only where it pays: a piece of legal size is not worth a slit without room for a
    // glue flap.
    if (!hinge_whole(strips, modest, options, min_width,
                     below_area / std::max(1.0, options.modest_join_factor), true))
      given_up.insert(strips[modest].id);
  }
  label_seams(strips);
  return strips;
}

}  // namespace papercraft
