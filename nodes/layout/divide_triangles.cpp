// Dividing large flat triangles (see divide_triangles.h).
#include "nodes/layout/divide_triangles.h"

#include <map>
#include <tuple>
#include <utility>

namespace papercraft::layout_internal {
namespace {

// The divided strip: the old vertices keep their indices; the points inside each edge (by its
// unordered ends) and inside each triangle follow.
FlatStrip divide(const FlatStrip& strip, int n) {
  FlatStrip out;
  out.id = strip.id;
  out.source_strip = strip.source_strip;
  out.vertices3d = strip.vertices3d;
  out.vertices2d = strip.vertices2d;
  out.uvs = strip.uvs;
  const bool uvs = !strip.uvs.empty();
  auto add = [&](int a, int b, int c, double wa, double wb, double wc) {
    out.vertices3d.push_back(wa * strip.vertices3d[a] + wb * strip.vertices3d[b] +
                             wc * strip.vertices3d[c]);
    out.vertices2d.push_back(wa * strip.vertices2d[a] + wb * strip.vertices2d[b] +
                             wc * strip.vertices2d[c]);
    if (uvs) out.uvs.push_back(wa * strip.uvs[a] + wb * strip.uvs[b] + wc * strip.uvs[c]);
    return static_cast<int>(out.vertices3d.size()) - 1;
  };
  // Points 1..n-1 of edge (lo, hi), lo < hi, counted from lo: made once, shared by both
  // triangles of an inner edge.
  std::map<std::pair<int, int>, std::vector<int>> edge_points;
  auto edge_point = [&](int a, int b, int k) {  // point k of n from a towards b
    if (k == 0) return a;
    if (k == n) return b;
    // Counted from the end whose 3D point comes first (x, then y, then z): the other side of
    // a seam, whose ends are the same points under other indices, makes bit for bit the same
    // points, and the layout pairs seam edges by their points.
    const Vec3 &pa = strip.vertices3d[a], &pb = strip.vertices3d[b];
    const bool a_first =
        std::make_tuple(pa.x(), pa.y(), pa.z(), a) < std::make_tuple(pb.x(), pb.y(), pb.z(), b);
    const int lo = a_first ? a : b, hi = a_first ? b : a;
    auto [it, inserted] = edge_points.try_emplace({lo, hi});
    if (inserted)
      for (int j = 1; j < n; ++j)
        it->second.push_back(add(lo, hi, hi, 1.0 - double(j) / n, double(j) / n, 0.0));
    return it->second[(a == lo ? k : n - k) - 1];
  };
  for (const Triangle& t : strip.triangles) {
    // Grid point (i, j): i steps from t[0] towards t[1], j from t[0] towards t[2].
    std::vector<int> grid((n + 1) * (n + 1), -1);
    auto at = [&](int i, int j) -> int& { return grid[i * (n + 1) + j]; };
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        if (j == 0)
          at(i, j) = edge_point(t[0], t[1], i);
        else if (i == 0)
          at(i, j) = edge_point(t[0], t[2], j);
        else if (i + j == n)
          at(i, j) = edge_point(t[1], t[2], j);
        else
          at(i, j) = add(t[0], t[1], t[2], 1.0 - double(i + j) / n, double(i) / n, double(j) / n);
      }
    // Same orientation as t: (p, p + e1, p + e2) and (p + e1, p + e1 + e2, p + e2).
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        out.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n) out.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  for (const BoundaryEdge& e : strip.boundary)
    for (int k = 0; k < n; ++k) {
      BoundaryEdge part = e;
      part.v0 = edge_point(e.v0, e.v1, k);
      part.v1 = edge_point(e.v0, e.v1, k + 1);
      if (e.partner_edge >= 0) part.partner_edge = e.partner_edge * n + (n - 1 - k);
      out.boundary.push_back(std::move(part));
    }
  return out;
}

}  // namespace

std::vector<FlatStrip> divide_triangles(const std::vector<FlatStrip>& strips, int n) {
  if (n <= 1) return strips;
  std::vector<FlatStrip> out;
  out.reserve(strips.size());
  for (const FlatStrip& strip : strips) out.push_back(divide(strip, n));
  return out;
}

}  // namespace papercraft::layout_internal
