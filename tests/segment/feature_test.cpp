#include "nodes/segment/feature.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <set>

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

// Normal of a planar part (the first face's); fails if any face deviates.
Vec3 plane_normal(const Mesh& part) {
  Mesh copy = part;
  copy.request_face_normals();
  copy.update_face_normals();
  const Vec3 normal = to_eigen(copy.normal(*copy.faces_begin()));
  for (auto f : copy.faces()) EXPECT_NEAR(to_eigen(copy.normal(f)).dot(normal), 1.0, 1e-12);
  return normal;
}

TEST(SegmentFeature, BoxSplitsIntoItsSixFlatFaces) {
  const BoxOptions options{2.0, 1.5, 1.0, 8, 6, 4};
  const Mesh mesh = tagged_mesh(box(options));
  const std::vector<Mesh> parts = segment_feature(mesh);
  ASSERT_EQ(parts.size(), 6u);
  expect_partition(mesh, parts);
  expect_boundaries_match(parts);
  std::vector<int> faces_along_axis(3, 0);  // faces of the parts whose normal is that axis
  for (const Mesh& part : parts) {
    const Vec3 normal = plane_normal(part);
    int axis = 0;
    normal.cwiseAbs().maxCoeff(&axis);
    EXPECT_NEAR(std::abs(normal[axis]), 1.0, 1e-12);
    faces_along_axis[axis] += static_cast<int>(part.n_faces());
    EXPECT_EQ(boundary_loops(part).size(), 1u);
    EXPECT_EQ(euler_characteristic(part), 1);  // a disc
  }
  const int nx = options.divisions_x, ny = options.divisions_y, nz = options.divisions_z;
  EXPECT_EQ(faces_along_axis[0], 2 * 2 * ny * nz);
  EXPECT_EQ(faces_along_axis[1], 2 * 2 * nx * nz);
  EXPECT_EQ(faces_along_axis[2], 2 * 2 * nx * ny);
  // Straight cut curves meeting three at a corner do not turn anywhere.
  EXPECT_EQ(boundary_turning_per_length(parts), 0.0);
}

TEST(SegmentFeature, CappedCylinderSplitsIntoSideAndTwoCaps) {
  const CappedCylinderOptions options{1.0, 2.0, 32, 8, 4};
  const Mesh mesh = tagged_mesh(capped_cylinder(options));
  const std::vector<Mesh> parts = segment_feature(mesh);
  ASSERT_EQ(parts.size(), 3u);
  expect_partition(mesh, parts);
  expect_boundaries_match(parts);
  std::vector<std::size_t> counts;
  for (const Mesh& part : parts) counts.push_back(part.n_faces());
  std::sort(counts.begin(), counts.end());
  const std::size_t cap = options.segments * (2 * options.cap_rings - 1);
  EXPECT_EQ(counts, (std::vector<std::size_t>{cap, cap, 2u * options.segments * options.rings}));
  // Two rims, regular 32-gons of radius 1: turning 2 pi over a perimeter just below 2 pi.
  const double perimeter = 2 * options.segments * std::sin(M_PI / options.segments);
  EXPECT_NEAR(boundary_turning_per_length(parts), 2 * M_PI / perimeter, 1e-9);
}

TEST(SegmentFeature, ThresholdAboveTheCreasesKeepsOnePart) {
  const Mesh mesh = tagged_mesh(box({2.0, 1.5, 1.0, 4, 3, 2}));
  FeatureSegmentOptions options;
  options.angle_degrees = 95;
  const std::vector<Mesh> parts = segment_feature(mesh, options);
  ASSERT_EQ(parts.size(), 1u);
  expect_partition(mesh, parts);
  EXPECT_EQ(euler_characteristic(parts[0]), 2);
}

// Height field z = sqrt(x^2 + w(y)^2), w = max(0, y - 0.5) / 2, over [-1, 1] x [0, 1] (20 x 10
// cells): a valley whose crease along x = 0 is sharp (> 40 degrees) from the boundary y = 0 up
// to y = 0.7 and rounded beyond, so the chain of sharp edges ends 0.3 short of y = 1.
Mesh valley_with_gap() {
  TriangleMesh grid;
  const int columns = 20, rows = 10;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const double x = -1.0 + 2.0 * i / columns, y = 1.0 * j / rows;
      const double w = 0.5 * std::max(0.0, y - 0.5);
      const double z = std::sqrt(x * x + w * w);
      grid.vertices.emplace_back(x, y, z);
    }
  }
  auto index = [&](int i, int j) { return j * (columns + 1) + i; };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      grid.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      grid.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return tagged_mesh(grid);
}

