// A strip grown from its neighbours, one triangle at a time, each taking with it what its
// neighbour held only through it.
#include "nodes/merge/transfer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/flat_boundary.h"
#include "core/piece_width.h"
#include "core/union_find.h"
#include "nodes/merge/chains.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/strip_parts.h"

namespace papercraft::merge_detail {
bool take_triangle(const FlatStrip& strip, std::size_t gone, FlatStrip& rest, FlatStrip& taken) {
  const int n = static_cast<int>(strip.triangles.size());
  if (n < 2) return false;
  // The triangles left, joined across the edges they share: (edge, triangle), sorted.
  std::vector<std::pair<std::pair<int, int>, int>> by_edge;
  by_edge.reserve(3 * n);
  for (int t = 0; t < n; ++t) {
    if (t == static_cast<int>(gone)) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = strip.triangles[t][k], b = strip.triangles[t][(k + 1) % 3];
      by_edge.push_back({{std::min(a, b), std::max(a, b)}, t});
    }
  }
  std::sort(by_edge.begin(), by_edge.end());
  UnionFind pieces(n);
  for (std::size_t i = 1; i < by_edge.size(); ++i)
    if (by_edge[i].first == by_edge[i - 1].first)
      pieces.unite(by_edge[i - 1].second, by_edge[i].second);
  std::map<std::size_t, double> area;
  for (int t = 0; t < n; ++t) {
    if (t == static_cast<int>(gone)) continue;
    const Triangle& tri = strip.triangles[t];
    const Vec2 u = strip.vertices2d[tri[1]] - strip.vertices2d[tri[0]];
    const Vec2 v = strip.vertices2d[tri[2]] - strip.vertices2d[tri[0]];
    area[pieces.find(t)] += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
  }
  std::size_t largest = 0;
  double most = -1.0;
  for (const auto& [root, a] : area)
    if (a > most) largest = root, most = a;
  std::vector<Triangle> kept, moved;
  std::set<int> moved_corners;
  for (int t = 0; t < n; ++t) {
    const bool stays = t != static_cast<int>(gone) && pieces.find(t) == largest;
    (stays ? kept : moved).push_back(strip.triangles[t]);
    if (!stays) moved_corners.insert(strip.triangles[t].begin(), strip.triangles[t].end());
  }
  for (int corner : moved_corners)
    if (!one_fan(kept, corner)) return false;
  rest = sub_strip(strip, kept, false);  // its boundary is found only if it is kept
  taken = sub_strip(strip, moved);
  return true;
}


