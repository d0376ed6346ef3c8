// Parts of a flat strip's triangles: sub-strips, triangle keys and fans round a vertex.
#include "nodes/merge/strip_parts.h"

#include <algorithm>
#include <cstddef>

#include "core/flat_boundary.h"
#include "core/union_find.h"

namespace papercraft::merge_detail {

FlatStrip sub_strip(const FlatStrip& strip, const std::vector<Triangle>& chosen,
                    bool with_boundary) {
  FlatStrip part;
  part.id = strip.id;
  part.source_strip = strip.source_strip;
  const bool has_uvs = strip.uvs.size() == strip.vertices2d.size();
  std::vector<int> index(strip.vertices2d.size(), -1);
  for (Triangle t : chosen) {
    for (int& v : t) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(part.vertices2d.size());
        part.vertices2d.push_back(strip.vertices2d[v]);
        part.vertices3d.push_back(strip.vertices3d[v]);
        if (has_uvs) part.uvs.push_back(strip.uvs[v]);
      }
      v = index[v];
    }
    part.triangles.push_back(t);
  }
  if (with_boundary) part.boundary = flat_boundary(part.triangles);
  return part;
}

std::array<double, 9> corners_key(const FlatStrip& strip, const Triangle& t) {
  std::array<std::array<double, 3>, 3> c;
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = strip.vertices3d[t[k]];
    c[k] = {p.x(), p.y(), p.z()};
  }
  std::sort(c.begin(), c.end());
  return {c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]};
}

bool one_fan(const std::vector<Triangle>& triangles, int vertex) {
  std::vector<const Triangle*> fan;
  for (const Triangle& t : triangles)
    if (std::find(t.begin(), t.end(), vertex) != t.end()) fan.push_back(&t);
  UnionFind around(fan.size());
  for (std::size_t i = 0; i < fan.size(); ++i)
    for (std::size_t j = i + 1; j < fan.size(); ++j) {
      int common = 0;
      for (int a : *fan[i]) common += std::find(fan[j]->begin(), fan[j]->end(), a) != fan[j]->end();
      if (common >= 2) around.unite(i, j);
    }
  for (std::size_t i = 1; i < fan.size(); ++i)
    if (around.find(i) != around.find(0)) return false;
  return true;
}

}  // namespace papercraft::merge_detail
