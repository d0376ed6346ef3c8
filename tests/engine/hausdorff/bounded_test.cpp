#include "engine/hausdorff/bounded.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "core/closest_point.h"
#include "core/errors.h"
#include "support/brute_force_hausdorff.h"

namespace papercraft {
namespace {

using testing::brute_force_hausdorff;
using testing::height_field;
using testing::reference_mesh_distance;
using testing::reference_triangle_distance;

TriangleMesh square(double z, double size = 1.0) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, z), Vec3(size, 0, z), Vec3(size, size, z), Vec3(0, size, z)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TriangleMesh rectangle(double x0, double x1, double y0, double y1) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(x0, y0, 0), Vec3(x1, y0, 0), Vec3(x1, y1, 0), Vec3(x0, y1, 0)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TriangleMesh merge(const TriangleMesh& x, const TriangleMesh& y) {
  TriangleMesh mesh = x;
  const int offset = static_cast<int>(x.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), y.vertices.begin(), y.vertices.end());
  for (Triangle t : y.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return mesh;
}

TriangleMesh single(const Vec3& a, const Vec3& b, const Vec3& c) {
  TriangleMesh mesh;
  mesh.vertices = {a, b, c};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

// The witness point must lie on the named triangle and its distance must be the exact
// distance to the other mesh (to the accuracy of the reference on slivers).
void expect_valid_witness(const HausdorffResult& r, const TriangleMesh& a, const TriangleMesh& b) {
  const TriangleMesh& source = r.witness.side == 0 ? a : b;
  const TriangleMesh& target = r.witness.side == 0 ? b : a;
  ASSERT_GE(r.witness.triangle, 0);
  ASSERT_LT(r.witness.triangle, static_cast<int>(source.triangles.size()));
  const Triangle& t = source.triangles[r.witness.triangle];
  EXPECT_NEAR(reference_triangle_distance(r.witness.point, source.vertices[t[0]],
                                          source.vertices[t[1]], source.vertices[t[2]]),
              0.0, 1e-9);
  EXPECT_NEAR(reference_mesh_distance(r.witness.point, target), r.witness.distance_lower_bound,
              1e-9);
  EXPECT_EQ(r.witness.distance_lower_bound, r.lower);
}

// Checks value mode and both decisions around the exactly known distance.
void expect_exact_hausdorff(const TriangleMesh& a, const TriangleMesh& b, double exact,
                            const BoundedHausdorffOptions& options = {}) {
  SCOPED_TRACE(::testing::Message() << "exact " << exact);
  for (double error_bound : {1e-2 * exact, 1e-4 * exact}) {
    const HausdorffResult value = certified_hausdorff_distance(a, b, error_bound, options);
    EXPECT_TRUE(value.certified);
    EXPECT_TRUE(value.within);
    EXPECT_LE(value.lower, exact * (1 + 1e-12));
    EXPECT_GE(value.upper, exact * (1 - 1e-12));
    EXPECT_LE(value.upper - value.lower, error_bound);
    expect_valid_witness(value, a, b);
  }
  const HausdorffResult accept = certified_hausdorff_within(a, b, 1.01 * exact, options);
  EXPECT_TRUE(accept.within);
  EXPECT_TRUE(accept.certified);
  EXPECT_LE(accept.upper, 1.01 * exact);
  EXPECT_GE(accept.upper, exact * (1 - 1e-12));
  EXPECT_LE(accept.lower, exact * (1 + 1e-12));

  const double tau = 0.99 * exact;
  const HausdorffResult reject = certified_hausdorff_within(a, b, tau, options);
  EXPECT_FALSE(reject.within);
  EXPECT_TRUE(reject.certified);
  EXPECT_GT(reject.lower, tau);
  EXPECT_LE(reject.lower, exact * (1 + 1e-12));
  EXPECT_GE(reject.witness.distance_lower_bound, exact - options.precision * tau);
  EXPECT_LE(reject.upper - reject.lower, options.precision * tau);
  expect_valid_witness(reject, a, b);
}

TEST(CertifiedHausdorff, ParallelSquares) {
  for (double d : {0.1, 0.01}) expect_exact_hausdorff(square(0), square(d), d);
  // Different diagonals, so the nearest triangles differ across the other square's diagonal.
  TriangleMesh flipped = square(0.05);
  flipped.triangles = {{0, 1, 3}, {1, 2, 3}};
  expect_exact_hausdorff(square(0), flipped, 0.05);
}

TEST(CertifiedHausdorff, TriangleAndSubTriangle) {
  // h(big, small) is attained at the far corners: |(1, 0) - (0.5, 0)| = 0.5; h(small, big) = 0.
  const TriangleMesh big = single(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  const TriangleMesh small = single(Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(0, 0.5, 0));
  expect_exact_hausdorff(big, small, 0.5);
  expect_exact_hausdorff(small, big, 0.5);
  const HausdorffResult backwards =
      certified_one_sided_hausdorff_distance(small, TriangleBvh(big), 1e-6);
  EXPECT_LE(backwards.upper, 1e-6);
}

TEST(CertifiedHausdorff, SquareWithLiftedVertex) {
  // B = the unit square with corner (1, 0) lifted by h: its tilted triangle lies in the plane
  // z = h (x - y). h(B, A) = h (the lifted corner); h(A, B) = h / sqrt(1 + 2 h^2), the
  // distance from (1, 0, 0) to that plane (the foot lies inside the tilted triangle).
  const double h = 0.2;
  const TriangleMesh a = square(0);
  TriangleMesh b = square(0);
  b.vertices[1].z() = h;
  expect_exact_hausdorff(a, b, h);
  const double one_sided = h / std::sqrt(1 + 2 * h * h);
  const HausdorffResult r = certified_one_sided_hausdorff_distance(a, TriangleBvh(b), 1e-6);
  EXPECT_LE(r.lower, one_sided + 1e-12);
  EXPECT_GE(r.upper, one_sided - 1e-12);
  EXPECT_LE(r.upper - r.lower, 1e-6);
  EXPECT_TRUE(certified_one_sided_hausdorff_within(a, TriangleBvh(b), 1.01 * one_sided).within);
  EXPECT_FALSE(certified_one_sided_hausdorff_within(a, TriangleBvh(b), 0.99 * one_sided).within);
}

TEST(CertifiedHausdorff, SegmentTriangleAgainstSquare) {
  // A = the segment from (0, 0, h) to (1, 0, h) as the triangle (a, b, b). h(A, B) = h;
  // h(B, A) is attained at the far corners (0, 1, 0) and (1, 1, 0): sqrt(1 + h^2).
  const double h = 0.3;
  const TriangleMesh segment = single(Vec3(0, 0, h), Vec3(1, 0, h), Vec3(1, 0, h));
  expect_exact_hausdorff(segment, square(0), std::sqrt(1 + h * h));
  expect_exact_hausdorff(square(0), segment, std::sqrt(1 + h * h));
  // Collinear three-point form of a longer segment, and the segment against a segment.
  const TriangleMesh collinear = single(Vec3(0, 0, h), Vec3(2, 0, h), Vec3(0.5, 0, h));
  expect_exact_hausdorff(collinear, segment, 1.0);
}

TEST(CertifiedHausdorff, MaximumInsideASegment) {
  // A segment of length 2 against two point triangles at its ends: the maximum (1) is at
  // the midpoint, where no corner lies; only a sound upper bound can accept at 1.01.
  const TriangleMesh segment = single(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0));
  const TriangleMesh points = merge(single(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 0)),
                                    single(Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0)));
  expect_exact_hausdorff(segment, points, 1.0);
  BoundedHausdorffOptions midpoints;
  midpoints.split = PieceSplit::midpoints;
  expect_exact_hausdorff(segment, points, 1.0, midpoints);
}

