// convex_hull (nodes/layout/polygon_2d.h) against the definition of a hull: its corners are
// input points, it turns left at every corner, and no input point lies outside it. Those three
// fix the corners, so the filter that drops inner points before the sort cannot change them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {
namespace {

void expect_hull_of(const std::vector<Vec2>& points, const std::vector<Vec2>& hull) {
  ASSERT_GE(hull.size(), 3u);
  double extent = 0;
  for (const Vec2& p : points) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double eps = 1e-12 * extent * extent;
  for (const Vec2& corner : hull)
    EXPECT_NE(std::find(points.begin(), points.end(), corner), points.end())
        << "corner " << corner.transpose() << " is no input point";
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    const Vec2& c = hull[(i + 2) % hull.size()];
    EXPECT_GT(cross(b - a, c - b), eps) << "no left turn at corner " << (i + 1) % hull.size();
    for (const Vec2& p : points)
      EXPECT_GE(cross(b - a, p - a), -eps) << p.transpose() << " lies outside edge " << i;
  }
}

TEST(ConvexHull, RandomCloudsInDiscsSquaresAndThinBands) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE(trial);
    const int n = 3 + trial * 17;
    const double squash = trial % 3 == 2 ? 1e-3 : 1.0;  // a thin band: few points are inner
    std::vector<Vec2> points;
    while (static_cast<int>(points.size()) < n) {
      const Vec2 p(unit(random), squash * unit(random));
      if (trial % 3 == 0 && p.x() * p.x() + p.y() * p.y() > 1) continue;  // a disc
      points.push_back(p * 50.0 + Vec2(120.0, -30.0));
    }
    expect_hull_of(points, convex_hull(points));
  }
}

TEST(ConvexHull, CollinearAndRepeatedPointsLeaveOnlyCorners) {
  // A 20 x 20 grid, each point three times (a piece's points come once per triangle): the hull
  // is the square's four corners, the points along its sides dropped.
  std::vector<Vec2> points;
  for (int copy = 0; copy < 3; ++copy)
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j) points.emplace_back(0.5 * i, 0.5 * j);
  const std::vector<Vec2> hull = convex_hull(points);
  ASSERT_EQ(hull.size(), 4u);
  expect_hull_of(points, hull);
  EXPECT_EQ(hull.front(), Vec2(0.0, 0.0));  // from the lowest x, then the lowest y
  EXPECT_DOUBLE_EQ(std::abs(signed_area(hull)), 9.5 * 9.5);
}

TEST(ConvexHull, RegularPolygonWithItsCentreKeepsEveryCorner) {
  // Every point of a circle is a corner: the filter must keep them all, however many there are.
  for (int n : {5, 31, 32, 33, 400}) {
    SCOPED_TRACE(n);
    std::vector<Vec2> points{Vec2(3.0, 4.0)};
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * k / n;
      points.emplace_back(3.0 + 10.0 * std::cos(angle), 4.0 + 10.0 * std::sin(angle));
    }
    const std::vector<Vec2> hull = convex_hull(points);
    EXPECT_EQ(static_cast<int>(hull.size()), n);
    expect_hull_of(points, hull);
  }
}

}  // namespace
}  // namespace papercraft::layout_internal
