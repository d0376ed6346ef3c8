#include "engine/hausdorff/sampled.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "engine/hausdorff/bounded.h"
#include "support/brute_force_hausdorff.h"

namespace papercraft {
namespace {

using testing::height_field;
using testing::reference_mesh_distance;

TriangleMesh square(double z) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, z), Vec3(1, 0, z), Vec3(1, 1, z), Vec3(0, 1, z)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(SampledHausdorff, ParallelSquaresAreExact) {
  const HausdorffResult r = sampled_hausdorff_distance(square(0), square(0.1));
  EXPECT_FALSE(r.certified);
  EXPECT_NEAR(r.lower, 0.1, 1e-12);
  EXPECT_EQ(r.upper, r.lower);
  EXPECT_TRUE(sampled_hausdorff_within(square(0), square(0.1), 0.101).within);
  EXPECT_FALSE(sampled_hausdorff_within(square(0), square(0.1), 0.099).within);
}

TEST(SampledHausdorff, FindsAnInteriorMaximumApproximately) {
  // Maximum 1 at the midpoint of a segment triangle, between two point triangles. The edge
  // samples come within the sample spacing of it but never exceed it.
  TriangleMesh segment;
  segment.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0)};
  segment.triangles = {{0, 1, 1}};
  TriangleMesh points;
  points.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0)};
  points.triangles = {{0, 0, 0}, {1, 1, 1}};
  SampledHausdorffOptions options;
  options.face_samples = 1000;
  const HausdorffResult r = sampled_hausdorff_distance(segment, points, options);
  EXPECT_LE(r.lower, 1.0 + 1e-12);
  EXPECT_GT(r.lower, 0.99);
  EXPECT_EQ(r.witness.side, 0);
  options.sample_edges = false;
  EXPECT_DOUBLE_EQ(sampled_hausdorff_distance(segment, points, options).lower, 0.0);
}

TEST(SampledHausdorff, NeverExceedsTheCertifiedUpperBound) {
  const TriangleMesh a = height_field(
      12, [](double x, double y) { return 0.1 * std::sin(5 * x) * std::cos(4 * y); }, 0.01, 1);
  const TriangleMesh b = height_field(
      7, [](double x, double y) { return 0.12 * std::sin(5 * x + 0.3) * std::cos(4 * y); }, 0.01,
      2);
  const HausdorffResult certified = certified_hausdorff_distance(a, b, 1e-5);
  SampledHausdorffOptions options;
  options.face_samples = 20000;
  const HausdorffResult sampled = sampled_hausdorff_distance(a, b, options);
  EXPECT_LE(sampled.lower, certified.upper * (1 + 1e-12));
  // Dense sampling gets close to the true value (here within 2%).
  EXPECT_GE(sampled.lower, 0.98 * certified.lower);
  EXPECT_GT(sampled.evaluations, 2 * options.face_samples);
  // The witness is a sample of the named side and its distance is exact.
  const TriangleMesh& target = sampled.witness.side == 0 ? b : a;
  EXPECT_NEAR(reference_mesh_distance(sampled.witness.point, target),
              sampled.witness.distance_lower_bound, 1e-12);
  EXPECT_EQ(sampled.witness.distance_lower_bound, sampled.lower);
}

TEST(SampledHausdorff, InvalidInputThrows) {
  EXPECT_THROW(sampled_hausdorff_within(TriangleMesh{}, square(0), 0.1), InvalidInputException);
  EXPECT_THROW(sampled_hausdorff_within(square(0), TriangleMesh{}, 0.1), InvalidInputException);
  EXPECT_THROW(sampled_hausdorff_within(square(0), square(0), 0.0), InvalidInputException);
  TriangleMesh bad = square(0);
  bad.triangles.push_back({0, 1, 7});
  EXPECT_THROW(sampled_hausdorff_distance(bad, square(0)), InvalidInputException);
}

}  // namespace
}  // namespace papercraft
