#include "engine/unfold/sequential.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using unfold_testing::circle_point;
using unfold_testing::count_overlapping_pairs;
using unfold_testing::expect_isometric;
using unfold_testing::fan_strip;
using unfold_testing::ladder_strip;
using unfold_testing::ring_strip;

// Flat vertices that are copies of 3D point p.
std::vector<int> copies_of(const FlatStrip& s, const Vec3& p) {
  std::vector<int> result;
  for (int v = 0; v < static_cast<int>(s.vertices3d.size()); ++v)
    if (s.vertices3d[v] == p) result.push_back(v);
  return result;
}

void expect_boundary_chained_with_strip_on_left(const FlatStrip& s) {
  // Each boundary edge is a directed edge of a triangle (so the strip is on its left, the
  // triangles being counter-clockwise) and its reverse is in none.
  for (const BoundaryEdge& e : s.boundary) {
    int forward = 0, backward = 0;
    for (const Triangle& t : s.triangles)
      for (int i = 0; i < 3; ++i) {
        forward += t[i] == e.v0 && t[(i + 1) % 3] == e.v1;
        backward += t[i] == e.v1 && t[(i + 1) % 3] == e.v0;
      }
    EXPECT_EQ(forward, 1);
    EXPECT_EQ(backward, 0);
    EXPECT_EQ(e.kind, EdgeKind::Cut);
  }
}

// A circular cylinder develops into a rectangle: width the perimeter of the n-gon, height h.
TEST(UnfoldSequential, CylinderUnrollsToExactRectangle) {
  const int n = 24;
  const double r = 1.5, h = 2.0;
  RuledStrip strip = ring_strip(r, 0.0, r, h, n);
  auto flat = unfold_strip(strip, 7, 30);
  ASSERT_EQ(flat.size(), 1u);
  const FlatStrip& s = flat[0];
  EXPECT_EQ(s.id, 30);
  EXPECT_EQ(s.source_strip, 7);
  EXPECT_EQ(s.triangles.size(), 2u * n);
  EXPECT_EQ(s.vertices2d.size(), 2u * n + 2);  // the opened ruling is duplicated
  expect_isometric(s);
  EXPECT_EQ(count_overlapping_pairs(s), 0);

  // All rulings are equally short: it opens at A's first vertex.
  auto a0 = copies_of(s, strip.mesh.vertices[0]);
  auto b0 = copies_of(s, strip.mesh.vertices[n]);
  ASSERT_EQ(a0.size(), 2u);
  ASSERT_EQ(b0.size(), 2u);
  const double width = n * 2.0 * r * std::sin(M_PI / n);
  const Vec2 origin = s.vertices2d[a0[0]];
  Vec2 along = s.vertices2d[a0[1]] - origin;
  ASSERT_NEAR(along.norm(), width, 1e-9 * width);
  Vec2 u = along / along.norm();
  Vec2 normal(-u.y(), u.x());
  double side = 0.0;
  for (int v = 0; v < static_cast<int>(s.vertices2d.size()); ++v) {
    Vec2 d = s.vertices2d[v] - origin;
    double x = u.dot(d), y = normal.dot(d);
    bool on_a = s.vertices3d[v].z() == 0.0;
    if (!on_a && side == 0.0) side = y > 0 ? 1.0 : -1.0;
    EXPECT_NEAR(std::abs(y), on_a ? 0.0 : h, 1e-9) << "vertex " << v;
    EXPECT_GE(x, -1e-9);
    EXPECT_LE(x, width + 1e-9);
  }
  for (int v = 0; v < static_cast<int>(s.vertices2d.size()); ++v) {
    if (s.vertices3d[v].z() == 0.0) continue;
    EXPECT_GT(side * normal.dot(s.vertices2d[v] - origin), 0.0);
  }
  double area = 0.0;
  for (const Triangle& t : s.triangles) area += unfold_testing::signed_area(s, t);
  EXPECT_NEAR(area, width * h, 1e-9 * width * h);

  EXPECT_EQ(s.boundary.size(), 2u * n + 2);
  for (std::size_t i = 0; i < s.boundary.size(); ++i)  // one loop: the rectangle
    EXPECT_EQ(s.boundary[i].v1, s.boundary[(i + 1) % s.boundary.size()].v0);
  expect_boundary_chained_with_strip_on_left(s);
}

