// The shared boundaries of flat strips: the chains two strips glue, their single edges as
// hinges, and a strip's neighbours.
#include "nodes/merge/chains.h"

#include <algorithm>
#include <map>
#include <utility>

namespace papercraft::merge_detail {

std::array<double, 6> exact_key(const Vec3& p, const Vec3& q) {
  std::array<double, 3> a{p.x(), p.y(), p.z()}, b{q.x(), q.y(), q.z()};
  if (b < a) std::swap(a, b);
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}

std::set<std::array<double, 6>> rim_of(const FlatStrip& strip) {
  std::set<std::array<double, 6>> rim;
  for (const BoundaryEdge& e : strip.boundary)
    rim.insert(exact_key(strip.vertices3d[e.v0], strip.vertices3d[e.v1]));
  return rim;
}

std::vector<PairCandidate> shared_boundaries(const std::vector<FlatStrip>& strips, int with) {
  const std::set<std::array<double, 6>> rim =
      with >= 0 ? rim_of(strips[with]) : std::set<std::array<double, 6>>{};
  std::map<std::array<double, 6>, std::vector<std::pair<int, int>>> groups;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    for (int e = 0; e < static_cast<int>(strips[s].boundary.size()); ++e) {
      const BoundaryEdge& edge = strips[s].boundary[e];
      const auto key = exact_key(strips[s].vertices3d[edge.v0], strips[s].vertices3d[edge.v1]);
      if (with < 0 || rim.count(key)) groups[key].push_back({s, e});
    }
  // (x, y) -> glued edge pairs (edge of x, edge of y).
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> glued;
  for (const auto& [key, group] : groups) {
    for (std::size_t i = 0; i < group.size(); ++i) {
      for (std::size_t j = i + 1; j < group.size(); ++j) {
        auto [si, ei] = group[i];
        auto [sj, ej] = group[j];
        if (si == sj || (with >= 0 && si != with && sj != with)) continue;
        const BoundaryEdge& a = strips[si].boundary[ei];
        const BoundaryEdge& b = strips[sj].boundary[ej];
        if (strips[si].vertices3d[a.v0] != strips[sj].vertices3d[b.v1] ||
            strips[si].vertices3d[a.v1] != strips[sj].vertices3d[b.v0])
          continue;
        if (si < sj)
          glued[{si, sj}].push_back({ei, ej});
        else
          glued[{sj, si}].push_back({ej, ei});
      }
    }
  }

  std::vector<PairCandidate> result;
  for (auto& glued_pair : glued) {
    // Named references, not a structured binding: clang before 16 cannot capture one.
    const auto& strip_pair = glued_pair.first;
    auto& pairs = glued_pair.second;
    const FlatStrip& x = strips[strip_pair.first];
    const FlatStrip& y = strips[strip_pair.second];
    std::sort(pairs.begin(), pairs.end());
    const int n = static_cast<int>(pairs.size());
    // Successor of a glued pair: the next edge of X along its boundary, whose partner in
    // Y is the previous edge of Y (they share the Y vertex at the junction).
    std::multimap<int, int> by_x_start;  // X edge v0 -> pair index
    for (int k = 0; k < n; ++k) by_x_start.emplace(x.boundary[pairs[k].first].v0, k);
    std::vector<int> next(n, -1), previous_count(n, 0);
    for (int k = 0; k < n; ++k) {
      const BoundaryEdge& ex = x.boundary[pairs[k].first];
      const BoundaryEdge& ey = y.boundary[pairs[k].second];
      auto [begin, end] = by_x_start.equal_range(ex.v1);
      for (auto it = begin; it != end; ++it) {
        if (y.boundary[pairs[it->second].second].v1 != ey.v0 || previous_count[it->second] > 0)
          continue;
        next[k] = it->second;
        ++previous_count[it->second];
        break;
      }
    }
    PairCandidate candidate;
    candidate.x = strip_pair.first;
    candidate.y = strip_pair.second;
    std::vector<bool> used(n, false);
    auto walk = [&](int k) {
      Chain chain;
      chain.x.push_back(x.boundary[pairs[k].first].v0);
      chain.y.push_back(y.boundary[pairs[k].second].v1);
      while (k >= 0 && !used[k]) {
        used[k] = true;
        const BoundaryEdge& ex = x.boundary[pairs[k].first];
        chain.x.push_back(ex.v1);
        chain.y.push_back(y.boundary[pairs[k].second].v0);
        chain.length += (x.vertices3d[ex.v1] - x.vertices3d[ex.v0]).norm();
        k = next[k];
      }
      candidate.total_length += chain.length;
      candidate.chains.push_back(std::move(chain));
    };
    for (int k = 0; k < n; ++k)
      if (previous_count[k] == 0) walk(k);
    for (int k = 0; k < n; ++k)  // closed loops
      if (!used[k]) walk(k);
    result.push_back(std::move(candidate));
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const PairCandidate& a, const PairCandidate& b) {
                     return a.total_length > b.total_length;
                   });
  return result;
}

std::vector<Hinge> hinges_of(const std::vector<PairCandidate>& pairs,
                             const std::vector<FlatStrip>& strips,
                             const std::function<bool(const PairCandidate&)>& wanted) {
  std::vector<Hinge> hinges;
  for (int p = 0; p < static_cast<int>(pairs.size()); ++p) {
    if (!wanted(pairs[p])) continue;
    const FlatStrip& x = strips[pairs[p].x];
    for (const Chain& chain : pairs[p].chains)
      for (std::size_t i = 0; i + 1 < chain.x.size(); ++i) {
        Chain edge;
        edge.x = {chain.x[i], chain.x[i + 1]};
        edge.y = {chain.y[i], chain.y[i + 1]};
        edge.length = (x.vertices3d[chain.x[i + 1]] - x.vertices3d[chain.x[i]]).norm();
        const bool open = chain.x.front() != chain.x.back();
        hinges.push_back({p, std::move(edge), open && (i == 0 || i + 2 == chain.x.size())});
      }
  }
  std::stable_sort(hinges.begin(), hinges.end(),
                   [](const Hinge& a, const Hinge& b) { return a.edge.length > b.edge.length; });
  return hinges;
}

std::vector<int> strips_beside(const std::vector<FlatStrip>& strips, int index) {
  const FlatStrip& strip = strips[index];
  const std::set<std::array<double, 6>> rim = rim_of(strip);
  std::vector<int> around;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    if (s == index) continue;
    for (const BoundaryEdge& e : strips[s].boundary)
      if (rim.count(exact_key(strips[s].vertices3d[e.v0], strips[s].vertices3d[e.v1]))) {
        around.push_back(s);
        break;
      }
  }
  return around;
}

}  // namespace papercraft::merge_detail
