// A band cut across its inner edges into two to four parts, each hinged onto a neighbour:
// the folds that may take a part, the cuts the most even first, each part placed where it
// leaves the least slit, and a part that finds no place cut again.
#include "nodes/merge/band_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>

#include "core/dual_cuts.h"
#include "core/flat_boundary.h"
#include "core/overlap_2d.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/join_measures.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/strip_parts.h"

namespace papercraft::merge_detail {
namespace {

// Hinges tried per neighbour for one half: the floor's edges must not use up the tries before
// the ceiling's.
constexpr int kMostHinges = 12;

// Each edge the band shares with a neighbour, as a hinge of the whole band: its triangle,
// and the band's triangles that its motion lays over that neighbour. A half folds over it
// only when it holds the triangle and none of those (the neighbour alone; a half folding
// onto a neighbour that took the other half is checked in full).
struct Fold {
  int triangle = -1;
  std::vector<int> over;
};
using Folds = std::map<std::pair<int, std::array<double, 6>>, Fold>;  // (neighbour, 3D edge)

// The folds of the band `strip` onto its neighbours strips[around[i]], keyed by i.
Folds folds_of(const std::vector<FlatStrip>& strips, const std::vector<int>& around,
               const FlatStrip& strip, const MergeOptions& options) {
  const int n = static_cast<int>(around.size());
  const int count = static_cast<int>(strip.triangles.size());
  Folds folds;
  std::vector<FlatStrip> whole;
  for (int s : around) whole.push_back(strips[s]);
  whole.push_back(strip);
  const std::vector<PairCandidate> pairs = shared_boundaries(whole, n);
  const auto hinges =
      hinges_of(pairs, whole, [&](const PairCandidate& pair) { return pair.x < n && pair.y == n; });
  const double band_edge = mean_edge_length(strip);
  std::map<int, TriangleGrid2> grids;
  for (const Hinge& hinge : hinges) {
    const int i = pairs[hinge.pair].x;
    const FlatStrip& neighbour = whole[i];
    const double mean_edge = 0.5 * (mean_edge_length(neighbour) + band_edge);
    auto grid = grids.find(i);
    if (grid == grids.end()) {
      grid = grids.emplace(i, TriangleGrid2(mean_edge > 0.0 ? mean_edge : 1.0)).first;
      for (const Triangle& t : neighbour.triangles)
        grid->second.insert(
            {neighbour.vertices2d[t[0]], neighbour.vertices2d[t[1]], neighbour.vertices2d[t[2]]});
    }
    const Chain& edge = hinge.edge;
    const RigidMotion motion =
        fit({strip.vertices2d[edge.y[0]], strip.vertices2d[edge.y[1]]},
            {neighbour.vertices2d[edge.x[0]], neighbour.vertices2d[edge.x[1]]});
    // Looser than try_merge's bound, which it only screens for.
    const double tolerance = 2.0 * options.overlap_tolerance * mean_edge +
                             8.0 * chain_residual(neighbour, strip, edge, motion);
    Fold fold;
    for (int t = 0; t < count; ++t) {
      const Triangle& tri = strip.triangles[t];
      int on_edge = 0;
      for (int v : tri) on_edge += v == edge.y[0] || v == edge.y[1];
      if (on_edge == 2) fold.triangle = t;
      if (grid->second.overlaps({motion(strip.vertices2d[tri[0]]), motion(strip.vertices2d[tri[1]]),
                                 motion(strip.vertices2d[tri[2]])},
                                tolerance))
        fold.over.push_back(t);
    }
    const std::array<double, 6> key =
        exact_key(strip.vertices3d[edge.y[0]], strip.vertices3d[edge.y[1]]);
    if (fold.triangle >= 0) folds.emplace(std::make_pair(i, key), std::move(fold));
  }
  return folds;
}

// The band's inner edges, as the two triangles they join.
std::vector<std::pair<int, int>> inner_edges(const FlatStrip& strip) {
  const int count = static_cast<int>(strip.triangles.size());
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (int t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = strip.triangles[t][k], b = strip.triangles[t][(k + 1) % 3];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  std::vector<std::pair<int, int>> inner;
  for (const auto& [edge, ts] : by_edge)
    if (ts.size() == 2) inner.emplace_back(ts[0], ts[1]);
  return inner;
}

// A band to cut and what its trials share: its neighbours strips[around[i]], the folds that
// may take its parts, and its cuts across the inner edges.
struct Band {
  const std::vector<FlatStrip>& strips;
  const FlatStrip& strip;
  int count;  // its triangles
  std::vector<int> around;
  int n;  // around's size: a trial holds the neighbours at 0..n-1, then a part of the band at n
  Folds folds;
  std::vector<std::pair<int, int>> inner;
  DualCuts cuts;
  double min_width;
  const MergeOptions& options;
  const KeepsWide& keeps_wide;
};

// Which side of a cut each triangle lies on (true: the first triangle's), or false where the
// band stays one piece (around an inner vertex).
bool sides(const Band& band, std::size_t cut, std::vector<bool>& first) {
  if (!band.cuts.splits(cut)) return false;
  first.assign(band.count, false);
  for (int t = 0; t < band.count; ++t) first[t] = band.cuts.on_first_side(cut, t);
  return true;
}

// Whether a half may fold over (neighbour, edge): it holds the hinge's triangle and none of
// the band's triangles the hinge lays over the neighbour.
bool may_fold(const Band& band, const std::vector<bool>& first, bool side, int neighbour,
              const std::array<double, 6>& key) {
  auto it = band.folds.find({neighbour, key});
  if (it == band.folds.end() || first[it->second.triangle] != side) return false;
  for (int t : it->second.over)
    if (first[t] == side) return false;
  return true;
}

bool any_fold(const Band& band, const std::vector<bool>& first, bool side) {
  for (const auto& [where, fold] : band.folds)
    if (may_fold(band, first, side, where.first, where.second)) return true;
  return false;
}

using CutOrder = std::vector<std::pair<int, std::size_t>>;  // (imbalance, cut)

// `cut_order` sorted by imbalance and, past `most_cuts`, thinned to that many spread evenly
// over it.
void keep_most_even(CutOrder& cut_order, int most_cuts) {
  std::stable_sort(cut_order.begin(), cut_order.end());
  if (static_cast<int>(cut_order.size()) <= most_cuts) return;
  CutOrder spread;
  for (int i = 0; i < most_cuts; ++i) spread.push_back(cut_order[i * cut_order.size() / most_cuts]);
  cut_order = std::move(spread);
}

// Cuts by how evenly they share the band, the most even first; only those where each half
// has a hinge that may take it (`both`). And, for a cut in three, those where one half has
// such a hinge (`one`: the other is cut again).
void cut_orders(const Band& band, bool in_three, int most_cuts, CutOrder& both, CutOrder& one) {
  for (std::size_t e = 0; e < band.inner.size(); ++e) {
    std::vector<bool> first;
    if (!sides(band, e, first)) continue;
    const bool first_folds = any_fold(band, first, true);
    const bool second_folds = any_fold(band, first, false);
    const int imbalance = std::abs(2 * band.cuts.first_side_size(e) - band.count);
    if (first_folds && second_folds) both.emplace_back(imbalance, e);
    if (in_three && (first_folds || second_folds)) one.emplace_back(imbalance, e);
  }
  keep_most_even(both, most_cuts);
  keep_most_even(one, most_cuts);
}

// Hinges the half at trial[n] (the `side` of `first`) onto a neighbour in `trial`: the union
// replaces the neighbour and the half is erased. Returns the slit left, or -1 where no hinge
// takes it.
int place(const Band& band, std::vector<FlatStrip>& trial, std::vector<bool>& took,
          const std::vector<bool>& first, bool side, bool check_wide) {
  const int n = band.n;
  const FlatStrip& half = trial[n];
  const std::vector<PairCandidate> pairs = shared_boundaries(trial, n);
  const auto hinges =
      hinges_of(pairs, trial, [&](const PairCandidate& pair) { return pair.x < n && pair.y == n; });
  // The unions that place it, the least slit first; with `check_wide`, the first of those
  // keeps_wide accepts.
  std::vector<std::pair<int, int>> placed;        // (slit, index into unions)
  std::vector<std::pair<int, FlatStrip>> unions;  // (neighbour in trial, union)
  std::vector<int> tried(n, 0);                   // per neighbour
  for (const Hinge& hinge : hinges) {
    const PairCandidate& pair = pairs[hinge.pair];
    if (tried[pair.x] == kMostHinges) continue;
    const std::array<double, 6> key =
        exact_key(half.vertices3d[hinge.edge.y[0]], half.vertices3d[hinge.edge.y[1]]);
    if (!may_fold(band, first, side, pair.x, key)) continue;
    ++tried[pair.x];
    FlatStrip merged;
    if (!try_merge(trial[pair.x], half, {hinge.edge}, band.options, merged, false)) continue;
    const int slit = slit_points(merged, trial[pair.x].vertices2d.size(), band.min_width);
    placed.emplace_back(slit, static_cast<int>(unions.size()));
    unions.emplace_back(pair.x, std::move(merged));
  }
  std::stable_sort(placed.begin(), placed.end());
  int best_x = -1, best_slit = 0;
  FlatStrip best;
  for (const auto& [slit, u] : placed) {
    if (check_wide && !band.keeps_wide(band.around[unions[u].first], unions[u].second)) continue;
    best_x = unions[u].first, best_slit = slit, best = std::move(unions[u].second);
    break;
  }
  if (best_x < 0) return -1;
  best.boundary = flat_boundary(best.triangles);
  trial[best_x] = std::move(best);
  took[best_x] = true;
  trial.erase(trial.begin() + n);
  return best_slit;
}

// A trial's start: the band's neighbours at 0..n-1.
std::vector<FlatStrip> neighbours(const Band& band) {
  std::vector<FlatStrip> trial;
  for (int s : band.around) trial.push_back(band.strips[s]);
  return trial;
}

// The band's triangles on the `side` of `first`, as a strip of their own.
FlatStrip half_of(const Band& band, const std::vector<bool>& first, bool side) {
  std::vector<Triangle> chosen;
  for (int t = 0; t < band.count; ++t)
    if (first[t] == side) chosen.push_back(band.strip.triangles[t]);
  return sub_strip(band.strip, chosen);
}

// Both halves placed at `cut` (the slit they leave), or -1.
int split_at(const Band& band, std::size_t cut, bool check_wide, std::vector<FlatStrip>& trial,
             std::vector<bool>& took) {
  std::vector<bool> first;
  sides(band, cut, first);
  trial = neighbours(band);
  took.assign(band.n, false);  // the neighbours that took a half
  trial.push_back(half_of(band, first, true));
  const int slit_first = place(band, trial, took, first, true, check_wide);
  if (slit_first < 0) return -1;
  trial.push_back(half_of(band, first, false));
  const int slit_second = place(band, trial, took, first, false, check_wide);
  return slit_second < 0 ? -1 : slit_first + slit_second;
}

// The neighbours as a split left them, which of them took a part, and the slit left (-1 where
// no split placed every part).
struct Split {
  std::vector<FlatStrip> trial;
  std::vector<bool> took;
  int slit = -1;
};

// In two: of the cuts of `order`, the one whose halves both find a place leaving the least
// slit. Placing costs little; measuring width is what costs. So the width is checked only where
// both halves find a place without it and might leave less slit than the split kept (the
// check only takes choices away), at most kMostChecks times before one passes and
// kMostBetter times after.
Split split_in_two(const Band& band, const CutOrder& order) {
  constexpr int kMostChecks = 32;
  constexpr int kMostBetter = 8;
  Split kept;
  int checks = 0, better = 0;
  for (const auto& [imbalance, cut] : order) {
    std::vector<FlatStrip> trial;
    std::vector<bool> took;
    const int unchecked = split_at(band, cut, false, trial, took);
    if (unchecked < 0 || (kept.slit >= 0 && unchecked >= kept.slit)) continue;
    if (kept.slit < 0 ? ++checks > kMostChecks : ++better > kMostBetter) break;
    const int slit = split_at(band, cut, true, trial, took);
    if (slit < 0 || (kept.slit >= 0 && slit >= kept.slit)) continue;
    kept.trial = std::move(trial), kept.took = std::move(took), kept.slit = slit;
    if (kept.slit == 0) break;
  }
  return kept;
}

// In three, where no cut placed both halves (a band whose neighbours turn twice along it:
// each half of any cut turns with them somewhere): one half placed, width checked, and the
// other cut in two again (trying at most 4 cuts, as it is tried for several first halves), and
// so on while `cuts_after` lasts: the rest of a band whose neighbours turn three times is cut
// in three again. The cuts of `order_one`, where one half may fold, the most even first; at
// most kMostThirds first halves placed.
Split split_in_three(const Band& band, const CutOrder& order_one, int cuts_after) {
  constexpr int kMostThirds = 4;
  const int n = band.n;
  Split kept;
  int thirds = 0;
  for (auto cut = order_one.begin(); kept.slit < 0 && cut != order_one.end(); ++cut) {
    std::vector<bool> first;
    sides(band, cut->second, first);
    for (const bool side : {true, false}) {
      std::vector<FlatStrip> trial = neighbours(band);
      std::vector<bool> took(n, false);
      trial.push_back(half_of(band, first, side));
      if (place(band, trial, took, first, side, true) < 0) continue;
      if (++thirds > kMostThirds) break;
      trial.push_back(half_of(band, first, !side));
      const auto keeps_wide_in_trial = [&band](int i, const FlatStrip& joined) {
        return band.keeps_wide(band.around[i], joined);
      };
      std::vector<int> took_rest;
      if (!hinge_in_two(trial, n, band.min_width, band.options, keeps_wide_in_trial, took_rest,
                        cuts_after - 1))
        continue;
      for (int i : took_rest) took[i] = true;
      kept.trial = std::move(trial), kept.took = std::move(took), kept.slit = 0;
      break;
    }
    if (thirds > kMostThirds) break;
  }
  return kept;
}

}  // namespace

bool hinge_in_two(std::vector<FlatStrip>& strips, int band_index, double min_width,
                  const MergeOptions& options, const KeepsWide& keeps_wide,
                  std::vector<int>& changed, int cuts_after) {
  const int most_cuts_after = std::max(0, options.most_band_pieces - 2);
  const bool whole_band = cuts_after < 0;
  if (whole_band) cuts_after = most_cuts_after;
  const bool in_three = cuts_after > 0;
  // A half cut again tries fewer cuts: see split_in_three.
  const int most_cuts = whole_band ? 48 : 4;
  // Checking a half's width rasters a box the size of the half: on a strip of thousands of
  // triangles (a large piece narrow along much of its rim; ChineseDragon's 3,629) the checks
  // took 12 s of its 18 s merge (harness), for the same pieces as without them (6 s). Such a
  // strip is left to the growth.
  constexpr int kMostTriangles = 2048;
  const FlatStrip& strip = strips[band_index];
  const int count = static_cast<int>(strip.triangles.size());
  if (count < 2 || count > kMostTriangles) return false;
  // The band's neighbours (a boundary edge on its rim), worked on apart from the other strips.
  std::vector<int> around = strips_beside(strips, band_index);
  if (around.empty()) return false;
  const int n = static_cast<int>(around.size());
  Folds folds = folds_of(strips, around, strip, options);
  if (folds.empty()) return false;
  std::vector<std::pair<int, int>> inner = inner_edges(strip);
  // A cut leaves exactly two halves where its edge is a bridge of the band's dual graph.
  DualCuts cuts(count, inner);
  if (!cuts.connected()) return false;  // a band in pieces: every cut leaves more than two
  const Band band{
      strips,           strip,           count,     std::move(around), n,         std::move(folds),
      std::move(inner), std::move(cuts), min_width, options,           keeps_wide};
  CutOrder order, order_one;
  cut_orders(band, in_three, most_cuts, order, order_one);
  Split kept = split_in_two(band, order);
  if (kept.slit < 0) kept = split_in_three(band, order_one, cuts_after);
  if (kept.slit < 0) return false;
  changed.clear();
  for (int i = 0; i < n; ++i) {
    if (!kept.took[i]) continue;
    strips[band.around[i]] = std::move(kept.trial[i]);
    changed.push_back(band.around[i] > band_index ? band.around[i] - 1 : band.around[i]);
  }
  strips.erase(strips.begin() + band_index);
  return true;
}

}  // namespace papercraft::merge_detail