bool grow_from_neighbours(std::vector<FlatStrip>& strips, int index, GrowUntil until,
                          double min_area, double min_width, double narrow_share,
                          const MergeOptions& options, bool least_narrow_first) {
  constexpr std::size_t kMostTaken = 128;
  auto share_of = [&](const FlatStrip& strip) {
    return min_width > 0.0 ? narrow_area_fraction(strip.vertices2d, strip.triangles, min_width)
                           : 0.0;
  };
  FlatStrip grown = strips[index];
  const std::size_t first_size = grown.triangles.size();
  const double grown_share = share_of(grown);
  std::map<int, FlatStrip> donors;  // strip index -> what is left of it
  auto current = [&](int s) -> const FlatStrip& {
    auto it = donors.find(s);
    return it == donors.end() ? strips[s] : it->second;
  };
  std::set<std::array<double, 9>> refused;  // triangles (their 3D corners) that found no place
  struct Candidate {
    int strip;
    std::size_t triangle;
  };
  // A growth is acceptable when neither the strip nor a neighbour it took from is narrower
  // than min_width over more of its area than before (or than narrow_share). The shares of
  // the neighbours, before and as left, are kept as they are measured.
  std::map<int, double> share_before, share_left;
  auto acceptable = [&](double share) {
    if (share > std::max(grown_share, narrow_share)) return false;
    for (const auto& [s, rest] : donors) {
      if (!share_before.count(s)) share_before[s] = share_of(strips[s]);
      if (!share_left.count(s)) share_left[s] = share_of(rest);
      if (share_left[s] > std::max(share_before[s], narrow_share)) return false;
    }
    return true;
  };
  // A crumb stops at the first acceptable growth past min_area; one that is not (a neighbour
  // it took from got narrower) goes on growing, within the same kMostTaken, until one is. A
  // band stops once it is narrow over at most narrow_share and acceptable. Either gives up
  // once kPatience triangles in a row bring it no closer: a band that stays narrow (a strip
  // along a thin feature) would only pay for the rest of kMostTaken and fail anyway.
  constexpr int kPatience = 16;
  double least_share = grown_share;
  int since_least = 0;
  while (true) {
    if (until == GrowUntil::kWide || flat_area(grown) >= min_area) {
      const double share = share_of(grown);
      if ((until == GrowUntil::kMinArea || share <= narrow_share) && acceptable(share)) break;
      if (until == GrowUntil::kWide && share < least_share) {
        least_share = share, since_least = 0;
      } else if (++since_least >= kPatience) {
        return false;
      }
    }
    const std::set<std::array<double, 6>> rim = rim_of(grown);
    // The neighbours' triangles on the rim: those with a boundary edge on it.
    std::vector<Candidate> candidates;
    for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
      if (s == index) continue;
      const FlatStrip& strip = current(s);
      std::set<std::pair<int, int>> on_rim;  // boundary edges (v0, v1) on the rim
      for (const BoundaryEdge& e : strip.boundary)
        if (rim.count(exact_key(strip.vertices3d[e.v0], strip.vertices3d[e.v1])))
          on_rim.insert({e.v0, e.v1});
      if (on_rim.empty()) continue;
      for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
        const Triangle& tri = strip.triangles[t];
        bool shares = false;
        for (int k = 0; k < 3; ++k) shares = shares || on_rim.count({tri[k], tri[(k + 1) % 3]});
        if (shares && !refused.count(corners_key(strip, tri))) candidates.push_back({s, t});
      }
    }
    // Of the triangles that find a place, the one leaving the strip most compact (the least
    // squared perimeter per area in the plane: a round piece is wide, a long one narrow); with
    // least_narrow_first, of those leaving it narrower than min_width over the least share of
    // its area.
    FlatStrip best, best_rest;
    int best_strip = -1;
    std::pair<double, double> best_score{0.0, 0.0};
    for (const Candidate& candidate : candidates) {
      const FlatStrip& donor = current(candidate.strip);
      const Triangle& tri = donor.triangles[candidate.triangle];
      FlatStrip rest, part;
      const std::vector<PairCandidate> pairs =
          take_triangle(donor, candidate.triangle, rest, part) && flat_area(rest) >= min_area &&
                  grown.triangles.size() + part.triangles.size() <= first_size + kMostTaken
              ? shared_boundaries({grown, part})
              : std::vector<PairCandidate>{};
      // Every shared edge welds: the strip gains only the part's corners off its rim.
      std::set<int> on_rim;
      for (const PairCandidate& pair : pairs)
        for (const Chain& chain : pair.chains) on_rim.insert(chain.y.begin(), chain.y.end());
      FlatStrip merged;
      if (pairs.empty() || !try_merge(grown, part, pairs[0].chains, options, merged) ||
          merged.vertices2d.size() !=
              grown.vertices2d.size() + part.vertices2d.size() - on_rim.size()) {
        refused.insert(corners_key(donor, tri));
        continue;
      }
      double perimeter = 0.0;
      for (const BoundaryEdge& e : merged.boundary)
        perimeter += (merged.vertices2d[e.v1] - merged.vertices2d[e.v0]).norm();
      const std::pair<double, double> score{least_narrow_first ? share_of(merged) : 0.0,
                                            perimeter * perimeter / flat_area(merged)};
      if (best_strip >= 0 && score >= best_score) continue;
      best = std::move(merged);
      best_rest = std::move(rest);
      best_strip = candidate.strip, best_score = score;
    }
    if (best_strip < 0) return false;
    grown = std::move(best);
    best_rest.boundary = flat_boundary(best_rest.triangles);
    donors[best_strip] = std::move(best_rest);
    share_left.erase(best_strip);
  }
  strips[index] = std::move(grown);
  for (auto& [s, rest] : donors) strips[s] = std::move(rest);
  return true;
}

}  // namespace papercraft::merge_detail
