// merge_congruent (paper 3.4): strips whose shared boundaries are congruent in the plane are
// joined; bent, mirrored, inconsistently oriented or overlapping unions are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using merge_testing::append;
using merge_testing::expect_valid;
using merge_testing::triangle_count;
using unfold_testing::circle_point;
using unfold_testing::euler_characteristic;
using unfold_testing::ladder_strip;
using unfold_testing::ring_strip;

// Three rings of one cylinder, cut by two horizontal iso-lines: one rectangle again.
TEST(MergeCongruent, StackedCylinderRingsMergeIntoOne) {
  const int n = 16;
  std::vector<FlatStrip> strips;
  for (int k = 0; k < 3; ++k) append(strips, ring_strip(1.0, k, 1.0, k + 1, n));
  ASSERT_EQ(strips.size(), 3u);
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 1u);
  const FlatStrip& s = merged[0];
  EXPECT_EQ(s.id, 0);
  EXPECT_EQ(s.triangles.size(), 6u * n);
  EXPECT_EQ(s.vertices2d.size(), 4u * (n + 1));  // the shared circles are welded
  EXPECT_EQ(euler_characteristic(s), 1);
  expect_valid(merged);
  int open = 0;
  std::set<std::string> labels;
  for (const BoundaryEdge& e : s.boundary) {
    if (e.kind == EdgeKind::Open) {
      ++open;
      continue;
    }
    EXPECT_EQ(e.neighbour_strip, s.id);  // the opened ruling, three storeys high
    labels.insert(e.label);
  }
  EXPECT_EQ(open, 2 * n);
  EXPECT_EQ(labels.size(), 1u);
}

// Rings opened at different angles still merge, into a staircase.
TEST(MergeCongruent, RingsOpenedAtDifferentRulingsMergeIntoOne) {
  const int n = 16;
  std::vector<FlatStrip> strips;
  const int offsets[3] = {0, 5, 11};
  for (int k = 0; k < 3; ++k) append(strips, ring_strip(1.0, k, 1.0, k + 1, n, offsets[k]));
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].triangles.size(), 6u * n);
  EXPECT_EQ(euler_characteristic(merged[0]), 1);
  expect_valid(merged);
}

// Paper fig. 3: a cylinder with two windows, as the strips the algorithm produces (a ring
// below, a ring above, a piece between the windows on either side): one piece of paper.
TEST(MergeCongruent, CylinderWithTwoHolesMergesIntoOne) {
  const int n = 16;
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(1.0, 0.0, 1.0, 1.0, n));
  append(strips, ring_strip(1.0, 2.0, 1.0, 3.0, n));
  for (int first : {2, 10}) {
    std::vector<Vec3> a, b;
    for (int i = first; i <= first + 4; ++i) {
      a.push_back(circle_point(1.0, i, n, 1.0));
      b.push_back(circle_point(1.0, i, n, 2.0));
    }
    append(strips, ladder_strip(a, b, false));
  }
  ASSERT_EQ(strips.size(), 4u);
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 1u);
  const FlatStrip& s = merged[0];
  EXPECT_EQ(s.triangles.size(), triangle_count(strips));
  // Every vertex of the pieces is welded to a ring's; the window the rings were opened
  // through is part of the outline, the other one a hole.
  EXPECT_EQ(s.vertices2d.size(), 4u * (n + 1));
  EXPECT_EQ(euler_characteristic(s), 0);
  expect_valid(merged);
}

// The flat strips of the frustums ring_strip(r0, z0, r1, z1, n), each given as {r0, z0, r1, z1},
// one after another.
std::vector<FlatStrip> rings(const std::vector<std::array<double, 4>>& frustums, int n) {
  std::vector<FlatStrip> strips;
  for (const auto& f : frustums) append(strips, ring_strip(f[0], f[1], f[2], f[3], n));
  return strips;
}

// Two frustums of one cone: the shared circle develops to the same arc on both sides.
TEST(MergeCongruent, FrustumsOfOneConeMerge) {
  const int n = 24;
  const std::vector<FlatStrip> strips = rings({{2.0, 0.0, 1.5, 1.0}, {1.5, 1.0, 1.0, 2.0}}, n);
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].vertices2d.size(), 3u * (n + 1));
  expect_valid(merged);
}

// A cylinder under a cone frustum: the circle is straight on one side, an arc on the other.
TEST(MergeCongruent, BentBoundaryIsNotMerged) {
  const int n = 24;
  const std::vector<FlatStrip> strips = rings({{1.0, 0.0, 1.0, 1.0}, {1.0, 1.0, 0.5, 2.0}}, n);
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 2u);
  expect_valid(merged);
  int seams = 0;
  for (const FlatStrip& s : merged)
    for (const BoundaryEdge& e : s.boundary)
      if (e.kind == EdgeKind::Seam && e.neighbour_strip != s.id) ++seams;
  EXPECT_EQ(seams, 2 * n);
}

// An hourglass waist: both sides develop to arcs bending the same way, congruent only
// through a reflection.
TEST(MergeCongruent, MirroredBoundaryIsNotMerged) {
  const int n = 24;
  const std::vector<FlatStrip> strips = rings({{2.0, -1.0, 1.0, 0.0}, {1.0, 0.0, 2.0, 1.0}}, n);
  EXPECT_EQ(merge_congruent(strips).size(), 2u);
}

