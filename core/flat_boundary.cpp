#include "core/flat_boundary.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/overlap_2d.h"

namespace papercraft {

std::vector<BoundaryEdge> flat_boundary(const std::vector<Triangle>& triangles) {
  // Every directed edge, sorted: a run of equal ones is an edge and its multiplicity. Sorted
  // vectors and binary search instead of maps: the merge calls this on every union it tries.
  using Edge = std::pair<int, int>;
  std::vector<Edge> directed;
  directed.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) directed.emplace_back(t[i], t[(i + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  auto multiplicity = [&](const Edge& edge) {
    const auto [begin, end] = std::equal_range(directed.begin(), directed.end(), edge);
    return static_cast<int>(end - begin);
  };

  // Boundary edges in sorted order, each with its multiplicity so a repeated edge (two
  // triangles on the same side, a non-manifold input) is not lost.
  std::vector<Edge> edges;
  for (std::size_t run = 0; run < directed.size();) {
    std::size_t next = run;
    while (next < directed.size() && directed[next] == directed[run]) ++next;
    const Edge& edge = directed[run];
    const int count = static_cast<int>(next - run);
    const int reverse_count = multiplicity({edge.second, edge.first});
    for (int k = 0; k < count - reverse_count; ++k) edges.push_back(edge);
    run = next;
  }

  // `edges` is sorted, so the edges leaving a vertex are a run of it, in index order.
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
      auto it = std::lower_bound(edges.begin(), edges.end(),
                                 Edge{edge.v1, std::numeric_limits<int>::min()});
      for (; it != edges.end() && it->first == edge.v1; ++it) {
        const auto index = static_cast<std::size_t>(it - edges.begin());
        if (!used[index]) {
          current = static_cast<int>(index);
          break;
        }
      }
    }
  }
  return result;
}

bool weld_keeps_lengths(const std::vector<Vec3>& points3d, const std::vector<Triangle>& triangles,
                        const std::vector<Vec2>& before, const std::vector<Vec2>& after) {
  for (const Triangle& t : triangles) {
    if (before[t[0]] == after[t[0]] && before[t[1]] == after[t[1]] && before[t[2]] == after[t[2]])
      continue;
    if (after[t[0]] == after[t[1]] || after[t[1]] == after[t[2]] || after[t[2]] == after[t[0]])
      continue;  // a triangle the weld drops
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double length3 = (points3d[a] - points3d[b]).norm();
      const double was = std::abs((before[a] - before[b]).norm() - length3);
      const double is = std::abs((after[a] - after[b]).norm() - length3);
      if (is > std::max(was, kWeldLengthTolerance * length3)) return false;
    }
  }
  return true;
}

double widest_corner_round_a_seam_vertex(const FlatStrip& a, const FlatStrip& b) {
  using Point = std::array<double, 3>;
  if (a.id == b.id) return 0.0;
  // The strip's vertices (by index: a strip may hold a point twice, at the two sides of a slit)
  // on two of its seam edges with `other`, by their 3D point.
  const auto inner = [](const FlatStrip& strip, int other) {
    std::map<int, int> ends;
    for (const BoundaryEdge& e : strip.boundary)
      if (e.kind == EdgeKind::Seam && e.neighbour_strip == other) ++ends[e.v0], ++ends[e.v1];
    std::map<Point, std::vector<int>> by_point;
    for (const auto& [v, count] : ends)
      if (count >= 2) {
        const Vec3& p = strip.vertices3d[v];
        by_point[{p.x(), p.y(), p.z()}].push_back(v);
      }
    return by_point;
  };
  // The corners of the strip's triangles at each vertex, summed, in radians.
  const auto corners = [](const FlatStrip& strip) {
    std::vector<double> sum(strip.vertices2d.size(), 0.0);
    for (const Triangle& t : strip.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec2 u = strip.vertices2d[t[(k + 1) % 3]] - strip.vertices2d[t[k]];
        const Vec2 w = strip.vertices2d[t[(k + 2) % 3]] - strip.vertices2d[t[k]];
        sum[t[k]] += std::abs(std::atan2(u.x() * w.y() - u.y() * w.x(), u.dot(w)));
      }
    return sum;
  };
  const auto in_a = inner(a, b.id), in_b = inner(b, a.id);
  if (in_a.empty() || in_b.empty()) return 0.0;
  const std::vector<double> corner_a = corners(a), corner_b = corners(b);
  double widest = 0.0;
  for (const auto& [point, a_vertices] : in_a) {
    auto it = in_b.find(point);
    if (it == in_b.end()) continue;
    // Where either holds the point twice, the pair of copies with the least sum.
    double least = std::numeric_limits<double>::infinity();
    for (int u : a_vertices)
      for (int v : it->second) least = std::min(least, corner_a[u] + corner_b[v]);
    widest = std::max(widest, least);
  }
  return widest * 180.0 / M_PI;
}