// The shortest ruling is the one opened; its two ends are the only duplicated vertices.
TEST(UnfoldSequential, ClosedStripOpensAtShortestRuling) {
  const int n = 20;
  std::vector<Vec3> a, b;
  for (int i = 0; i < n; ++i) {
    a.push_back(circle_point(1.0, i, n, 0.0));
    double angle = 2.0 * M_PI * i / n;
    b.push_back(circle_point(1.0, i, n, 2.0 + 0.5 * std::cos(angle)));  // lowest at i = n/2
  }
  RuledStrip strip = ladder_strip(a, b, true);
  auto flat = unfold_strip(strip, 0, 0);
  ASSERT_EQ(flat.size(), 1u);
  expect_isometric(flat[0]);
  EXPECT_EQ(count_overlapping_pairs(flat[0]), 0);
  for (int v = 0; v < 2 * n; ++v) {
    std::size_t expected = (v == n / 2 || v == n + n / 2) ? 2u : 1u;
    EXPECT_EQ(copies_of(flat[0], strip.mesh.vertices[v]).size(), expected) << "vertex " << v;
  }
}

// A closed cone (fan) develops into one circular sector with the apex once.
TEST(UnfoldSequential, ConeDevelopsToSector) {
  const int n = 32;
  std::vector<Vec3> a;
  for (int i = 0; i < n; ++i) a.push_back(circle_point(1.0, i, n, 0.0));
  RuledStrip cone = fan_strip(a, Vec3(0, 0, 2.0), true);
  auto flat = unfold_strip(cone, 0, 0);
  ASSERT_EQ(flat.size(), 1u);
  const FlatStrip& s = flat[0];
  expect_isometric(s);
  EXPECT_EQ(count_overlapping_pairs(s), 0);
  EXPECT_EQ(s.triangles.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(s.vertices2d.size(), static_cast<std::size_t>(n + 2));
  auto apex = copies_of(s, cone.mesh.vertices[n]);
  ASSERT_EQ(apex.size(), 1u);
  auto a0 = copies_of(s, cone.mesh.vertices[0]);
  ASSERT_EQ(a0.size(), 2u);
  Vec2 u = s.vertices2d[a0[0]] - s.vertices2d[apex[0]];
  Vec2 v = s.vertices2d[a0[1]] - s.vertices2d[apex[0]];
  double opening = std::atan2(std::abs(unfold_testing::cross2(u, v)), u.dot(v));
  const double sector = unfold_testing::angle_sum_at(cone, n);
  ASSERT_LT(sector, M_PI);
  EXPECT_NEAR(opening, sector, 1e-9);
}

// A saddle fan turning more than 360 degrees around its apex cannot lie flat in one piece.
TEST(UnfoldSequential, FanOverFullTurnSplitsIntoOverlapFreeStrips) {
  const int n = 40;
  RuledStrip fan = unfold_testing::saddle_fan(n);
  ASSERT_GT(unfold_testing::angle_sum_at(fan, n), 2.5 * M_PI);
  auto flat = unfold_strip(fan, 3, 10);
  ASSERT_GE(flat.size(), 2u);
  std::size_t triangles = 0;
  for (std::size_t k = 0; k < flat.size(); ++k) {
    EXPECT_EQ(flat[k].id, 10 + static_cast<int>(k));
    EXPECT_EQ(flat[k].source_strip, 3);
    EXPECT_FALSE(flat[k].triangles.empty());
    expect_isometric(flat[k]);
    EXPECT_EQ(count_overlapping_pairs(flat[k]), 0) << "flat strip " << k;
    expect_boundary_chained_with_strip_on_left(flat[k]);
    triangles += flat[k].triangles.size();
  }
  EXPECT_EQ(triangles, static_cast<std::size_t>(n));
}

// An open helicoidal strip winding twice around its axis overlaps after about one turn.
TEST(UnfoldSequential, HelixStripSplits) {
  const int n = 120;
  std::vector<Vec3> a, b;
  for (int i = 0; i < n; ++i) {
    double angle = 4.0 * M_PI * i / (n - 1);
    a.push_back(Vec3(std::cos(angle), std::sin(angle), 0.15 * angle));
    b.push_back(Vec3(2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.15 * angle));
  }
  RuledStrip helix = ladder_strip(a, b, false);
  auto flat = unfold_strip(helix, 0, 0);
  ASSERT_GE(flat.size(), 2u);
  std::size_t triangles = 0;
  for (const FlatStrip& s : flat) {
    expect_isometric(s);
    EXPECT_EQ(count_overlapping_pairs(s), 0);
    triangles += s.triangles.size();
  }
  EXPECT_EQ(triangles, helix.mesh.triangles.size());
}

// A gently curved open strip stays in one piece; uvs follow their vertices.
TEST(UnfoldSequential, OpenStripKeepsUvsAndStaysWhole) {
  const int n = 30;
  std::vector<Vec3> a, b;
  for (int i = 0; i < n; ++i) {
    double t = i / double(n - 1);
    a.push_back(Vec3(t * 3.0, 0.2 * std::sin(3.0 * t), 0.1 * t * t));
    b.push_back(Vec3(t * 3.0 + 0.05 * std::cos(5.0 * t), 1.0, 0.3 * std::sin(2.0 * t)));
  }
  RuledStrip strip = ladder_strip(a, b, false);
  for (int v = 0; v < 2 * n; ++v) strip.uvs.push_back(Vec2(v, -v));
  auto flat = unfold_strip(strip, 0, 0);
  ASSERT_EQ(flat.size(), 1u);
  const FlatStrip& s = flat[0];
  expect_isometric(s);
  EXPECT_EQ(count_overlapping_pairs(s), 0);
  EXPECT_EQ(s.vertices2d.size(), 2u * n);
  ASSERT_EQ(s.uvs.size(), s.vertices2d.size());
  for (std::size_t v = 0; v < s.vertices3d.size(); ++v) {
    auto it = std::find(strip.mesh.vertices.begin(), strip.mesh.vertices.end(), s.vertices3d[v]);
    ASSERT_NE(it, strip.mesh.vertices.end());
    int source = static_cast<int>(it - strip.mesh.vertices.begin());
    EXPECT_EQ(s.uvs[v], strip.uvs[source]);
  }
  EXPECT_EQ(s.boundary.size(), 2u * n);
}

// A zero-length ruling (pinched strip), a zero-area triangle and a repeated index: no NaN,
// lengths kept.
TEST(UnfoldSequential, DegenerateTrianglesStayFinite) {
  std::vector<Vec3> a = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0)};
  std::vector<Vec3> b = {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(2, 1, 1), Vec3(3, 1, 1)};
  RuledStrip strip = ladder_strip(a, b, false);  // a_1 == b_1: two triangles have no area
  strip.mesh.triangles.push_back({0, 0, 4});     // repeated index: skipped
  auto flat = unfold_strip(strip, 0, 0);
  std::size_t triangles = 0;
  for (const FlatStrip& s : flat) {
    for (const Vec2& p : s.vertices2d) EXPECT_TRUE(p.allFinite());
    expect_isometric(s);
    triangles += s.triangles.size();
  }
  // The repeated index is skipped; (a0, a1, b1) and (a1, b2, b1) have two corners at one
  // point (a1 == b1) and go too.
  EXPECT_EQ(triangles, strip.mesh.triangles.size() - 3);
}

