#pragma once
// Test-only builders of small ruled strips and brute-force checks of flat strips for the
// unfold and merge tests. The overlap check is independent of the product's (separating
// axis) code: shrunken triangles tested for crossing edges and contained corners.
//
// Triangles are counter-clockwise seen from outside for polylines running counter-clockwise
// around +z with B above A (the outward side of a ring).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "core/strip.h"

namespace papercraft::unfold_testing {

/// Point i of a regular n-gon of radius r at height z; the same arguments give bit-identical
/// points, so strips built from it share their polylines exactly.
inline Vec3 circle_point(double r, int i, int n, double z) {
  double angle = 2.0 * M_PI * (((i % n) + n) % n) / n;
  return Vec3(r * std::cos(angle), r * std::sin(angle), z);
}

/// The ladder triangulation between polylines a and b of equal length: triangles
/// (a_i, a_i+1, b_i+1) and (a_i, b_i+1, b_i); closed wraps around.
inline RuledStrip ladder_strip(const std::vector<Vec3>& a, const std::vector<Vec3>& b,
                               bool closed) {
  RuledStrip strip;
  const int n = static_cast<int>(a.size());
  strip.mesh.vertices = a;
  strip.mesh.vertices.insert(strip.mesh.vertices.end(), b.begin(), b.end());
  strip.a_count = strip.b_count = n;
  strip.a_closed = strip.b_closed = closed;
  for (int i = 0; i < (closed ? n : n - 1); ++i) {
    int j = (i + 1) % n;
    strip.mesh.triangles.push_back({i, j, n + j});
    strip.mesh.triangles.push_back({i, n + j, n + i});
  }
  return strip;
}

/// Ring of a cylinder (or of a cone frustum when r0 != r1) between heights z0 and z1;
/// vertex i of A is circle point i + offset, so the strip opens at that angle.
inline RuledStrip ring_strip(double r0, double z0, double r1, double z1, int n, int offset = 0) {
  std::vector<Vec3> a, b;
  for (int i = 0; i < n; ++i) {
    a.push_back(circle_point(r0, i + offset, n, z0));
    b.push_back(circle_point(r1, i + offset, n, z1));
  }
  return ladder_strip(a, b, true);
}

/// A fan: triangles (a_i, a_i+1, apex); the apex is the single point of B.
inline RuledStrip fan_strip(const std::vector<Vec3>& a, const Vec3& apex, bool closed) {
  RuledStrip strip;
  const int n = static_cast<int>(a.size());
  strip.mesh.vertices = a;
  strip.mesh.vertices.push_back(apex);
  strip.a_count = n;
  strip.b_count = 1;
  strip.a_closed = closed;
  for (int i = 0; i < (closed ? n : n - 1); ++i)
    strip.mesh.triangles.push_back({i, (i + 1) % n, n});
  return strip;
}

/// A closed fan around the origin whose rim zigzags up and down: its corner angles at the
/// apex add up to far more than a full turn, so it cannot lie flat in one piece.
inline RuledStrip saddle_fan(int n) {
  std::vector<Vec3> a;
  for (int i = 0; i < n; ++i) {
    Vec3 p = circle_point(1.0, i, n, 0.0);
    p.z() = i % 2 ? 0.3 : -0.3;
    a.push_back(p);
  }
  return fan_strip(a, Vec3::Zero(), true);
}

inline double cross2(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

inline double signed_area(const FlatStrip& s, const Triangle& t) {
  return 0.5 *
         cross2(s.vertices2d[t[1]] - s.vertices2d[t[0]], s.vertices2d[t[2]] - s.vertices2d[t[0]]);
}

/// Every triangle keeps its 3D edge lengths (relative `tolerance`) and, having area, is
/// counter-clockwise in 2D with its 3D area (never mirrored).
inline void expect_isometric(const FlatStrip& s, double tolerance = 1e-9) {
  ASSERT_EQ(s.vertices2d.size(), s.vertices3d.size());
  for (const Triangle& t : s.triangles) {
    double longest = 0.0;
    for (int i = 0; i < 3; ++i)
      longest = std::max(longest, (s.vertices3d[t[(i + 1) % 3]] - s.vertices3d[t[i]]).norm());
    for (int i = 0; i < 3; ++i) {
      double l3 = (s.vertices3d[t[(i + 1) % 3]] - s.vertices3d[t[i]]).norm();
      double l2 = (s.vertices2d[t[(i + 1) % 3]] - s.vertices2d[t[i]]).norm();
      ASSERT_NEAR(l2, l3, tolerance * longest) << "strip " << s.id;
    }
    double area3 = 0.5 * (s.vertices3d[t[1]] - s.vertices3d[t[0]])
                             .cross(s.vertices3d[t[2]] - s.vertices3d[t[0]])
                             .norm();
    if (area3 > 1e-12 * longest * longest) {
      ASSERT_GT(signed_area(s, t), 0.0) << "mirrored triangle in strip " << s.id;
      ASSERT_NEAR(signed_area(s, t), area3, 1e-9 * longest * longest);
    }
  }
}

/// Whether the interiors of two 2D triangles intersect: both are shrunk towards their
/// centroid by `shrink` of their size (so touching ones come apart), then tested for
/// crossing edges or a corner inside the other.
inline bool interiors_intersect(std::array<Vec2, 3> p, std::array<Vec2, 3> q, double shrink) {
  for (auto* t : {&p, &q}) {
    Vec2 c = ((*t)[0] + (*t)[1] + (*t)[2]) / 3.0;
    for (Vec2& v : *t) v = c + (1.0 - shrink) * (v - c);
  }
  auto orient = [](const Vec2& a, const Vec2& b, const Vec2& c) { return cross2(b - a, c - a); };
  auto inside = [&](const std::array<Vec2, 3>& t, const Vec2& x) {
    double s = orient(t[0], t[1], t[2]) > 0 ? 1.0 : -1.0;
    for (int i = 0; i < 3; ++i)
      if (s * orient(t[i], t[(i + 1) % 3], x) <= 0) return false;
    return true;
  };
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec2 &a = p[i], &b = p[(i + 1) % 3], &c = q[j], &d = q[(j + 1) % 3];
      double d1 = orient(a, b, c), d2 = orient(a, b, d), d3 = orient(c, d, a), d4 = orient(c, d, b);
      if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return true;
    }
  }
  return inside(p, q[0]) || inside(q, p[0]);
}