TEST(CertifiedHausdorff, MaximumInsideARectangle) {
  // [0, 2] x [0, 1] against its two end strips [0, 0.5] and [1.5, 2]: the points of the
  // line x = 1 are 0.5 away, the maximum, and no corner of either mesh lies there.
  const TriangleMesh whole = rectangle(0, 2, 0, 1);
  const TriangleMesh ends = merge(rectangle(0, 0.5, 0, 1), rectangle(1.5, 2, 0, 1));
  expect_exact_hausdorff(whole, ends, 0.5);
  BoundedHausdorffOptions midpoints;
  midpoints.split = PieceSplit::midpoints;
  expect_exact_hausdorff(ends, whole, 0.5, midpoints);
}

// A fine grid with a square hole of half-width w centred at (0.35, 0.6) (not a point that
// splitting the lid reaches) under two large triangles at height h: the point above the
// hole's centre is farthest, sqrt(w^2 + h^2) from the grid (the midpoints of the hole's
// sides). A projection of the lid onto the grid that ignored the hole's boundary would
// certify h.
TEST(CertifiedHausdorff, HoleUnderACoarseTriangle) {
  const double h = 0.01, w = 0.05;
  const Vec2 centre(0.35, 0.6);
  const TriangleMesh full = height_field(
      20, [](double, double) { return 0.0; }, 0.0, 1);
  TriangleMesh grid = full;
  grid.triangles.clear();
  for (const Triangle& t : full.triangles) {
    const Vec3 centroid = (full.vertices[t[0]] + full.vertices[t[1]] + full.vertices[t[2]]) / 3.0;
    if (std::abs(centroid.x() - centre.x()) > w || std::abs(centroid.y() - centre.y()) > w) {
      grid.triangles.push_back(t);
    }
  }
  ASSERT_EQ(grid.triangles.size(), full.triangles.size() - 8);
  expect_exact_hausdorff(square(h), grid, std::sqrt(w * w + h * h));
  expect_exact_hausdorff(square(h), full, h);  // without the hole: h everywhere
}