// A neighbour oriented the other way would have to be turned over: never merged.
TEST(MergeCongruent, InconsistentlyOrientedNeighbourIsNotMerged) {
  const int n = 16;
  RuledStrip flipped = ring_strip(1.0, 1.0, 1.0, 2.0, n);
  for (Triangle& t : flipped.mesh.triangles) std::swap(t[1], t[2]);
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(1.0, 0.0, 1.0, 1.0, n));
  append(strips, flipped);
  append(strips, ring_strip(1.0, 2.0, 1.0, 3.0, n));
  ASSERT_EQ(strips.size(), 3u);
  auto merged = merge_congruent(strips);
  EXPECT_EQ(merged.size(), 3u);
}

// Pieces of a fan split because they overlap share congruent rulings but stay apart.
TEST(MergeCongruent, OverlappingUnionIsNotMerged) {
  std::vector<FlatStrip> strips;
  append(strips, unfold_testing::saddle_fan(40));
  ASSERT_GE(strips.size(), 2u);
  auto merged = merge_congruent(strips);
  EXPECT_EQ(merged.size(), strips.size());
  expect_valid(merged);
}

TEST(MergeCongruent, UvsAreKeptWhenBothStripsHaveThem) {
  std::vector<FlatStrip> strips;
  for (int k = 0; k < 2; ++k) {
    RuledStrip ring = ring_strip(1.0, k, 1.0, k + 1, 8);
    for (const Vec3& p : ring.mesh.vertices) ring.uvs.push_back(Vec2(p.x() + p.z(), p.y()));
    append(strips, ring);
  }
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 1u);
  const FlatStrip& s = merged[0];
  ASSERT_EQ(s.uvs.size(), s.vertices3d.size());
  for (std::size_t v = 0; v < s.uvs.size(); ++v)
    EXPECT_EQ(s.uvs[v], Vec2(s.vertices3d[v].x() + s.vertices3d[v].z(), s.vertices3d[v].y()));
}

// A flat strip made by hand: 3D points in the plane z = 0 at its flat points, but where
// `flat_offset` moves one flat point off (the 3D point stays).
FlatStrip hand_strip(int id, const std::vector<Vec2>& points,
                     const std::vector<Triangle>& triangles, int moved = -1,
                     const Vec2& flat_offset = Vec2::Zero()) {
  FlatStrip strip;
  strip.id = id;
  strip.source_strip = id;
  for (std::size_t v = 0; v < points.size(); ++v) {
    strip.vertices3d.push_back({points[v].x(), points[v].y(), 0.0});
    strip.vertices2d.push_back(static_cast<int>(v) == moved ? Vec2(points[v] + flat_offset)
                                                            : points[v]);
  }
  strip.triangles = triangles;
  strip.boundary = flat_boundary(triangles);
  return strip;
}

// Welding snaps a neighbour's seam points onto the strip's, which the rigid fit leaves up to
// congruence_tolerance of the seam's length apart. An edge 1e-4 long beside the seam would
// take that whole, and its two sides would differ: such a union is refused. Without the
// offset the same two strips merge.
TEST(MergeCongruent, WeldThatWouldStretchAShortEdgeIsRefused) {
  // X: a 2 x 1 rectangle. Y: above it, with an edge 1e-4 long up from the middle of the seam.
  const std::vector<Vec2> x = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
  const std::vector<Vec2> y = {{0, 1}, {1, 1}, {2, 1}, {1, 1.0001}, {0, 2}, {2, 2}};
  const std::vector<Triangle> x_triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  const std::vector<Triangle> y_triangles = {{0, 1, 3}, {1, 2, 3}, {0, 3, 4}, {3, 2, 5}, {3, 5, 4}};
  std::vector<FlatStrip> exact = {hand_strip(0, x, x_triangles), hand_strip(1, y, y_triangles)};
  ASSERT_EQ(merge_congruent(exact).size(), 1u);
  // X's seam point (1, 1) 4e-12 off on paper, along the short edge: no rigid motion fits it,
  // but it is within the congruence tolerance of the seam. Whichever strip the merge keeps in
  // place, the short edge keeps its length: the union is made only where it does.
  for (const bool y_first : {false, true}) {
    std::vector<FlatStrip> off = {hand_strip(0, x, x_triangles, 3, Vec2(0.0, 4e-12)),
                                  hand_strip(1, y, y_triangles)};
    if (y_first) std::swap(off[0], off[1]);
    int short_edges = 0;
    for (const FlatStrip& s : merge_congruent(off))
      for (const Triangle& t : s.triangles)
        for (int k = 0; k < 3; ++k) {
          const int a = t[k], b = t[(k + 1) % 3];
          const double length3 = (s.vertices3d[a] - s.vertices3d[b]).norm();
          if (length3 > 1e-3) continue;  // the short edge only (X's own are off by 4e-12)
          ++short_edges;
          EXPECT_LE(std::abs((s.vertices2d[a] - s.vertices2d[b]).norm() - length3), 1e-10 * length3)
              << (y_first ? "Y first" : "X first");
        }
    EXPECT_EQ(short_edges, 2);  // in both of Y's triangles
  }
}

TEST(MergeCongruent, BadInputThrows) {
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(1.0, 0.0, 1.0, 1.0, 8));
  auto bad = strips;
  bad[0].vertices2d.pop_back();
  EXPECT_THROW(merge_congruent(bad), InvalidInputException);
  bad = strips;
  bad[0].triangles[0][2] = -1;
  EXPECT_THROW(merge_congruent(bad), InvalidInputException);
  EXPECT_THROW(merge_congruent(strips, MergeOptions{.congruence_tolerance = -1.0}),
               InvalidInputException);
}

}  // namespace
}  // namespace papercraft