/// Number of pairs of triangles (with area) of `s` whose interiors intersect; all pairs.
inline int count_overlapping_pairs(const FlatStrip& s, double shrink = 1e-6) {
  int count = 0;
  auto image = [&](const Triangle& t) {
    return std::array<Vec2, 3>{s.vertices2d[t[0]], s.vertices2d[t[1]], s.vertices2d[t[2]]};
  };
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    for (std::size_t j = i + 1; j < s.triangles.size(); ++j)
      if (signed_area(s, s.triangles[i]) != 0.0 && signed_area(s, s.triangles[j]) != 0.0 &&
          interiors_intersect(image(s.triangles[i]), image(s.triangles[j]), shrink))
        ++count;
  return count;
}

/// Sum over triangles of the 3D corner angle at `vertex`.
inline double angle_sum_at(const RuledStrip& strip, int vertex) {
  double sum = 0.0;
  for (const Triangle& t : strip.mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      if (t[i] != vertex) continue;
      Vec3 u = strip.mesh.vertices[t[(i + 1) % 3]] - strip.mesh.vertices[vertex];
      Vec3 v = strip.mesh.vertices[t[(i + 2) % 3]] - strip.mesh.vertices[vertex];
      sum += std::atan2(u.cross(v).norm(), u.dot(v));
    }
  return sum;
}

/// V - E + F of a flat strip (edges counted once per vertex pair).
inline int euler_characteristic(const FlatStrip& s) {
  std::vector<std::pair<int, int>> edges;
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i)
      edges.push_back({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return static_cast<int>(s.vertices2d.size()) - static_cast<int>(edges.size()) +
         static_cast<int>(s.triangles.size());
}

}  // namespace papercraft::unfold_testing