bool folds_flat_onto(const FlatStrip& a, const FlatStrip& b, double relative) {
  using Segment = std::array<double, 6>;
  const auto segment = [](const FlatStrip& strip, int from, int to) {
    const Vec3 &p = strip.vertices3d[from], &q = strip.vertices3d[to];
    return Segment{p.x(), p.y(), p.z(), q.x(), q.y(), q.z()};
  };
  std::map<Segment, const BoundaryEdge*> in_b;  // b's seam edges to a, by their 3D ends
  for (const BoundaryEdge& e : b.boundary)
    if (e.kind == EdgeKind::Seam && e.neighbour_strip == a.id) in_b[segment(b, e.v0, e.v1)] = &e;
  double length = 0.0;
  int edges = 0;
  for (const FlatStrip* strip : {&a, &b})
    for (const Triangle& t : strip->triangles)
      for (int k = 0; k < 3; ++k, ++edges)
        length += (strip->vertices2d[t[(k + 1) % 3]] - strip->vertices2d[t[k]]).norm();
  const double mean_edge = edges > 0 ? length / edges : 0.0;
  if (!(mean_edge > 0.0) || !std::isfinite(mean_edge)) return false;  // no triangle of area
  const double tolerance = relative * mean_edge;
  TriangleGrid2 grid(mean_edge);
  for (const Triangle& t : b.triangles)
    grid.insert({b.vertices2d[t[0]], b.vertices2d[t[1]], b.vertices2d[t[2]]});
  for (const BoundaryEdge& e : a.boundary) {
    if (e.kind != EdgeKind::Seam || e.neighbour_strip != b.id) continue;
    // b's edge runs the other way round its strip.
    auto partner = in_b.find(segment(a, e.v1, e.v0));
    if (partner == in_b.end()) continue;
    const Vec2 from = a.vertices2d[e.v0], to = a.vertices2d[e.v1];
    const Vec2 onto_from = b.vertices2d[partner->second->v1],
               onto_to = b.vertices2d[partner->second->v0];
    const double turn = std::atan2((onto_to - onto_from).y(), (onto_to - onto_from).x()) -
                        std::atan2((to - from).y(), (to - from).x());
    const Eigen::Rotation2Dd rotation(turn);
    const auto moved = [&](int v) -> Vec2 {
      return onto_from + rotation * (a.vertices2d[v] - from);
    };
    bool flat = true;
    for (const Triangle& t : a.triangles)
      if (grid.overlaps({moved(t[0]), moved(t[1]), moved(t[2])}, tolerance)) {
        flat = false;
        break;
      }
    if (flat) return true;
  }
  return false;
}

double flat_area(const FlatStrip& strip) {
  return flat_area(strip.vertices2d, strip.triangles);
}

double flat_area(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles) {
  double area = 0.0;
  for (const Triangle& t : triangles) {
    const Vec2 u = points[t[1]] - points[t[0]];
    const Vec2 v = points[t[2]] - points[t[0]];
    area += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
  }
  return area;
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