TEST(CertifiedHausdorff, RandomSurfacesAgainstBruteForce) {
  // Two different triangulations of nearby wavy surfaces. The dense sampling of the
  // independent reference never exceeds the certified upper bound, and the certified lower
  // bound never exceeds the sampled maximum plus the sampling gap (the distance is
  // 1-Lipschitz).
  struct Case {
    int n_a, n_b;
    double amplitude_b, noise;
    unsigned seed;
  };
  for (const Case& c : {Case{10, 7, 0.12, 0.01, 1}, Case{8, 11, 0.1, 0.02, 2},
                        Case{12, 5, 0.05, 0.0, 3}, Case{6, 6, 0.15, 0.03, 4}}) {
    SCOPED_TRACE(::testing::Message() << "seed " << c.seed);
    const TriangleMesh a = height_field(
        c.n_a, [](double x, double y) { return 0.1 * std::sin(5 * x) * std::cos(4 * y); }, c.noise,
        c.seed);
    const TriangleMesh b = height_field(
        c.n_b,
        [&](double x, double y) { return c.amplitude_b * std::sin(5 * x + 0.3) * std::cos(4 * y); },
        c.noise, c.seed + 100);
    const auto reference = brute_force_hausdorff(a, b, 12);
    const double error_bound = 1e-3 * reference.distance;
    const HausdorffResult value = certified_hausdorff_distance(a, b, error_bound);
    ASSERT_TRUE(value.certified);
    EXPECT_LE(reference.distance, value.upper * (1 + 1e-12));
    EXPECT_LE(value.lower, reference.distance + reference.gap);
    EXPECT_LE(value.upper - value.lower, error_bound);
    expect_valid_witness(value, a, b);

    // Decisions on both sides of the value; on reject the witness is near the maximum.
    const double precision = 0.05;
    for (double tau : {0.5 * value.lower, 0.9 * value.lower}) {
      const HausdorffResult reject = certified_hausdorff_within(a, b, tau);
      EXPECT_FALSE(reject.within);
      EXPECT_TRUE(reject.certified);
      EXPECT_GE(reject.witness.distance_lower_bound, reference.distance - precision * tau);
      EXPECT_GE(reject.witness.distance_lower_bound, value.lower - precision * tau);
      EXPECT_LE(reference.distance, reject.upper * (1 + 1e-12));
      expect_valid_witness(reject, a, b);
    }
    const HausdorffResult accept = certified_hausdorff_within(a, b, 1.02 * value.upper);
    EXPECT_TRUE(accept.within);
    EXPECT_LE(accept.upper, 1.02 * value.upper);
    EXPECT_LE(reference.distance, accept.upper * (1 + 1e-12));
  }
}