// A flat square fanned from one of its own corners (the apex lies on the polyline, as when the
// ruled stage fans a disc-shaped part from a boundary vertex): the two triangles with two
// corners at the apex have no area and are dropped, their copies of the apex welded, so the
// flat strip is the square's two triangles with four boundary edges, none of zero length.
TEST(UnfoldSequential, FanFromItsOwnCornerLeavesNoEmptyTriangle) {
  const std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
  const auto flat = unfold_strip(unfold_testing::fan_strip(square, square[0], true), 0, 0);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_EQ(flat[0].triangles.size(), 2u);
  EXPECT_EQ(flat[0].vertices2d.size(), 4u);
  EXPECT_EQ(flat[0].boundary.size(), 4u);
  expect_isometric(flat[0]);
  double area = 0;
  for (const Triangle& t : flat[0].triangles) {
    const double twice =
        unfold_testing::cross2(flat[0].vertices2d[t[1]] - flat[0].vertices2d[t[0]],
                               flat[0].vertices2d[t[2]] - flat[0].vertices2d[t[0]]);
    EXPECT_GT(twice, 1.0);
    area += 0.5 * twice;
  }
  EXPECT_NEAR(area, 4.0, 1e-12);
  for (const BoundaryEdge& e : flat[0].boundary)
    EXPECT_GT((flat[0].vertices2d[e.v1] - flat[0].vertices2d[e.v0]).norm(), 1.0);
  // The same fan with its apex at the corner but one copy of it moved off (a real fan): kept.
  const auto real = unfold_strip(unfold_testing::fan_strip(square, Vec3(0, 0, 0.5), true), 0, 0);
  std::size_t triangles = 0;
  for (const FlatStrip& s : real) triangles += s.triangles.size();
  EXPECT_EQ(triangles, 4u);
}

