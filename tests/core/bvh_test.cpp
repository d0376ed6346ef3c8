#include "core/bvh.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "core/errors.h"
#include "support/brute_force_hausdorff.h"

namespace papercraft {
namespace {

using testing::reference_triangle_distance;

// Random triangle soup in [-1, 1]^3 with some degenerate triangles mixed in.
TriangleMesh random_soup(int triangle_count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TriangleMesh mesh;
  for (int f = 0; f < triangle_count; ++f) {
    const Vec3 center(u(rng), u(rng), u(rng));
    const int base = static_cast<int>(mesh.vertices.size());
    for (int k = 0; k < 3; ++k)
      mesh.vertices.push_back(center + 0.15 * Vec3(u(rng), u(rng), u(rng)));
    if (f % 7 == 0) mesh.vertices[base + 2] = mesh.vertices[base + 1];  // segment
    if (f % 11 == 0)
      mesh.vertices[base + 2] = 0.5 * (mesh.vertices[base] + mesh.vertices[base + 1]);
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

struct Reference {
  double distance;
  int triangle;
};

Reference brute_force_closest(const TriangleMesh& mesh, const Vec3& p) {
  Reference best{std::numeric_limits<double>::infinity(), -1};
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const double d = reference_triangle_distance(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                 mesh.vertices[t[2]]);
    if (d < best.distance) best = {d, static_cast<int>(f)};
  }
  return best;
}

void expect_consistent_hit(const TriangleMesh& mesh, const Vec3& p, const BvhClosestHit& hit) {
  ASSERT_TRUE(hit.found());
  const Reference reference = brute_force_closest(mesh, p);
  EXPECT_NEAR(hit.distance, reference.distance, 1e-12);
  EXPECT_NEAR((hit.point - p).norm(), hit.distance, 1e-12);
  const Triangle& t = mesh.triangles[hit.triangle];
  const Vec3 from_weights = hit.barycentric[0] * mesh.vertices[t[0]] +
                            hit.barycentric[1] * mesh.vertices[t[1]] +
                            hit.barycentric[2] * mesh.vertices[t[2]];
  EXPECT_NEAR((from_weights - hit.point).norm(), 0.0, 1e-12);
}

TEST(TriangleBvh, ClosestMatchesBruteForceOnRandomSoups) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const TriangleMesh mesh = random_soup(seed == 1 ? 1 : 700 * seed, seed);
    const TriangleBvh bvh(mesh);
    std::mt19937 rng(100 + seed);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int q = 0; q < 2000; ++q) {
      const Vec3 p(u(rng), u(rng), u(rng));
      expect_consistent_hit(mesh, p, bvh.closest(p));
    }
  }
}

TEST(TriangleBvh, ClosestMatchesBruteForceOnHeightField) {
  const TriangleMesh mesh = testing::height_field(
      30, [](double x, double y) { return 0.2 * std::sin(6 * x) * std::cos(5 * y); }, 0.01, 5);
  const TriangleBvh bvh(mesh, {.leaf_size = 2});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int q = 0; q < 3000; ++q) {
    const Vec3 p(u(rng), u(rng), 0.5 * u(rng));
    expect_consistent_hit(mesh, p, bvh.closest(p));
  }
}

TEST(TriangleBvh, UpperBoundAndCandidatesDoNotChangeTheAnswer) {
  const TriangleMesh mesh = random_soup(500, 4);
  const TriangleBvh bvh(mesh);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::uniform_int_distribution<int> any_triangle(0, 499);
  for (int q = 0; q < 1000; ++q) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const BvhClosestHit plain = bvh.closest(p);
    const int candidates[2] = {any_triangle(rng), any_triangle(rng)};
    const BvhClosestHit hinted = bvh.closest(p, std::span<const int>(candidates, 2));
    EXPECT_EQ(hinted.triangle, plain.triangle);
    EXPECT_EQ(hinted.distance, plain.distance);
    const BvhClosestHit loose = bvh.closest(p, plain.distance * 1.5 + 1e-9);
    EXPECT_EQ(loose.triangle, plain.triangle);
    const BvhClosestHit tight = bvh.closest(p, plain.distance * 0.9);
    EXPECT_FALSE(tight.found());
    EXPECT_TRUE(std::isinf(tight.distance));
  }
}

TEST(TriangleBvh, TiesResolveToLowestIndex) {
  // A fan of 8 triangles around the origin: the apex is at the same distance from all.
  TriangleMesh fan;
  fan.vertices.push_back(Vec3::Zero());
  for (int k = 0; k < 8; ++k) {
    const double angle = 2 * M_PI * k / 8;
    fan.vertices.emplace_back(std::cos(angle), std::sin(angle), 0.0);
  }
  for (int k = 0; k < 8; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % 8});
  const TriangleBvh bvh(fan, {.leaf_size = 1});
  const int candidate = 5;
  EXPECT_EQ(bvh.closest(Vec3(0, 0, 1)).triangle, 0);
  EXPECT_EQ(bvh.closest(Vec3(0, 0, 1), std::span<const int>(&candidate, 1)).triangle, 0);
  EXPECT_DOUBLE_EQ(bvh.closest(Vec3(0, 0, 1)).distance, 1.0);
}

