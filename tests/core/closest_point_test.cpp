#include "core/closest_point.h"

#include <gtest/gtest.h>

#include <random>

#include "support/brute_force_hausdorff.h"

namespace papercraft {
namespace {

using testing::reference_triangle_distance;

// The result must be a point of the triangle given by its barycentric weights, and its
// distance must match the independent reference.
void expect_matches_reference(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                              double tolerance) {
  const TriangleClosestPoint r = closest_point_on_triangle(p, a, b, c);
  const double scale = 1.0 + (p - a).norm() + (b - a).norm() + (c - a).norm();
  EXPECT_NEAR(r.distance(), reference_triangle_distance(p, a, b, c), tolerance * scale)
      << "p " << p.transpose() << " a " << a.transpose() << " b " << b.transpose() << " c "
      << c.transpose();
  EXPECT_GE(r.barycentric.minCoeff(), -1e-12);
  EXPECT_NEAR(r.barycentric.sum(), 1.0, 1e-12);
  const Vec3 from_weights = r.barycentric[0] * a + r.barycentric[1] * b + r.barycentric[2] * c;
  EXPECT_NEAR((from_weights - r.point).norm(), 0.0, 1e-12 * scale);
  EXPECT_NEAR(r.squared_distance, (p - r.point).squaredNorm(), 1e-12 * scale * scale);
}

TEST(ClosestPoint, RegionsOfAUnitTriangle) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closest_point_on_triangle(Vec3(-1, -1, 0), a, b, c).point, a);
  EXPECT_EQ(closest_point_on_triangle(Vec3(2, -1, 0), a, b, c).point, b);
  EXPECT_EQ(closest_point_on_triangle(Vec3(-1, 3, 1), a, b, c).point, c);
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.5, -2, 0), a, b, c).point.isApprox(Vec3(0.5, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle(Vec3(1, 1, 0), a, b, c).point.isApprox(Vec3(0.5, 0.5, 0)));
  const TriangleClosestPoint inside = closest_point_on_triangle(Vec3(0.2, 0.3, 2), a, b, c);
  EXPECT_TRUE(inside.point.isApprox(Vec3(0.2, 0.3, 0)));
  EXPECT_DOUBLE_EQ(inside.distance(), 2.0);
  EXPECT_TRUE(inside.barycentric.isApprox(Vec3(0.5, 0.2, 0.3)));
}

TEST(ClosestPoint, SegmentTriangleAndPointTriangle) {
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  // (a, b, b), (a, a, b), (b, a, a): all are the segment [a, b].
  for (const auto& [x, y, z] :
       {std::array<Vec3, 3>{a, b, b}, std::array<Vec3, 3>{a, a, b}, std::array<Vec3, 3>{b, a, a}}) {
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(Vec3(1, 3, 4), x, y, z).distance(), 5.0);
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(Vec3(-3, 4, 0), x, y, z).distance(), 5.0);
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(Vec3(5, 0, 4), x, y, z).distance(), 5.0);
  }
  // Collinear with the middle corner last.
  EXPECT_DOUBLE_EQ(closest_point_on_triangle(Vec3(-1, 0, 0), a, b, Vec3(1, 0, 0)).distance(), 1.0);
  EXPECT_DOUBLE_EQ(closest_point_on_triangle(Vec3(3, 0, 0), Vec3(1, 0, 0), a, b).distance(), 1.0);
  // A point triangle.
  EXPECT_DOUBLE_EQ(closest_point_on_triangle(Vec3(3, 4, 0), a, a, a).distance(), 5.0);
}

TEST(ClosestPoint, RandomTrianglesMatchReference) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random_point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 a = random_point(), b = random_point(), c = random_point();
    const Vec3 p = 2.0 * random_point();
    expect_matches_reference(p, a, b, c, 1e-12);
  }
}

TEST(ClosestPoint, DegenerateAndSliverTrianglesMatchReference) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random_point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 a = random_point(), b = random_point(), p = 2.0 * random_point();
    const double t = 1.5 * u(rng);  // c on the line ab, inside or outside [a, b]
    const int kind = trial % 5;
    Vec3 c;
    if (kind == 0) c = a + t * (b - a);                          // collinear
    if (kind == 1) c = b;                                        // (a, b, b)
    if (kind == 2) c = a + t * (b - a) + 1e-9 * random_point();  // sliver
    if (kind == 3) c = a + t * (b - a) + 1e-5 * random_point();  // near the switch
    if (kind == 4) c = a + 1e-13 * random_point();               // a ~ c
    expect_matches_reference(p, a, b, c, 1e-9);
    expect_matches_reference(p, c, a, b, 1e-9);
    expect_matches_reference(p, b, c, a, 1e-9);
  }
}

TEST(ClosestPoint, Segment) {
  double t = -1.0;
  EXPECT_TRUE(closest_point_on_segment(Vec3(1, 1, 0), Vec3(0, 0, 0), Vec3(2, 0, 0), &t)
                  .isApprox(Vec3(1, 0, 0)));
  EXPECT_DOUBLE_EQ(t, 0.5);
  EXPECT_EQ(closest_point_on_segment(Vec3(5, 1, 0), Vec3(0, 0, 0), Vec3(2, 0, 0), &t),
            Vec3(2, 0, 0));
  EXPECT_DOUBLE_EQ(t, 1.0);
  EXPECT_EQ(closest_point_on_segment(Vec3(5, 1, 0), Vec3(1, 1, 1), Vec3(1, 1, 1), &t),
            Vec3(1, 1, 1));
  EXPECT_DOUBLE_EQ(t, 0.0);
}

}  // namespace
}  // namespace papercraft
