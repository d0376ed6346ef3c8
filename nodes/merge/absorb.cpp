// A crumb taken apart into its triangles, each hinged onto a neighbour over one of its edges,
// kept where every triangle finds a place and at most one inner edge is opened.
#include "nodes/merge/absorb.h"

#include <array>
#include <map>
#include <utility>

#include "nodes/merge/chains.h"
#include "nodes/merge/rigid_join.h"
#include "nodes/merge/strip_parts.h"

namespace papercraft::merge_detail {

bool absorb_by_triangles(std::vector<FlatStrip>& strips, int small, const MergeOptions& options) {
  constexpr std::size_t kMostTriangles = 64;
  constexpr int kMostOpened = 1;
  const FlatStrip& crumb = strips[small];
  if (crumb.triangles.size() < 2 || crumb.triangles.size() > kMostTriangles) return false;
  // Only the crumb's neighbours (a boundary edge on its rim) can take its triangles: they
  // and the triangles are worked on apart from the other strips, then put back.
  const std::vector<int> around = strips_beside(strips, small);
  if (around.empty()) return false;
  // trial: the neighbours at 0..n-1, then the triangles not yet taken. A triangle taken is
  // welded into the neighbour (the lower index keeps its place and id) and erased, so the
  // neighbours never move and the rest of `trial` is always the triangles left.
  const int n = static_cast<int>(around.size());
  std::vector<FlatStrip> trial;
  trial.reserve(around.size() + crumb.triangles.size());
  for (int s : around) trial.push_back(strips[s]);
  for (const Triangle& t : crumb.triangles) trial.push_back(sub_strip(crumb, {t}));
  std::vector<bool> touched(around.size(), false);  // neighbours that took a triangle
  while (static_cast<int>(trial.size()) > n) {
    const std::vector<PairCandidate> pairs = shared_boundaries(trial);
    // A neighbour (x, the lower index) and a triangle (y).
    const auto hinges = hinges_of(
        pairs, trial, [&](const PairCandidate& pair) { return pair.x < n && pair.y >= n; });
    bool taken = false;
    for (const Hinge& hinge : hinges) {
      const PairCandidate& pair = pairs[hinge.pair];
      FlatStrip merged;
      if (!try_merge(trial[pair.x], trial[pair.y], {hinge.edge}, options, merged)) continue;
      touched[pair.x] = true;
      trial[pair.x] = std::move(merged);
      trial.erase(trial.begin() + pair.y);
      taken = true;
      break;
    }
    if (!taken) return false;
  }
  // Each edge between two of the crumb's triangles that the plane no longer joins is one more
  // seam to glue (often a tiny one in a notch, with no room for a tab): at most one.
  std::map<std::array<double, 6>, int> inner;  // the crumb's inner edges
  for (const Triangle& t : crumb.triangles)
    for (int k = 0; k < 3; ++k)
      ++inner[exact_key(crumb.vertices3d[t[k]], crumb.vertices3d[t[(k + 1) % 3]])];
  int opened = 0;
  for (const auto& [key, count] : inner) opened += count > 1;
  for (int i = 0; i < n; ++i) {
    if (!touched[i]) continue;
    const FlatStrip& strip = trial[i];
    std::map<std::pair<int, int>, int> uses;
    for (const Triangle& t : strip.triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        ++uses[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& [edge, count] : uses) {
      if (count < 2) continue;
      auto it = inner.find(exact_key(strip.vertices3d[edge.first], strip.vertices3d[edge.second]));
      if (it != inner.end() && it->second > 1) {
        it->second = 0;  // still joined in the plane
        --opened;
      }
    }
  }
  if (opened > kMostOpened) return false;
  for (int i = 0; i < n; ++i) strips[around[i]] = std::move(trial[i]);
  strips.erase(strips.begin() + small);
  return true;
}

}  // namespace papercraft::merge_detail