// A ruled strip of long thin triangles (rulings across y) over a finer, jittered surface:
// the strip -> part shape of the pipeline, where the projection bound does most of the work.
TEST(CertifiedHausdorff, RuledStripOverFineSurfaceAgainstBruteForce) {
  auto height = [](double x, double y) { return 0.1 * std::sin(5 * x) + 0.05 * y * x; };
  for (unsigned seed : {1u, 2u}) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    const TriangleMesh part = height_field(14, height, 0.004, seed);
    TriangleMesh strip;
    const int n = 9;
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n;
      strip.vertices.emplace_back(x, 0.0, height(x, 0.0));
      strip.vertices.emplace_back(x, 1.0, height(x, 1.0));
    }
    for (int i = 0; i < n; ++i) {
      strip.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
      strip.triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
    }
    const auto reference = brute_force_hausdorff(part, strip, 16);
    const HausdorffResult value =
        certified_hausdorff_distance(part, strip, 1e-3 * reference.distance);
    ASSERT_TRUE(value.certified);
    EXPECT_LE(reference.distance, value.upper * (1 + 1e-12));
    EXPECT_LE(value.lower, reference.distance + reference.gap);
    for (double factor : {1.05, 2.0}) {
      const HausdorffResult accept = certified_hausdorff_within(part, strip, factor * value.upper);
      EXPECT_TRUE(accept.within);
      EXPECT_LE(reference.distance, accept.upper * (1 + 1e-12));
    }
    const HausdorffResult reject = certified_hausdorff_within(part, strip, 0.9 * value.lower);
    EXPECT_FALSE(reject.within);
    EXPECT_GE(reject.witness.distance_lower_bound, reference.distance - 0.05 * 0.9 * value.lower);
  }
}

// One-sided, chords over an arch: a coarse strip B spanning a fine arch A. The largest
// distance from B to A lies inside B's triangles (under the arch's crests), where no corner
// of B is, so only sound upper bounds (mostly the projection bound here) can certify it.
TEST(CertifiedHausdorff, ChordsUnderAnArchOneSided) {
  // Not symmetric within a panel, so the farthest points are not midpoints that bisection hits.
  auto arch = [](double x, double) { return 0.2 * std::sin(3 * x); };
  const TriangleMesh fine = height_field(23, arch, 0.0, 1);
  TriangleMesh chords;
  for (double x : {0.0, 0.5, 1.0}) {
    chords.vertices.emplace_back(x, 0.0, arch(x, 0.0));
    chords.vertices.emplace_back(x, 1.0, arch(x, 0.0));
  }
  chords.triangles = {{0, 2, 1}, {1, 2, 3}, {2, 4, 3}, {3, 4, 5}};
  const TriangleBvh fine_tree(fine);
  const auto reference = testing::brute_force_one_sided(chords, fine, 60);
  const HausdorffResult value =
      certified_one_sided_hausdorff_distance(chords, fine_tree, 1e-4 * reference.distance);
  ASSERT_TRUE(value.certified);
  EXPECT_LE(reference.distance, value.upper * (1 + 1e-12));
  EXPECT_LE(value.lower, reference.distance + reference.gap);
  EXPECT_GT(value.lower, 0.0);
  const HausdorffResult accept =
      certified_one_sided_hausdorff_within(chords, fine_tree, 1.01 * reference.distance);
  EXPECT_TRUE(accept.within);
  EXPECT_LE(reference.distance, accept.upper * (1 + 1e-12));
  EXPECT_FALSE(
      certified_one_sided_hausdorff_within(chords, fine_tree, 0.99 * reference.distance).within);
}

