#pragma once
// A piece's cut lines in square buckets, for the clearance tests of label placement, and the
// search for leader lines that bend round a corner.

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {

/// True when segments a-b and c-d cross at a point inside both (touching does not count).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// True when q lies in the convex quad (on its edges included).
bool inside_convex(const Vec2& q, const std::array<Vec2, 4>& box);

/// A piece's cut lines in square buckets (4 mm, coarser on a huge piece), so a text box or a
/// leader line is tested against the lines near it only; and the search for leaders that bend:
/// breadth first on a square grid around a seam, stepping between neighbouring grid points
/// along moves that cross no cut line and no text, from points just off the seam; the first
/// grid point (fewest steps) whose text box passes a test ends it.
class LeaderRouter {
 public:
  /// `lines`: the cut lines (kept by reference); `step`: the search grid's spacing (mm).
  LeaderRouter(const std::vector<std::array<Vec2, 2>>& lines, double step);

  /// True when segment a-b crosses no cut line and no box of `taken`.
  bool clear(const Vec2& a, const Vec2& b, const std::vector<std::array<Vec2, 4>>& taken) const;

  /// True when no cut line crosses the convex quad.
  bool box_clear(const std::array<Vec2, 4>& box) const;

  /// The path from one of `starts` to the first grid point within `reach` of it where
  /// `box_ok(centre, start index)` holds, grid points inside a box of `taken` left out: the
  /// points of the path, start first, and the start's index; empty when none is found.
  template <class BoxOk>
  std::pair<std::vector<Vec2>, int> route(const std::vector<Vec2>& starts, double reach,
                                          const std::vector<std::array<Vec2, 4>>& taken,
                                          BoxOk box_ok) const {
    Box2 around;
    for (const Vec2& s : starts) around.add(s);
    const Vec2 origin = around.lo - Vec2::Constant(reach);
    const int n = static_cast<int>((around.hi.x() - around.lo.x() + 2 * reach) / step_) + 2;
    const int m = static_cast<int>((around.hi.y() - around.lo.y() + 2 * reach) / step_) + 2;
    auto point = [&](int node) { return Vec2(origin + step_ * Vec2(node % n, node / n)); };
    auto free = [&](const Vec2& q) {
      for (const auto& box : taken)
        if (inside_convex(q, box)) return false;
      return true;
    };
    std::vector<int> parent(static_cast<std::size_t>(n) * m, -2), source(parent.size(), -1);
    std::deque<int> queue;
    for (int k = 0; k < static_cast<int>(starts.size()); ++k) {
      const Vec2 g = (starts[k] - origin) / step_;
      for (int dx = 0; dx <= 1; ++dx)
        for (int dy = 0; dy <= 1; ++dy) {
          const int x = static_cast<int>(std::floor(g.x())) + dx;
          const int y = static_cast<int>(std::floor(g.y())) + dy;
          if (x < 0 || y < 0 || x >= n || y >= m) continue;
          const int node = y * n + x;
          if (parent[node] != -2 || !free(point(node)) || !clear(starts[k], point(node), taken))
            continue;
          parent[node] = -1;
          source[node] = k;
          queue.push_back(node);
        }
    }
    while (!queue.empty()) {
      const int node = queue.front();
      queue.pop_front();
      const Vec2 here = point(node);
      const int k = source[node];
      if ((here - starts[k]).norm() > reach) continue;
      if ((here - starts[k]).norm() >= 2.0 && box_ok(here, k)) {
        std::vector<Vec2> path{here};
        for (int at = parent[node]; at >= 0; at = parent[at]) path.push_back(point(at));
        path.push_back(starts[k]);
        std::reverse(path.begin(), path.end());
        return {path, k};
      }
      const int x = node % n, y = node / n;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= n || ny >= m) continue;
          const int next = ny * n + nx;
          if (parent[next] != -2) continue;
          const Vec2 there = point(next);
          if (!free(there) || !clear(here, there, taken)) continue;
          parent[next] = node;
          source[next] = k;
          queue.push_back(next);
        }
    }
    return {{}, -1};
  }

 private:
  std::pair<int, int> cell(const Vec2& p) const {
    const int c = static_cast<int>(std::floor((p.x() - bounds_.lo.x()) / bucket_));
    const int r = static_cast<int>(std::floor((p.y() - bounds_.lo.y()) / bucket_));
    return {std::clamp(c, 0, columns_ - 1), std::clamp(r, 0, rows_ - 1)};
  }

  const std::vector<std::array<Vec2, 2>>& lines_;
  double step_;
  double bucket_ = 4.0;
  Box2 bounds_;
  int columns_ = 0, rows_ = 0;
  std::vector<std::vector<int>> buckets_;
};

}  // namespace papercraft::layout_internal