TEST(TriangleBvh, BatchQueryEqualsSingleQueriesForAnyThreadCount) {
  const TriangleMesh mesh = random_soup(800, 6);
  const TriangleBvh bvh(mesh);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Vec3> points(3000);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  for (int threads : {1, 2}) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    const std::vector<BvhClosestHit> hits = bvh.closest(points);
    ASSERT_EQ(hits.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const BvhClosestHit single = bvh.closest(points[i]);
      EXPECT_EQ(hits[i].triangle, single.triangle);
      EXPECT_EQ(hits[i].distance, single.distance);
    }
  }
}

TEST(TriangleBvh, DegenerateOnlyMeshAndCoincidentCentroids) {
  // Many identical segment triangles: centroids coincide, so no split is possible.
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  for (int k = 0; k < 40; ++k) mesh.triangles.push_back({0, 1, 1});
  const TriangleBvh bvh(mesh);
  const BvhClosestHit hit = bvh.closest(Vec3(0.5, 3, 4));
  EXPECT_DOUBLE_EQ(hit.distance, 5.0);
  EXPECT_EQ(hit.triangle, 0);
  EXPECT_EQ(bvh.bounds().min, Vec3(0, 0, 0));
  EXPECT_EQ(bvh.bounds().max, Vec3(1, 0, 0));
}

TEST(TriangleBvh, InvalidMeshesThrow) {
  EXPECT_THROW(TriangleBvh(TriangleMesh{}), InvalidInputException);
  TriangleMesh bad_index;
  bad_index.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  bad_index.triangles = {{0, 1, 2}};
  EXPECT_THROW(TriangleBvh{bad_index}, InvalidInputException);
  TriangleMesh not_finite;
  not_finite.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, NAN, 0)};
  not_finite.triangles = {{0, 1, 2}};
  EXPECT_THROW(TriangleBvh{not_finite}, InvalidInputException);
}

TEST(Aabb, SquaredDistance) {
  Aabb box;
  box.extend(Vec3(0, 0, 0));
  box.extend(Vec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(box.squared_distance(Vec3(0.5, 1, 1)), 0.0);
  EXPECT_DOUBLE_EQ(box.squared_distance(Vec3(-1, 4, 3)), 1.0 + 4.0);
}

TEST(TriangleBvh, SubtreesPartitionTheTrianglesInsideTheirBoxes) {
  for (int count : {1, 2, 5, 300}) {
    const TriangleMesh mesh = random_soup(count, 7u + static_cast<unsigned>(count));
    const TriangleBvh bvh(mesh);
    const BvhSubtree root = bvh.root();
    EXPECT_EQ(root.first_slot, 0);
    EXPECT_EQ(root.slot_count, count);
    std::vector<int> seen(count, 0);
    std::vector<BvhSubtree> pending = {root};
    while (!pending.empty()) {
      const BvhSubtree subtree = pending.back();
      pending.pop_back();
      for (int s = subtree.first_slot; s < subtree.first_slot + subtree.slot_count; ++s) {
        const Triangle& t = mesh.triangles[bvh.triangle_at_slot(s)];
        for (int v : t) {
          EXPECT_TRUE((mesh.vertices[v].array() >= subtree.box.min.array()).all());
          EXPECT_TRUE((mesh.vertices[v].array() <= subtree.box.max.array()).all());
        }
      }
      if (subtree.node < 0) {
        for (int s = subtree.first_slot; s < subtree.first_slot + subtree.slot_count; ++s) {
          ++seen[bvh.triangle_at_slot(s)];
        }
        continue;
      }
      int covered = 0;
      for (const BvhSubtree& child : bvh.children(subtree)) {
        if (child.slot_count == 0) continue;
        EXPECT_GE(child.first_slot, subtree.first_slot);
        EXPECT_LE(child.first_slot + child.slot_count, subtree.first_slot + subtree.slot_count);
        covered += child.slot_count;
        pending.push_back(child);
      }
      EXPECT_EQ(covered, subtree.slot_count);
    }
    for (int t = 0; t < count; ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t;
  }
}

TEST(TriangleBvh, LimitedBoxQueryGivesUpOnlyAboveTheLimit) {
  const TriangleBvh bvh(random_soup(200, 3u));
  Aabb box;
  box.extend(Vec3(-0.5, -0.5, -0.5));
  box.extend(Vec3(0.5, 0.5, 0.5));
  std::vector<int> all;
  bvh.triangles_meeting(box, all);
  ASSERT_GT(all.size(), 2u);
  std::vector<int> limited;
  EXPECT_TRUE(bvh.triangles_meeting(box, limited, all.size()));
  EXPECT_EQ(limited.size(), all.size());
  limited.clear();
  EXPECT_FALSE(bvh.triangles_meeting(box, limited, all.size() - 1));
}

}  // namespace
}  // namespace papercraft
