#pragma once
// Synthetic flat strips for layout and export tests: grids of cells (rectangles, U shapes,
// long thin strips), annular arcs and the strips of a prism (a lateral band and two caps)
// whose seams, labels and 3D folds are known exactly.

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/strip.h"

namespace papercraft::testing {

/// Boundary edges of `triangles` with their left side inside, kind Open, in triangle order.
inline std::vector<BoundaryEdge> open_boundary(const std::vector<Triangle>& triangles) {
  std::vector<BoundaryEdge> boundary;
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      bool inner = false;
      for (const Triangle& u : triangles)
        for (int k = 0; k < 3; ++k)
          if (u[k] == b && u[(k + 1) % 3] == a) inner = true;
      if (!inner) boundary.push_back({a, b, EdgeKind::Open, -1, ""});
    }
  return boundary;
}

/// A grid of nx by ny cells of cell_w by cell_h model units (lower-left at the origin),
/// keeping the cells where keep(i, j); each cell split by its diagonal. Flat in 3D (z = 0).
/// Every boundary edge is Open.
inline FlatStrip cell_strip(int id, int nx, int ny, double cell_w, double cell_h,
                            const std::function<bool(int, int)>& keep = nullptr) {
  FlatStrip strip;
  strip.id = id;
  strip.source_strip = id;
  auto index = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      strip.vertices2d.emplace_back(i * cell_w, j * cell_h);
      strip.vertices3d.emplace_back(i * cell_w, j * cell_h, 0.0);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (keep && !keep(i, j)) continue;
      strip.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      strip.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  strip.boundary = open_boundary(strip.triangles);
  return strip;
}

/// Marks the boundary edges whose 2D midpoint satisfies `where` as seams with `label`.
inline void mark_seam(FlatStrip& strip, const std::string& label, int neighbour,
                      const std::function<bool(const Vec2&)>& where) {
  for (BoundaryEdge& e : strip.boundary) {
    const Vec2 mid = 0.5 * (strip.vertices2d[e.v0] + strip.vertices2d[e.v1]);
    if (where(mid)) {
      e.kind = EdgeKind::Seam;
      e.label = label;
      e.neighbour_strip = neighbour;
    }
  }
}

/// A flat annular arc: radii r0 < r1, from angle 0 to `sweep` radians in n cells.
inline FlatStrip arc_strip(int id, double r0, double r1, double sweep, int n) {
  FlatStrip strip;
  strip.id = id;
  strip.source_strip = id;
  for (int i = 0; i <= n; ++i) {
    const double a = sweep * i / n;
    for (double r : {r0, r1}) {
      strip.vertices2d.emplace_back(r * std::cos(a), r * std::sin(a));
      strip.vertices3d.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
    }
  }
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    strip.triangles.push_back({a, b, d});
    strip.triangles.push_back({a, d, c});
  }
  strip.boundary = open_boundary(strip.triangles);
  return strip;
}

/// The three strips of a prism over a counter-clockwise footprint (seen from +z) that is
/// star-shaped from its first point, `height` tall: the lateral band (id first_id, opened
/// at footprint point 0, seam "A" with itself), the top cap (first_id + 1, seam "T") and
/// the bottom cap (first_id + 2, seam "B"). Triangles are counter-clockwise seen from
/// outside and in 2D.
inline std::vector<FlatStrip> prism_strips(const std::vector<Vec2>& footprint, double height,
                                           int first_id) {
  const int n = static_cast<int>(footprint.size());
  FlatStrip band, top, bottom;
  band.id = band.source_strip = first_id;
  top.id = top.source_strip = first_id + 1;
  bottom.id = bottom.source_strip = first_id + 2;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const Vec2& p = footprint[i % n];
    if (i > 0) s += (p - footprint[i - 1]).norm();
    band.vertices2d.emplace_back(s, 0.0);  // bottom row: index 2i
    band.vertices3d.emplace_back(p.x(), p.y(), 0.0);
    band.vertices2d.emplace_back(s, height);  // top row: index 2i + 1
    band.vertices3d.emplace_back(p.x(), p.y(), height);
  }
  for (int i = 0; i < n; ++i) {
    const int b0 = 2 * i, t0 = 2 * i + 1, b1 = 2 * i + 2, t1 = 2 * i + 3;
    band.triangles.push_back({b0, b1, t1});
    band.triangles.push_back({b0, t1, t0});
    band.boundary.push_back({b0, b1, EdgeKind::Seam, first_id + 2, "B"});
    band.boundary.push_back({t1, t0, EdgeKind::Seam, first_id + 1, "T"});
  }
  band.boundary.push_back({2 * n, 2 * n + 1, EdgeKind::Seam, first_id, "A"});
  band.boundary.push_back({1, 0, EdgeKind::Seam, first_id, "A"});
  for (int i = 0; i < n; ++i) {
    const Vec2& p = footprint[i];
    top.vertices2d.push_back(p);
    top.vertices3d.emplace_back(p.x(), p.y(), height);
    bottom.vertices2d.emplace_back(p.x(), -p.y());
    bottom.vertices3d.emplace_back(p.x(), p.y(), 0.0);
  }
  for (int i = 1; i + 1 < n; ++i) {
    top.triangles.push_back({0, i, i + 1});
    bottom.triangles.push_back({0, i + 1, i});
  }
  for (int i = 0; i < n; ++i) {
    top.boundary.push_back({i, (i + 1) % n, EdgeKind::Seam, first_id, "T"});
    bottom.boundary.push_back({(i + 1) % n, i, EdgeKind::Seam, first_id, "B"});
  }
  return {band, top, bottom};
}

/// A square footprint of side `side` (a box), counter-clockwise.
inline std::vector<Vec2> square_footprint(double side) {
  return {Vec2(0, 0), Vec2(side, 0), Vec2(side, side), Vec2(0, side)};
}

/// An L-shaped footprint (one reflex corner, at index 3), counter-clockwise.
inline std::vector<Vec2> l_footprint(double side) {
  return {Vec2(0, 0),       Vec2(2 * side, 0),    Vec2(2 * side, side),
          Vec2(side, side), Vec2(side, 2 * side), Vec2(0, 2 * side)};
}

}  // namespace papercraft::testing
