#include "nodes/segment/fuzzy.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "core/generate.h"
#include "nodes/segment/boundary_turning.h"
#include "tests/segment/partition_checks.h"

namespace papercraft {
namespace {

using testing::expect_boundaries_match;
using testing::expect_partition;
using testing::expect_same_parts;
using testing::tagged_mesh;

constexpr double kNeckRadius = 0.3;
constexpr double kNeckHalfLength = 0.75;

Mesh default_dumbbell() {
  DumbbellOptions options;
  options.handle_radius = kNeckRadius;
  options.handle_length = 2 * kNeckHalfLength;
  return tagged_mesh(dumbbell(options));
}

// A peanut: an icosphere (5120 faces) scaled radially by 1 + 0.5 cos(2 theta) (theta the polar
// angle), so two bulbs meet in a smooth concave waist of radius 0.5 at z = 0. Its triangulation
// follows no ring, so a boundary along mesh edges is a staircase there.
Mesh peanut() {
  TriangleMesh shape = sphere({1.0, 4});
  for (Vec3& p : shape.vertices) p *= 1.0 + 0.5 * (p.z() * p.z() - p.x() * p.x() - p.y() * p.y());
  return tagged_mesh(shape);
}

// Vertices on the boundary of some part (the input is closed, so these are the cut curves).
std::vector<Vec3> cut_vertices(const std::vector<Mesh>& parts) {
  std::vector<Vec3> points;
  for (const Mesh& part : parts)
    for (auto v : part.vertices())
      if (v.is_boundary()) points.push_back(to_eigen(part.point(v)));
  return points;
}

double mean_z(const Mesh& part) {
  double z = 0;
  for (auto v : part.vertices()) z += part.point(v)[2];
  return z / part.n_vertices();
}

void expect_cuts_in_the_neck(const std::vector<Mesh>& parts) {
  const std::vector<Vec3> points = cut_vertices(parts);
  ASSERT_FALSE(points.empty());
  for (const Vec3& p : points) {
    EXPECT_NEAR(std::hypot(p.x(), p.y()), kNeckRadius, 0.01 * kNeckRadius) << p.transpose();
    EXPECT_LE(std::abs(p.z()), kNeckHalfLength + 1e-9) << p.transpose();
  }
}

TEST(SegmentFuzzy, DumbbellSplitsIntoHandleAndTwoEnds) {
  const Mesh mesh = default_dumbbell();
  const std::vector<Mesh> parts = segment_fuzzy(mesh);
  ASSERT_EQ(parts.size(), 3u);
  expect_partition(mesh, parts);
  expect_boundaries_match(parts);
  expect_cuts_in_the_neck(parts);
  std::vector<double> centres;
  for (const Mesh& part : parts) centres.push_back(mean_z(part));
  std::sort(centres.begin(), centres.end());
  EXPECT_LT(centres[0], -kNeckHalfLength);
  EXPECT_NEAR(centres[1], 0.0, 1e-6);  // the handle, symmetric about z = 0
  EXPECT_GT(centres[2], kNeckHalfLength);
  for (const Mesh& part : parts) {
    // Ends are discs, the handle an open cylinder.
    const bool handle = std::abs(mean_z(part)) < 0.1;
    EXPECT_EQ(boundary_loops(part).size(), handle ? 2u : 1u);
  }
}

TEST(SegmentFuzzy, FixedTwoPartsCutsOnceInTheNeck) {
  const Mesh mesh = default_dumbbell();
  FuzzySegmentOptions options;
  options.parts = 2;
  const std::vector<Mesh> parts = segment_fuzzy(mesh, options);
  ASSERT_EQ(parts.size(), 2u);
  expect_partition(mesh, parts);
  expect_boundaries_match(parts);
  expect_cuts_in_the_neck(parts);
  EXPECT_EQ(boundary_loops(parts[0]).size(), 1u);
  EXPECT_EQ(boundary_loops(parts[1]).size(), 1u);
}

TEST(SegmentFuzzy, SmoothConvexShapeStaysWhole) {
  const Mesh mesh = tagged_mesh(sphere({1.0, 3}));
  const std::vector<Mesh> parts = segment_fuzzy(mesh);
  ASSERT_EQ(parts.size(), 1u);
  expect_partition(mesh, parts);
}

TEST(SegmentFuzzy, PeanutSplitsAtItsWaistWithASmoothCurve) {
  const Mesh mesh = peanut();
  FuzzySegmentOptions options;
  options.straighten = false;
  const std::vector<Mesh> jagged = segment_fuzzy(mesh, options);
  options.straighten = true;
  const std::vector<Mesh> smooth = segment_fuzzy(mesh, options);
  ASSERT_EQ(jagged.size(), 2u);
  ASSERT_EQ(smooth.size(), 2u);
  expect_partition(mesh, jagged);
  expect_partition(mesh, smooth);
  expect_boundaries_match(jagged);
  expect_boundaries_match(smooth);
  EXPECT_LT(mean_z(smooth[0]) * mean_z(smooth[1]), 0.0);  // one bulb each
  for (const Vec3& p : cut_vertices(smooth)) {
    EXPECT_LT(std::abs(p.z()), 0.1) << p.transpose();
    EXPECT_NEAR(p.norm(), 0.5, 0.02) << p.transpose();
  }
  const double before = boundary_turning_per_length(jagged);
  const double after = boundary_turning_per_length(smooth);
  std::printf("peanut: turning per length %.3f before, %.3f after straightening\n", before, after);
  // A circle of radius 0.5 would score 2; what is left is the faceting of the surface itself.
  EXPECT_LT(after, 0.5 * before);
}

TEST(SegmentFuzzy, StraighteningLeavesCutsAlongCreasesAlone) {
  // The minimum cut finds the dumbbell's concave creases, exact circles already; moving the
  // cut off a crease would leave a fold inside a part.
  const Mesh mesh = default_dumbbell();
  FuzzySegmentOptions options;
  options.straighten = false;
  const std::vector<Mesh> raw = segment_fuzzy(mesh, options);
  ASSERT_EQ(raw.size(), 3u);
  expect_partition(mesh, raw);
  expect_boundaries_match(raw);
  expect_cuts_in_the_neck(raw);
  for (const Vec3& p : cut_vertices(raw)) EXPECT_NEAR(std::abs(p.z()), kNeckHalfLength, 1e-12);
  options.straighten = true;
  const std::vector<Mesh> smooth = segment_fuzzy(mesh, options);
  expect_same_parts(raw, smooth);
  std::printf("dumbbell: turning per length %.4f before, %.4f after straightening\n",
              boundary_turning_per_length(raw), boundary_turning_per_length(smooth));
}

TEST(SegmentFuzzy, CarriesAndInterpolatesTextureCoordinates) {
  Mesh mesh = peanut();
  mesh.request_vertex_texcoords2D();
  for (auto v : mesh.vertices())
    mesh.set_texcoord2D(v, OpenMesh::Vec2d(mesh.point(v)[0], mesh.point(v)[2]));
  const std::vector<Mesh> parts = segment_fuzzy(mesh);
  ASSERT_GE(parts.size(), 2u);
  int inserted = 0;
  for (const Mesh& part : parts) {
    ASSERT_TRUE(part.has_vertex_texcoords2D());
    OpenMesh::VPropHandleT<int> input_vertex;
    ASSERT_TRUE(part.get_property_handle(input_vertex, kInputVertexProperty));
    for (auto v : part.vertices()) {
      // Linear in the position, so interpolation along an edge reproduces it.
      const OpenMesh::Vec2d expected(part.point(v)[0], part.point(v)[2]);
      EXPECT_LT((part.texcoord2D(v) - expected).norm(), 1e-12);
      inserted += part.property(input_vertex, v) < 0;
    }
  }
  EXPECT_GT(inserted, 0);
}

TEST(SegmentFuzzy, SameResultWithOneAndTwoThreads) {
  for (const Mesh& mesh : {default_dumbbell(), peanut()}) {
    std::vector<Mesh> one, two;
    {
      tbb::global_control control(tbb::global_control::max_allowed_parallelism, 1);
      one = segment_fuzzy(mesh);
    }
    {
      tbb::global_control control(tbb::global_control::max_allowed_parallelism, 2);
      two = segment_fuzzy(mesh);
    }
    expect_same_parts(one, two);
  }
}

TEST(SegmentFuzzy, RejectsBadInput) {
  const Mesh mesh = default_dumbbell();
  auto expect_rejected = [&](auto change) {
    FuzzySegmentOptions options;
    change(options);
    EXPECT_THROW(segment_fuzzy(mesh, options), InvalidInputException);
  };
  expect_rejected([](FuzzySegmentOptions& o) { o.parts = 1; });
  expect_rejected([](FuzzySegmentOptions& o) { o.parts = -1; });
  expect_rejected([](FuzzySegmentOptions& o) { o.max_depth = 0; });
  expect_rejected([](FuzzySegmentOptions& o) { o.angular_weight = 1.5; });
  expect_rejected([](FuzzySegmentOptions& o) { o.fuzzy_epsilon = 0.5; });
  expect_rejected([](FuzzySegmentOptions& o) { o.straighten_width = 0; });
  expect_rejected([](FuzzySegmentOptions& o) { o.min_area_fraction = -0.1; });
  expect_rejected([](FuzzySegmentOptions& o) { o.alternatives = {{2.0, {}, {}}}; });
  expect_rejected([](FuzzySegmentOptions& o) { o.alternatives = {{{}, {}, 0.7}}; });
  EXPECT_THROW(segment_fuzzy(Mesh()), InvalidInputException);
}

TEST(SegmentFuzzy, ParsesAlternatives) {
  const FuzzyAlternative both = parse_fuzzy_alternative(" angular_weight=0.5  fuzzy_epsilon=0.2 ");
  EXPECT_EQ(both.angular_weight, 0.5);
  EXPECT_EQ(both.fuzzy_epsilon, 0.2);
  EXPECT_FALSE(both.convex_eta.has_value());
  EXPECT_EQ(parse_fuzzy_alternative("convex_eta=0.3").convex_eta, 0.3);
  for (const char* bad : {"", "angular_weight", "angular_weight=", "angular_weight=0.5x",
                          "angular_weight=half", "depth=4", "=0.5"}) {
    EXPECT_THROW(parse_fuzzy_alternative(bad), InvalidInputException) << bad;
  }
}

}  // namespace
}  // namespace papercraft