// A flat disc fanned from its centre lies flat in one piece: no radial slit, only the rim
// is boundary. A cone (not flat) keeps its opened ruling.
TEST(UnfoldSequential, FlatCapClosesWithoutASlit) {
  const int n = 24;
  std::vector<Vec3> rim;
  for (int i = 0; i < n; ++i) rim.push_back(unfold_testing::circle_point(1.0, i, n, 0.0));
  const auto flat = unfold_strip(unfold_testing::fan_strip(rim, Vec3(0.1, -0.2, 0.0), true), 0, 0);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_EQ(flat[0].boundary.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(flat[0].vertices2d.size(), static_cast<std::size_t>(n + 1));
  const auto cone = unfold_strip(unfold_testing::fan_strip(rim, Vec3(0.0, 0.0, 0.8), true), 0, 0);
  ASSERT_EQ(cone.size(), 1u);
  EXPECT_EQ(cone[0].boundary.size(), static_cast<std::size_t>(n + 2));
}

// A cap that is flat but for a cone's worth of 1e-11 at its apex, with a rim edge 1e-4 long
// beside the ruling it opens along: the two copies of that ruling land within the weld's reach,
// but welding them would stretch that short edge by a part in 1e7. Every edge keeps its 3D
// length (to 1e-10 of it), so a seam along it is the same length on both sides.
TEST(UnfoldSequential, NearlyFlatCapIsWeldedOnlyWhereEveryEdgeKeepsItsLength) {
  const int n = 24;
  std::vector<Vec3> rim;
  for (int i = 0; i < n; ++i) {
    rim.push_back(unfold_testing::circle_point(1.0, i, n, 0.0));
    // Beside the rim point nearest the apex (at 300 degrees), where the shortest ruling ends.
    if (i == 20) rim.push_back({std::cos(5 * M_PI / 3 + 1e-4), std::sin(5 * M_PI / 3 + 1e-4), 0.0});
  }
  const double height = std::sqrt(1e-11 / M_PI);  // a full turn less about 1e-11 at the apex
  const auto flat =
      unfold_strip(unfold_testing::fan_strip(rim, Vec3(0.1, -0.2, height), true), 0, 0);
  std::size_t triangles = 0;
  for (const FlatStrip& s : flat) {
    triangles += s.triangles.size();
    for (const Triangle& t : s.triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const double length3 = (s.vertices3d[a] - s.vertices3d[b]).norm();
        const double length2 = (s.vertices2d[a] - s.vertices2d[b]).norm();
        EXPECT_LE(std::abs(length2 - length3), 1e-10 * length3) << a << "-" << b;
      }
  }
  EXPECT_EQ(triangles, rim.size());
}

TEST(UnfoldSequential, BadInputThrows) {
  RuledStrip strip = ring_strip(1.0, 0.0, 1.0, 1.0, 8);
  RuledStrip bad_index = strip;
  bad_index.mesh.triangles[3][1] = 99;
  EXPECT_THROW(unfold_strip(bad_index, 0, 0), InvalidInputException);
  RuledStrip bad_uvs = strip;
  bad_uvs.uvs.resize(3);
  EXPECT_THROW(unfold_strip(bad_uvs, 0, 0), InvalidInputException);
  RuledStrip bad_counts = strip;
  bad_counts.a_count = 5;
  EXPECT_THROW(unfold_strip(bad_counts, 0, 0), InvalidInputException);
  EXPECT_TRUE(unfold_strip(RuledStrip{}, 0, 0).empty());
}

}  // namespace
}  // namespace papercraft
