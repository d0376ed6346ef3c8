// drop_double_covered_triangles: a triangle printed by two pieces is taken out of the later
// one, which is split into its pieces where it falls apart.
#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>

#include "core/union_find.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/strip_parts.h"
#include "nodes/merge/validate.h"

namespace papercraft {

using merge_detail::corners_key;
using merge_detail::one_fan;
using merge_detail::sub_strip;
using merge_detail::validate;

std::vector<FlatStrip> drop_double_covered_triangles(std::vector<FlatStrip> strips,
                                                     std::size_t* dropped) {
  validate(strips, {});
  if (dropped) *dropped = 0;
  // Each triangle by its sorted 3D corners; every occurrence after the first is marked.
  std::set<std::array<double, 9>> seen;
  std::vector<std::vector<char>> twice(strips.size());
  bool any = false;
  for (std::size_t s = 0; s < strips.size(); ++s) {
    const FlatStrip& strip = strips[s];
    twice[s].assign(strip.triangles.size(), 0);
    for (std::size_t t = 0; t < strip.triangles.size(); ++t)
      if (!seen.insert(corners_key(strip, strip.triangles[t])).second) twice[s][t] = any = 1;
  }
  if (!any) return strips;
  int next_id = 0;
  for (const FlatStrip& strip : strips) next_id = std::max(next_id, strip.id + 1);
  std::vector<FlatStrip> result;
  result.reserve(strips.size());
  for (std::size_t s = 0; s < strips.size(); ++s) {
    FlatStrip& strip = strips[s];
    const std::size_t count =
        static_cast<std::size_t>(std::count(twice[s].begin(), twice[s].end(), 1));
    if (count == 0) {
      result.push_back(std::move(strip));
      continue;
    }
    std::vector<Triangle> kept;
    std::set<int> touched;  // corners of the triangles dropped
    for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
      if (!twice[s][t])
        kept.push_back(strip.triangles[t]);
      else
        touched.insert(strip.triangles[t].begin(), strip.triangles[t].end());
    }
    if (kept.empty()) {  // printed whole by the strips before it
      if (dropped) *dropped += count;
      continue;
    }
    // What is left, in its pieces joined across edges (a strip the triangles crossed falls
    // apart: each piece is a strip, the largest keeping the id, the others new ids). Kept only
    // where each piece is a surface at every corner the triangles dropped had (no two fans
    // meeting at a point).
    std::map<std::pair<int, int>, std::size_t> edge_of;
    UnionFind pieces(kept.size());
    for (std::size_t t = 0; t < kept.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = kept[t][k], b = kept[t][(k + 1) % 3];
        const auto [it, added] = edge_of.try_emplace({std::min(a, b), std::max(a, b)}, t);
        if (!added) pieces.unite(it->second, t);
      }
    std::map<std::size_t, std::vector<Triangle>> by_piece;
    for (std::size_t t = 0; t < kept.size(); ++t) by_piece[pieces.find(t)].push_back(kept[t]);
    bool surface = true;
    for (const auto& [root, triangles] : by_piece)
      for (int corner : touched) {
        const bool has = std::any_of(triangles.begin(), triangles.end(), [&](const Triangle& t) {
          return std::find(t.begin(), t.end(), corner) != t.end();
        });
        surface = surface && (!has || one_fan(triangles, corner));
      }
    if (!surface) {
      result.push_back(std::move(strip));
      continue;
    }
    std::vector<std::vector<Triangle>> ordered;
    for (auto& [root, triangles] : by_piece) ordered.push_back(std::move(triangles));
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const auto& x, const auto& y) { return x.size() > y.size(); });
    for (std::size_t k = 0; k < ordered.size(); ++k) {
      result.push_back(sub_strip(strip, ordered[k]));
      if (k > 0) result.back().id = next_id++;
    }
    if (dropped) *dropped += count;
  }
  return result;
}

}  // namespace papercraft
