#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "core/errors.h"
#include "core/generate.h"
#include "engine/refine/refine.h"
#include "nodes/segment/fuzzy.h"
#include "nodes/segment/parts_ply.h"
#include "tests/segment/partition_checks.h"

namespace papercraft {
namespace {

using testing::expect_boundaries_match;
using testing::expect_partition;
using testing::expect_same_parts;
using testing::tagged_mesh;

TEST(StripCount, AnOpenCylinderIsOneStrip) {
  // A cylinder is ruled: one strip between its two boundary circles.
  const Mesh mesh = tagged_mesh(open_cylinder());
  EXPECT_EQ(count_strips(mesh, at_tolerance({}, 0.01), 100), 1);
}

TEST(StripCount, ASphereNeedsSeveralAndTheCapHolds) {
  const Mesh mesh = tagged_mesh(sphere({1.0, 3}));
  const int strips = count_strips(mesh, at_tolerance({}, 0.02), 1000);
  EXPECT_GT(strips, 1);
  EXPECT_LE(strips, 1000);
  EXPECT_EQ(count_strips(mesh, at_tolerance({}, 0.02), strips), strips);
  EXPECT_EQ(count_strips(mesh, at_tolerance({}, 0.02), strips - 1), strips);  // cap + 1
  EXPECT_EQ(count_strips(mesh, at_tolerance({}, 0.02), 0), 1);
}

FuzzySegmentOptions judged(double tolerance) {
  FuzzySegmentOptions options;
  options.strip_tolerance = tolerance;
  return options;
}

TEST(SegmentFuzzyByStrips, SphereStaysWhole) {
  const Mesh mesh = tagged_mesh(sphere({1.0, 3}));
  const std::vector<Mesh> parts = segment_fuzzy(mesh, judged(0.04));
  ASSERT_EQ(parts.size(), 1u);
  expect_partition(mesh, parts);
}

TEST(SegmentFuzzyByStrips, DumbbellPartitionIsValidAndThreadIndependent) {
  DumbbellOptions shape;
  shape.handle_radius = 0.3;
  shape.handle_length = 1.5;
  const Mesh mesh = tagged_mesh(dumbbell(shape));
  std::vector<Mesh> one, two;
  {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, 1);
    one = segment_fuzzy(mesh, judged(0.08));
  }
  {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, 2);
    two = segment_fuzzy(mesh, judged(0.08));
  }
  expect_partition(mesh, one);
  expect_boundaries_match(one);
  expect_same_parts(one, two);
  // Kept only if its parts cost fewer strips than the whole (judged before straightening;
  // with straightening off the parts are the judged ones).
  FuzzySegmentOptions plain = judged(0.08);
  plain.straighten = false;
  const std::vector<Mesh> parts = segment_fuzzy(mesh, plain);
  if (parts.size() > 1) {
    int sum = 0;
    for (const Mesh& part : parts) sum += count_strips(part, at_tolerance({}, 0.08), 1000);
    EXPECT_LT(sum, count_strips(mesh, at_tolerance({}, 0.08), 1000));
  }
}

TEST(SegmentFuzzyByStrips, MergingNeighboursNeverCostsStrips) {
  // The pass after the hierarchy merges adjacent parts only where the union is estimated
  // cheaper: the emitted parts (not straightened, so they are the judged ones) never cost more
  // strips with it, and still partition the mesh.
  constexpr double kTolerance = 0.08;
  auto cost = [](const std::vector<Mesh>& parts) {
    int sum = 0;
    for (const Mesh& part : parts) sum += count_strips(part, at_tolerance({}, kTolerance), 1000);
    return sum;
  };
  DumbbellOptions shape;
  shape.handle_radius = 0.3;
  shape.handle_length = 1.5;
  const Mesh mesh = tagged_mesh(dumbbell(shape));
  FuzzySegmentOptions with = judged(kTolerance);
  with.straighten = false;
  FuzzySegmentOptions without = with;
  without.merge_neighbours = false;
  const std::vector<Mesh> merged = segment_fuzzy(mesh, with);
  const std::vector<Mesh> unmerged = segment_fuzzy(mesh, without);
  expect_partition(mesh, merged);
  EXPECT_LE(merged.size(), unmerged.size());
  EXPECT_LE(cost(merged), cost(unmerged));
}

TEST(SegmentFuzzyByStrips, RejectsNegativeTolerance) {
  const Mesh mesh = tagged_mesh(sphere({1.0, 2}));
  EXPECT_THROW(segment_fuzzy(mesh, judged(-1.0)), InvalidInputException);
}

TEST(PartsPly, OneColouredFacePerPartFace) {
  DumbbellOptions shape;
  const Mesh mesh = tagged_mesh(dumbbell(shape));
  const std::vector<Mesh> parts = segment_fuzzy(mesh);
  ASSERT_GE(parts.size(), 2u);
  std::size_t vertices = 0, faces = 0;
  for (const Mesh& part : parts) {
    vertices += part.n_vertices();
    faces += part.n_faces();
  }
  const std::string ply = parts_ply(parts);
  EXPECT_NE(ply.find("element vertex " + std::to_string(vertices) + "\n"), std::string::npos);
  EXPECT_NE(ply.find("element face " + std::to_string(faces) + "\n"), std::string::npos);
  std::istringstream in(ply.substr(ply.find("end_header\n") + 11));
  std::string line;
  for (std::size_t i = 0; i < vertices; ++i) std::getline(in, line);
  std::vector<int> per_part(parts.size(), 0);
  for (std::size_t i = 0; i < faces; ++i) {
    ASSERT_TRUE(std::getline(in, line));
    std::istringstream face(line);
    int n, a, b, c, part, red, green, blue;
    face >> n >> a >> b >> c >> part >> red >> green >> blue;
    ASSERT_EQ(n, 3);
    ASSERT_GE(part, 0);
    ASSERT_LT(part, static_cast<int>(parts.size()));
    EXPECT_LT(std::max({a, b, c}), static_cast<int>(vertices));
    const auto colour = part_colour(part);
    EXPECT_EQ(red, colour[0]);
    EXPECT_EQ(green, colour[1]);
    EXPECT_EQ(blue, colour[2]);
    ++per_part[part];
  }
  for (std::size_t p = 0; p < parts.size(); ++p)
    EXPECT_EQ(per_part[p], static_cast<int>(parts[p].n_faces()));
  EXPECT_NE(part_colour(0), part_colour(1));
}

}  // namespace
}  // namespace papercraft
