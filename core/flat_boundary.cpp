#include "core/flat_boundary.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace papercraft {

std::vector<BoundaryEdge> flat_boundary(const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> directed;  // edge -> multiplicity
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];

  // Boundary edges in sorted order, each with its multiplicity so a repeated edge (two
  // triangles on the same side, a non-manifold input) is not lost.
  std::vector<std::pair<int, int>> edges;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    int reverse_count = reverse == directed.end() ? 0 : reverse->second;
    for (int k = 0; k < count - reverse_count; ++k) edges.push_back(edge);
  }

  std::multimap<int, int> outgoing;  // v0 -> index into edges
  for (int i = 0; i < static_cast<int>(edges.size()); ++i) outgoing.emplace(edges[i].first, i);
  std::vector<bool> used(edges.size(), false);
  std::vector<BoundaryEdge> result;
  result.reserve(edges.size());
  for (int start = 0; start < static_cast<int>(edges.size()); ++start) {
    int current = start;
    while (current >= 0 && !used[current]) {
      used[current] = true;
      BoundaryEdge edge;
      edge.v0 = edges[current].first;
      edge.v1 = edges[current].second;
      result.push_back(edge);
      current = -1;
      auto [begin, end] = outgoing.equal_range(edge.v1);
      for (auto it = begin; it != end; ++it) {
        if (!used[it->second]) {
          current = it->second;
          break;
        }
      }
    }
  }
  return result;
}

int first_clockwise_triangle(const std::vector<Vec2>& points,
                             const std::vector<Triangle>& triangles, double relative) {
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const Vec2& p : points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  const double negligible = points.empty() ? 0.0 : 1e-12 * (high - low).squaredNorm();
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const Triangle& tri = triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    const Vec2 &a = points[tri[0]], e1 = points[tri[1]] - a, e2 = points[tri[2]] - a;
    const double longest = std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
    if (longest > negligible && e1.x() * e2.y() - e1.y() * e2.x() < -relative * longest) return t;
  }
  return -1;
}

}  // namespace papercraft