// Random soups with obtuse, sliver, segment and point triangles: every bound of the cascade
// (Lipschitz, whole-piece and per-region convexity) gets exercised on odd shapes.
TriangleMesh random_soup(int triangle_count, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TriangleMesh mesh;
  for (int f = 0; f < triangle_count; ++f) {
    const Vec3 center(u(rng), u(rng), 0.3 * u(rng));
    const int base = static_cast<int>(mesh.vertices.size());
    for (int k = 0; k < 3; ++k)
      mesh.vertices.push_back(center + size * Vec3(u(rng), u(rng), u(rng)));
    Vec3& third = mesh.vertices[base + 2];
    const Vec3& first = mesh.vertices[base];
    const Vec3& second = mesh.vertices[base + 1];
    if (f % 5 == 1) third = second;  // segment
    if (f % 5 == 2) third = first + 1.3 * (second - first) + 1e-7 * Vec3(u(rng), u(rng), u(rng));
    if (f % 9 == 3) third = mesh.vertices[base + 1] = first;  // point
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

TEST(CertifiedHausdorff, RandomSoupsAgainstBruteForce) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    const TriangleMesh a = random_soup(25, 0.3, seed);
    const TriangleMesh b = random_soup(25, 0.4, seed + 50);
    const auto reference = brute_force_hausdorff(a, b, 40);
    BoundedHausdorffOptions options;
    options.split = seed % 2 ? PieceSplit::longest_edge : PieceSplit::midpoints;
    const HausdorffResult value = certified_hausdorff_distance(a, b, 1e-4, options);
    ASSERT_TRUE(value.certified);
    EXPECT_LE(reference.distance, value.upper * (1 + 1e-12));
    EXPECT_LE(value.lower, reference.distance + reference.gap);
    expect_valid_witness(value, a, b);
    const HausdorffResult accept = certified_hausdorff_within(a, b, 1.001 * value.upper, options);
    EXPECT_TRUE(accept.within);
    EXPECT_LE(reference.distance, accept.upper * (1 + 1e-12));
    const HausdorffResult reject = certified_hausdorff_within(a, b, 0.8 * value.lower, options);
    EXPECT_FALSE(reject.within);
    EXPECT_GE(reject.witness.distance_lower_bound,
              reference.distance - options.precision * 0.8 * value.lower);
  }
}

TEST(CertifiedHausdorff, SameResultWithOneAndTwoThreads) {
  const TriangleMesh a = height_field(
      24, [](double x, double y) { return 0.1 * std::sin(5 * x) * std::cos(4 * y); }, 0.01, 7);
  const TriangleMesh b = height_field(
      17, [](double x, double y) { return 0.11 * std::sin(5 * x) * std::cos(4 * y + 0.1); }, 0.01,
      8);
  std::vector<HausdorffResult> results;
  BoundedHausdorffOptions small_batches;
  small_batches.batch_size = 8;
  for (int threads : {1, 2}) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    const HausdorffResult value = certified_hausdorff_distance(a, b, 1e-4, small_batches);
    results.push_back(value);
    results.push_back(certified_hausdorff_within(a, b, 0.9 * value.lower, small_batches));
    results.push_back(certified_hausdorff_within(a, b, 1.1 * value.upper, small_batches));
  }
  ASSERT_EQ(results.size(), 6u);
  for (int k = 0; k < 3; ++k) {
    const HausdorffResult& one = results[k];
    const HausdorffResult& two = results[k + 3];
    EXPECT_EQ(one.within, two.within);
    EXPECT_EQ(one.lower, two.lower);
    EXPECT_EQ(one.upper, two.upper);
    EXPECT_EQ(one.evaluations, two.evaluations);
    EXPECT_EQ(one.witness.point, two.witness.point);
    EXPECT_EQ(one.witness.triangle, two.witness.triangle);
    EXPECT_EQ(one.witness.side, two.witness.side);
  }
  EXPECT_FALSE(results[1].within);
  EXPECT_TRUE(results[2].within);
}

