#include "nodes/merge/congruent.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/errors.h"
#include "nodes/unfold/sequential.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using unfold_testing::circle_point;
using unfold_testing::count_overlapping_pairs;
using unfold_testing::euler_characteristic;
using unfold_testing::expect_isometric;
using unfold_testing::ladder_strip;
using unfold_testing::ring_strip;

void append(std::vector<FlatStrip>& all, const RuledStrip& strip) {
  auto flat = unfold_strip(strip, static_cast<int>(all.size()), static_cast<int>(all.size()));
  all.insert(all.end(), flat.begin(), flat.end());
}

std::size_t triangle_count(const std::vector<FlatStrip>& strips) {
  std::size_t count = 0;
  for (const FlatStrip& s : strips) count += s.triangles.size();
  return count;
}

void expect_valid(const std::vector<FlatStrip>& strips) {
  for (const FlatStrip& s : strips) {
    expect_isometric(s);
    EXPECT_EQ(count_overlapping_pairs(s), 0) << "strip " << s.id;
    for (const BoundaryEdge& e : s.boundary) {
      EXPECT_TRUE(e.kind == EdgeKind::Seam || e.kind == EdgeKind::Open);
      EXPECT_EQ(e.kind == EdgeKind::Seam, !e.label.empty());
    }
  }
}

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

// Two frustums of one cone: the shared circle develops to the same arc on both sides.
TEST(MergeCongruent, FrustumsOfOneConeMerge) {
  const int n = 24;
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(2.0, 0.0, 1.5, 1.0, n));
  append(strips, ring_strip(1.5, 1.0, 1.0, 2.0, n));
  auto merged = merge_congruent(strips);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].vertices2d.size(), 3u * (n + 1));
  expect_valid(merged);
}

// A cylinder under a cone frustum: the circle is straight on one side, an arc on the other.
TEST(MergeCongruent, BentBoundaryIsNotMerged) {
  const int n = 24;
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(1.0, 0.0, 1.0, 1.0, n));
  append(strips, ring_strip(1.0, 1.0, 0.5, 2.0, n));
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
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(2.0, -1.0, 1.0, 0.0, n));
  append(strips, ring_strip(1.0, 0.0, 2.0, 1.0, n));
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

// A crumb of two triangles no hinge takes whole: folded out over the edge a-b its second
// triangle lands on the neighbour X, folded out over d-c its first lands on a triangle of X
// placed there. One triangle at a time, each finds a free side, and the crumb is gone.
// (X's plane image need not be isometric to its "3D" points here: the join reads only the
// shared edges' plane lengths and the 3D points' identities.)
TEST(JoinSmallStrips, CrumbNoHingeTakesWholeIsTakenOneTriangleAtATime) {
  const Vec3 a(1, 0, 0), b(3, 0, 0), c(2, 2, 0), d(4, -1, 0);
  FlatStrip crumb;
  crumb.id = 1;
  crumb.source_strip = 1;
  crumb.vertices3d = {a, b, c, d};
  for (const Vec3& p : crumb.vertices3d) crumb.vertices2d.emplace_back(p.x(), p.y());
  crumb.triangles = {{0, 1, 2}, {1, 3, 2}};

  // X: the rectangle [0, 10] x [-3, 0] with a-b and d-c on its top edge, plus a blocker.
  const double dc = (d - c).norm();
  FlatStrip x;
  x.id = 0;
  x.source_strip = 0;
  const std::vector<Vec2> top{{0, 0}, {1, 0}, {3, 0}, {4.5, 0}, {9 - dc, 0}, {9, 0}, {10, 0}};
  const std::vector<Vec3> top3d{{0, 0, 5}, a, b, {4.5, 0, 5}, d, c, {10, 0, 5}};
  x.vertices2d = top;
  x.vertices3d = top3d;
  x.vertices2d.push_back({0, -3});  // 7
  x.vertices3d.push_back({0, -3, 5});
  x.vertices2d.push_back({10, -3});  // 8
  x.vertices3d.push_back({10, -3, 5});
  for (int i = 0; i + 1 < 7; ++i) x.triangles.push_back({7, i + 1, i});
  x.triangles.push_back({7, 8, 6});
  // Where the crumb's first triangle lands when the crumb is folded out over d-c.
  const Vec2 d2 = x.vertices2d[4], c2 = x.vertices2d[5];
  const Vec2 dy(d.x(), d.y()), cy(c.x(), c.y());
  const double turn = std::atan2((c2 - d2).y(), (c2 - d2).x()) - std::atan2((cy - dy).y(), (cy - dy).x());
  auto landed = [&](const Vec3& p) {
    const Vec2 q = Vec2(p.x(), p.y()) - dy;
    return Vec2(Vec2(std::cos(turn) * q.x() - std::sin(turn) * q.y(),
                     std::sin(turn) * q.x() + std::cos(turn) * q.y()) + d2);
  };
  const Vec2 centre = (landed(a) + landed(b) + landed(c)) / 3.0;
  for (const Vec3& p : {a, b, c}) {
    x.vertices2d.push_back(centre + 0.5 * (landed(p) - centre));
    x.vertices3d.push_back(Vec3(x.vertices2d.back().x(), x.vertices2d.back().y(), 7.0));
  }
  x.triangles.push_back({9, 10, 11});

  std::vector<int> left;
  const auto joined = join_small_strips({x, crumb}, 5.0, {}, &left);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_TRUE(left.empty());
  EXPECT_EQ(joined[0].id, 0);
  EXPECT_EQ(joined[0].triangles.size(), x.triangles.size() + 2);
  EXPECT_EQ(count_overlapping_pairs(joined[0]), 0);
  // Both crumb triangles keep their shape in the plane.
  for (std::size_t t = x.triangles.size(); t < joined[0].triangles.size(); ++t) {
    const Triangle& tri = joined[0].triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int u = tri[k], v = tri[(k + 1) % 3];
      EXPECT_NEAR((joined[0].vertices2d[u] - joined[0].vertices2d[v]).norm(),
                  (joined[0].vertices3d[u] - joined[0].vertices3d[v]).norm(), 1e-9);
    }
  }
}

// Without the neighbour's room on either side the crumb stays whole and is named.
TEST(JoinSmallStrips, CrumbWithNoFreeSideStaysAndIsNamed) {
  FlatStrip crumb;
  crumb.id = 1;
  crumb.vertices3d = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  crumb.vertices2d = {{0, 0}, {1, 0}, {0, 1}};
  crumb.triangles = {{0, 1, 2}};
  // X holds the crumb's edge 0-1 (reversed) with its image under a triangle of X.
  FlatStrip x;
  x.id = 0;
  x.vertices3d = {{1, 0, 0}, {0, 0, 0}, {0.5, -10, 3}, {0.2, 0.2, 4}, {0.6, 0.2, 4}, {0.2, 0.6, 4}};
  x.vertices2d = {{1, 0}, {0, 0}, {0.5, -10}, {0.2, 0.2}, {0.6, 0.2}, {0.2, 0.6}};
  x.triangles = {{0, 1, 2}, {3, 4, 5}};
  std::vector<int> left;
  const auto joined = join_small_strips({x, crumb}, 1.0, {}, &left);
  EXPECT_EQ(joined.size(), 2u);
  EXPECT_EQ(left, std::vector<int>{1});
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
