// triangle_penetration and TriangleGrid2 against a brute force: the area of the two triangles'
// intersection, clipped exactly (Sutherland-Hodgman).
#include "core/overlap_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace papercraft {
namespace {

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double signed_area(const std::vector<Vec2>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    area += 0.5 * cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  return area;
}

// The area of the intersection of two triangles (either orientation); 0 where either has no
// interior (zero area).
double intersection_area(Triangle2 p, Triangle2 q) {
  if (cross2(p[1] - p[0], p[2] - p[0]) == 0 || cross2(q[1] - q[0], q[2] - q[0]) == 0) return 0.0;
  if (cross2(p[1] - p[0], p[2] - p[0]) < 0) std::swap(p[1], p[2]);
  if (cross2(q[1] - q[0], q[2] - q[0]) < 0) std::swap(q[1], q[2]);
  std::vector<Vec2> polygon(p.begin(), p.end());
  for (int e = 0; e < 3 && !polygon.empty(); ++e) {
    const Vec2 a = q[e], b = q[(e + 1) % 3];
    auto side = [&](const Vec2& x) { return cross2(b - a, x - a); };
    std::vector<Vec2> clipped;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2 &c = polygon[i], &d = polygon[(i + 1) % polygon.size()];
      const double sc = side(c), sd = side(d);
      if (sc >= 0) clipped.push_back(c);
      if ((sc >= 0) != (sd >= 0)) clipped.push_back(c + (d - c) * (sc / (sc - sd)));
    }
    polygon = std::move(clipped);
  }
  return polygon.size() < 3 ? 0.0 : std::abs(signed_area(polygon));
}

Triangle2 random_triangle(std::mt19937& random, double extent) {
  std::uniform_int_distribution<int> coordinate(0, 8);
  const double s = extent / 8.0;
  return {Vec2(coordinate(random) * s, coordinate(random) * s),
          Vec2(coordinate(random) * s, coordinate(random) * s),
          Vec2(coordinate(random) * s, coordinate(random) * s)};
}

// On a coarse lattice, where triangles often share edges and corners or only touch: a positive
// depth exactly where the interiors meet, as the exact intersection's area says.
TEST(Overlap2d, PenetrationIsPositiveExactlyWhereTheInteriorsMeet) {
  std::mt19937 random(99);
  int overlapping = 0, apart = 0;
  for (int round = 0; round < 20000; ++round) {
    const Triangle2 p = random_triangle(random, 4.0), q = random_triangle(random, 4.0);
    const double depth = triangle_penetration(p, q);
    const double area = intersection_area(p, q);
    EXPECT_EQ(depth > 0.0, triangle_penetration(q, p) > 0.0);
    if (area > 1e-9) {
      ++overlapping;
      EXPECT_GT(depth, 0.0) << "interiors overlap by " << area << " but depth " << depth;
    } else {
      ++apart;
      EXPECT_LE(depth, 1e-9) << "interiors meet nowhere but depth " << depth;
    }
  }
  EXPECT_GT(overlapping, 1000);
  EXPECT_GT(apart, 1000);
}

// The grid answers as testing every stored triangle would, small and large ones alike.
TEST(Overlap2d, GridAgreesWithTestingEveryTriangle) {
  std::mt19937 random(5);
  for (const double cell : {0.25, 1.0, 3.0}) {
    TriangleGrid2 grid(cell);
    std::vector<Triangle2> stored;
    for (int k = 0; k < 60; ++k) {
      const Triangle2 t = random_triangle(random, k % 10 == 0 ? 40.0 : 4.0);
      grid.insert(t);
      stored.push_back(t);
    }
    for (int query = 0; query < 2000; ++query) {
      const Triangle2 t = random_triangle(random, query % 7 == 0 ? 30.0 : 5.0);
      for (const double tolerance : {0.0, 0.1}) {
        bool expected = false;
        for (const Triangle2& s : stored)
          expected = expected || triangle_penetration(t, s) > tolerance;
        EXPECT_EQ(grid.overlaps(t, tolerance), expected) << "cell " << cell;
      }
    }
  }
}

TEST(Overlap2d, BadCellSizeThrows) {
  EXPECT_ANY_THROW(TriangleGrid2(0.0));
  EXPECT_ANY_THROW(TriangleGrid2(std::nan("")));
}

}  // namespace
}  // namespace papercraft
