#pragma once
// Keys for the edges of an indexed triangle set, and the triangles around each edge: the
// adjacency that cuts, segmentation and layout all build from plain vertex indices.

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

/// Key of the directed edge a -> b (a in the high 32 bits). \pre a, b >= 0.
inline std::uint64_t directed_edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

/// Key of the undirected edge {a, b}: directed_edge_key(min, max), so (a, b) and (b, a) agree.
inline std::uint64_t undirected_edge_key(int a, int b) {
  return a < b ? directed_edge_key(a, b) : directed_edge_key(b, a);
}

/// The two vertex indices of a key, in the order the key holds them (for an undirected key:
/// the smaller one first).
inline std::pair<int, int> edge_key_vertices(std::uint64_t key) {
  return {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)};
}

/// Undirected edge -> indices of the triangles having it, in triangle order.
using EdgeTriangles = std::unordered_map<std::uint64_t, std::vector<int>>;

/// The triangles around every undirected edge of `triangles` (#F by 3 vertex indices >= 0).
inline EdgeTriangles edge_triangles(const std::vector<Triangle>& triangles) {
  EdgeTriangles map;
  map.reserve(3 * triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Triangle& t = triangles[f];
    for (int k = 0; k < 3; ++k) {
      map[undirected_edge_key(t[k], t[(k + 1) % 3])].push_back(static_cast<int>(f));
    }
  }
  return map;
}

}  // namespace papercraft