TEST(CertifiedHausdorff, RejectWithoutLocatingStopsAtTheFirstFarPoint) {
  const TriangleMesh whole = rectangle(0, 2, 0, 1);
  const TriangleMesh ends = merge(rectangle(0, 0.5, 0, 1), rectangle(1.5, 2, 0, 1));
  BoundedHausdorffOptions options;
  options.locate_maximum = false;
  const HausdorffResult r = certified_hausdorff_within(whole, ends, 0.25, options);
  EXPECT_FALSE(r.within);
  EXPECT_TRUE(r.certified);
  EXPECT_GT(r.lower, 0.25);
  expect_valid_witness(r, whole, ends);
}

TEST(CertifiedHausdorff, CapLeavesTheResultUncertified) {
  const TriangleMesh a = height_field(
      10, [](double x, double y) { return 0.1 * std::sin(5 * x) * std::cos(4 * y); }, 0.0, 1);
  const TriangleMesh b = height_field(
      7, [](double x, double y) { return 0.12 * std::sin(5 * x + 0.3) * std::cos(4 * y); }, 0.0, 2);
  const HausdorffResult value = certified_hausdorff_distance(a, b, 1e-6);
  const double tau = value.upper * (1 + 1e-5);
  BoundedHausdorffOptions options;
  options.max_evaluations = a.vertices.size() + b.vertices.size() + 1;
  const HausdorffResult capped = certified_hausdorff_within(a, b, tau, options);
  EXPECT_FALSE(capped.within);
  EXPECT_FALSE(capped.certified);
  EXPECT_GT(capped.upper, tau);
  EXPECT_LE(capped.lower, tau);
  options = {};
  options.max_depth = 1;
  const HausdorffResult shallow = certified_hausdorff_within(a, b, tau, options);
  EXPECT_FALSE(shallow.within);
  EXPECT_FALSE(shallow.certified);
  EXPECT_GT(shallow.upper, tau);
  const HausdorffResult full = certified_hausdorff_within(a, b, tau);
  EXPECT_TRUE(full.within);
  EXPECT_TRUE(full.certified);
  EXPECT_GT(full.evaluations, capped.evaluations);
}

TEST(CertifiedHausdorff, IdenticalMeshesHaveZeroDistance) {
  const TriangleMesh a = height_field(
      9, [](double x, double y) { return 0.1 * std::sin(5 * x) * std::cos(4 * y); }, 0.01, 3);
  const HausdorffResult r = certified_hausdorff_within(a, a, 1e-9);
  EXPECT_TRUE(r.within);
  EXPECT_LE(r.upper, 1e-12);  // midpoints on edges are off the surface by rounding
}

TEST(CertifiedHausdorff, InvalidInputThrows) {
  const TriangleMesh a = square(0);
  EXPECT_THROW(certified_hausdorff_within(TriangleMesh{}, a, 0.1), InvalidInputException);
  EXPECT_THROW(certified_hausdorff_within(a, TriangleMesh{}, 0.1), InvalidInputException);
  EXPECT_THROW(certified_hausdorff_distance(TriangleMesh{}, a, 0.1), InvalidInputException);
  EXPECT_THROW(certified_hausdorff_within(a, a, 0.0), InvalidInputException);
  EXPECT_THROW(certified_hausdorff_within(a, a, -1.0), InvalidInputException);
  EXPECT_THROW(certified_hausdorff_within(a, a, NAN), InvalidInputException);
  EXPECT_THROW(certified_hausdorff_distance(a, a, 0.0), InvalidInputException);
  BoundedHausdorffOptions bad;
  bad.precision = 0.0;
  EXPECT_THROW(certified_hausdorff_within(a, a, 0.1, bad), InvalidInputException);
  TriangleMesh bad_index = a;
  bad_index.triangles.push_back({0, 1, 9});
  EXPECT_THROW(certified_hausdorff_within(bad_index, a, 0.1), InvalidInputException);
  EXPECT_THROW(certified_one_sided_hausdorff_within(bad_index, TriangleBvh(a), 0.1),
               InvalidInputException);
}

}  // namespace
}  // namespace papercraft
