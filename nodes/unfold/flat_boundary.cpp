#include "nodes/unfold/flat_boundary.h"

#include <algorithm>
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

}  // namespace papercraft