TEST(SegmentFeature, ChainEndingShortOfTheBoundaryIsClosedOnlyWithinTheGap) {
  const Mesh mesh = valley_with_gap();
  FeatureSegmentOptions options;
  options.close_gap_fraction = 0;
  EXPECT_EQ(segment_feature(mesh, options).size(), 1u);
  options.close_gap_fraction = 0.05;  // of a diagonal of 2.45: 0.12, too short
  EXPECT_EQ(segment_feature(mesh, options).size(), 1u);
  options.close_gap_fraction = 0.2;  // 0.49
  const std::vector<Mesh> parts = segment_feature(mesh, options);
  ASSERT_EQ(parts.size(), 2u);
  expect_partition(mesh, parts);
  // The two slopes, split along x = 0 all the way from y = 0 to y = 1.
  std::set<testing::PointKey> first;
  for (auto v : parts[0].vertices()) first.insert(testing::key_of(parts[0].point(v)));
  std::set<double> shared_y;
  for (auto v : parts[1].vertices()) {
    if (!first.count(testing::key_of(parts[1].point(v)))) continue;
    EXPECT_EQ(parts[1].point(v)[0], 0.0);
    shared_y.insert(parts[1].point(v)[1]);
  }
  EXPECT_EQ(shared_y.size(), 11u);
  EXPECT_NEAR(surface_area(parts[0]), surface_area(parts[1]), 1e-3 * surface_area(mesh));
}

TEST(SegmentFeature, SmallRegionsAreMergedIntoTheirNeighbour) {
  // Faces 2 x 1, 2 x 0.5 and 1 x 0.5, two of each: total area 7.
  const Mesh mesh = tagged_mesh(box({2.0, 1.0, 0.5, 4, 2, 1}));
  FeatureSegmentOptions options;
  const double total = surface_area(mesh);
  options.min_area_fraction = 0.6 / total;  // the two 1 x 0.5 ends go
  std::vector<Mesh> parts = segment_feature(mesh, options);
  ASSERT_EQ(parts.size(), 4u);
  expect_partition(mesh, parts);
  expect_boundaries_match(parts);
  for (const Mesh& part : parts) EXPECT_GE(surface_area(part), 0.6 - 1e-12);
  options.min_area_fraction = 0.99;
  parts = segment_feature(mesh, options);
  ASSERT_EQ(parts.size(), 1u);
  expect_partition(mesh, parts);
}

TEST(SegmentFeature, CarriesTextureCoordinates) {
  Mesh mesh = tagged_mesh(capped_cylinder({1.0, 2.0, 16, 4, 2}));
  mesh.request_vertex_texcoords2D();
  for (auto v : mesh.vertices())
    mesh.set_texcoord2D(v, OpenMesh::Vec2d(mesh.point(v)[0], mesh.point(v)[2]));
  for (const Mesh& part : segment_feature(mesh)) {
    ASSERT_TRUE(part.has_vertex_texcoords2D());
    for (auto v : part.vertices()) {
      EXPECT_EQ(part.texcoord2D(v), OpenMesh::Vec2d(part.point(v)[0], part.point(v)[2]));
    }
  }
}

TEST(SegmentFeature, SameResultWithOneAndTwoThreads) {
  const Mesh mesh = tagged_mesh(capped_cylinder());
  std::vector<Mesh> one, two;
  {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, 1);
    one = segment_feature(mesh);
  }
  {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, 2);
    two = segment_feature(mesh);
  }
  expect_same_parts(one, two);
}

TEST(SegmentFeature, RejectsBadInput) {
  const Mesh mesh = tagged_mesh(box());
  FeatureSegmentOptions options;
  options.angle_degrees = 0;
  EXPECT_THROW(segment_feature(mesh, options), InvalidInputException);
  options = {};
  options.min_area_fraction = 1;
  EXPECT_THROW(segment_feature(mesh, options), InvalidInputException);
  options = {};
  options.close_gap_fraction = -1;
  EXPECT_THROW(segment_feature(mesh, options), InvalidInputException);
  EXPECT_THROW(segment_feature(Mesh()), InvalidInputException);
}

}  // namespace
}  // namespace papercraft
