#include "nodes/merge/congruent.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "core/piece_width.h"
#include "engine/unfold/sequential.h"
#include "nlohmann/json.hpp"
#include "support/flat_strips_json.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using unfold_testing::circle_point;
using unfold_testing::count_overlapping_pairs;
using unfold_testing::euler_characteristic;
using unfold_testing::expect_isometric;
using unfold_testing::ladder_strip;
using unfold_testing::ring_strip;
using unfold_testing::signed_area;

void append(std::vector<FlatStrip>& all, const RuledStrip& strip) {
  auto flat = unfold_strip(strip, static_cast<int>(all.size()), static_cast<int>(all.size()));
  all.insert(all.end(), flat.begin(), flat.end());
}

std::size_t triangle_count(const std::vector<FlatStrip>& strips) {
  std::size_t count = 0;
  for (const FlatStrip& s : strips) count += s.triangles.size();
  return count;
}

// The area of a strip laid flat with counter-clockwise triangles (expect_valid checks that).
double area_of(const FlatStrip& strip) {
  double sum = 0.0;
  for (const Triangle& t : strip.triangles) sum += signed_area(strip, t);
  return sum;
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

// The floor a-b-c-d (at z = 0, corners counter-clockwise), laid out in the plane as it lies.
// A crumb at a saddle: four triangles around a vertex whose angles there add up to about 375
// degrees. X is three of them laid flat as a fan (about 272 degrees) with one more triangle on
// the outer edge of its first; the fourth is the crumb. Folded out over either edge it shares
// with X, the crumb lands on X's other end, and a single triangle cannot be taken apart; so it
// grows instead, taking X's first triangle together with the triangle X held only through it.
TEST(JoinSmallStrips, CrumbAtASaddleGrowsByTakingItsNeighboursEnd) {
  constexpr double kDegree = M_PI / 180.0;
  const double azimuth[4] = {0, 100, 190, 280}, elevation[4] = {15, -15, 15, -15};
  std::vector<Vec3> p;
  for (int k = 0; k < 4; ++k)
    p.emplace_back(std::cos(azimuth[k] * kDegree) * std::cos(elevation[k] * kDegree),
                   std::sin(azimuth[k] * kDegree) * std::cos(elevation[k] * kDegree),
                   std::sin(elevation[k] * kDegree));
  const Vec3 apex(0, 0, 0);
  auto angle = [&](int i, int j) { return std::acos(p[i].dot(p[j])); };  // at the apex
  ASSERT_GT(angle(0, 1) + angle(1, 2) + angle(2, 3) + angle(3, 0), 2 * M_PI + 10 * kDegree);
  auto at = [](double turn) { return Vec2(std::cos(turn), std::sin(turn)); };

  // X: the fan apex, p1, p2, p3, p0 from p1 at angle 0, and (p1, p1 + p2, p2) beyond p1-p2
  // (p1 + p2 lies in the plane of apex, p1, p2, so it lands at their images' sum).
  FlatStrip x;
  x.id = 0;
  x.source_strip = 0;
  x.vertices3d = {apex, p[1], p[2], p[3], p[0], p[1] + p[2]};
  const double turn2 = angle(1, 2), turn3 = turn2 + angle(2, 3), turn0 = turn3 + angle(3, 0);
  x.vertices2d = {Vec2(0, 0), at(0), at(turn2), at(turn3), at(turn0), at(0) + at(turn2)};
  x.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {1, 5, 2}};
  ASSERT_EQ(count_overlapping_pairs(x), 0);
  expect_isometric(x);
  // The crumb (apex, p0, p1), laid out on its own.
  FlatStrip crumb;
  crumb.id = 1;
  crumb.source_strip = 1;
  crumb.vertices3d = {apex, p[0], p[1]};
  crumb.vertices2d = {Vec2(0, 0), at(0), at(angle(0, 1))};
  crumb.triangles = {{0, 1, 2}};
  const double crumb_area = area_of(crumb);
  ASSERT_LT(crumb_area, 0.5);

  std::vector<int> left;
  const double min_area = 0.9;  // X keeps its last two triangles (about 1.0)
  const auto joined = join_small_strips({x, crumb}, min_area, {}, &left);
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_TRUE(left.empty());
  EXPECT_EQ(triangle_count(joined), 5u);
  expect_valid(joined);
  for (const FlatStrip& strip : joined) EXPECT_GE(area_of(strip), min_area) << strip.id;
  // The crumb kept its id and now holds X's first triangle and the one beyond it.
  const FlatStrip& grown = joined[0].id == 1 ? joined[0] : joined[1];
  ASSERT_EQ(grown.id, 1);
  EXPECT_EQ(grown.triangles.size(), 3u);
  EXPECT_NE(std::find(grown.vertices3d.begin(), grown.vertices3d.end(), p[1] + p[2]),
            grown.vertices3d.end());
}

// Flat strips of a real model as the merge node had them, with the node's limits (model
// units): tests/merge/data, written from a run at 2% and 200 mm.
struct MergeFixture {
  double min_area = 0.0, min_width = 0.0;
  std::vector<FlatStrip> strips;
};

MergeFixture read_fixture(const std::string& name) {
  std::ifstream in(std::string(PAPERCRAFT_SOURCE_DIR) + "/tests/merge/data/" + name);
  EXPECT_TRUE(in) << "missing test data " << name;
  MergeFixture fixture;
  if (!in) return fixture;
  const nlohmann::json j = nlohmann::json::parse(in);
  fixture.min_area = j.at("min_area").get<double>();
  fixture.min_width = j.at("min_width").get<double>();
  fixture.strips = testing::read_flat_strips(j.at("strips"));
  return fixture;
}

const FlatStrip* find_id(const std::vector<FlatStrip>& strips, int id) {
  for (const FlatStrip& s : strips)
    if (s.id == id) return &s;
  return nullptr;
}

// elephant-with-holes: crumb 79 (7 triangles, 55 mm^2) beside strip 78. Its first growths
// past min_area leave a piece narrower than min_width over more of its area than before (and
// than a quarter); it grows on until one does not, instead of giving up there.
// Crumb `id` of the fixture grows into its neighbours (every strip stays, none under min_area,
// none narrower than min_width over more of its area than it was, or than a quarter).
void expect_crumb_grown(const std::string& fixture_name, int id) {
  const MergeFixture fixture = read_fixture(fixture_name);
  const FlatStrip* crumb = find_id(fixture.strips, id);
  ASSERT_NE(crumb, nullptr);
  ASSERT_LT(area_of(*crumb), fixture.min_area);
  auto share = [&](const FlatStrip& s) {
    return narrow_area_fraction(s.vertices2d, s.triangles, fixture.min_width);
  };
  std::map<int, double> before;
  for (const FlatStrip& s : fixture.strips) before[s.id] = share(s);

  std::vector<int> left;
  const auto joined =
      join_small_strips(fixture.strips, fixture.min_area, {}, &left, fixture.min_width);
  EXPECT_TRUE(left.empty());
  ASSERT_EQ(joined.size(), fixture.strips.size());
  EXPECT_EQ(triangle_count(joined), triangle_count(fixture.strips));
  expect_valid(joined);
  for (const FlatStrip& strip : joined) {
    EXPECT_GE(area_of(strip), fixture.min_area) << strip.id;
    EXPECT_LE(share(strip), std::max(before[strip.id], 0.25) + 1e-12) << strip.id;
  }
}

TEST(JoinSmallStrips, CrumbWhoseFirstGrowthLeavesAPieceNarrowerGrowsOn) {
  ASSERT_EQ(read_fixture("elephant_with_holes_crumb_79.json").strips.size(), 2u);
  expect_crumb_grown("elephant_with_holes_crumb_79.json", 79);
}

// cow: crumb 10 (10 triangles, 30 mm^2) beside strips 2 and 7, fans of thin triangles. Grown
// the most compact way, it takes their thin triangles, whose tips only add narrow area, and
// ends narrower than min_width over more of its area than it began (and than a quarter): that
// growth is not kept. Grown again, taking first the triangle that leaves it narrow over the
// least share, it reaches min_area no narrower than it began.
TEST(JoinSmallStrips, CrumbGrowsTheLeastNarrowWayWhereTheMostCompactEndsNarrower) {
  ASSERT_EQ(read_fixture("cow_crumb_10_between_fans.json").strips.size(), 3u);
  expect_crumb_grown("cow_crumb_10_between_fans.json", 10);
}

// b9_mesh: a part of three strips, each under min_area (about 2.1 times min_area together).
// The first pass over the crumbs leaves crumb 187 (8 triangles) where it is; the narrow join
// then changes the strips beside it, and the crumbs given up are tried again: 187 grows past
// min_area and one crumb fewer is left.
TEST(JoinSmallAndNarrowStrips, CrumbGivenUpIsTriedAgainAfterTheNarrowJoins) {
  const MergeFixture fixture = read_fixture("b9_mesh_crumb_187_beside_a_band.json");
  ASSERT_EQ(fixture.strips.size(), 3u);
  ASSERT_NE(find_id(fixture.strips, 187), nullptr);
  ASSERT_LT(area_of(*find_id(fixture.strips, 187)), fixture.min_area);
  std::vector<int> first;
  join_small_strips(fixture.strips, fixture.min_area, {}, &first, fixture.min_width);
  ASSERT_EQ(std::count(first.begin(), first.end(), 187), 1);

  std::vector<int> left;
  const auto joined =
      join_small_and_narrow_strips(fixture.strips, fixture.min_area, fixture.min_width, {}, &left);
  EXPECT_EQ(std::count(left.begin(), left.end(), 187), 0);
  EXPECT_LT(left.size(), first.size());
  EXPECT_EQ(triangle_count(joined), triangle_count(fixture.strips));
  expect_valid(joined);
  for (const FlatStrip& strip : joined) {
    if (std::count(left.begin(), left.end(), strip.id) == 0) {
      EXPECT_GE(area_of(strip), fixture.min_area) << strip.id;
    }
  }
}

FlatStrip flat_floor(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  FlatStrip floor;
  floor.id = 0;
  floor.vertices3d = {a, b, c, d};
  for (const Vec3& p : floor.vertices3d) floor.vertices2d.emplace_back(p.x(), p.y());
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  return floor;
}

// A wall `h` high standing on the polyline `bottom` (at z = 0; points 0..n-1), its top
// points n..2n-1 `h` higher, unrolled straight along x. Walking `bottom` in order keeps the
// wall on the left, so it must run against the floor's edges.
FlatStrip straight_wall(const std::vector<Vec3>& bottom, double h) {
  FlatStrip wall;
  wall.id = 1;
  wall.source_strip = 1;
  const int n = static_cast<int>(bottom.size());
  double along = 0.0;
  for (int k = 0; k < n; ++k) {
    if (k > 0) along += (bottom[k] - bottom[k - 1]).norm();
    wall.vertices2d.push_back({along, 0.0});
    wall.vertices3d.push_back(bottom[k]);
  }
  for (int k = 0; k < n; ++k) {
    wall.vertices2d.push_back(wall.vertices2d[k] + Vec2(0, h));
    wall.vertices3d.push_back(bottom[k] + Vec3(0, 0, h));
  }
  for (int k = 0; k + 1 < n; ++k) {
    wall.triangles.push_back({k, k + 1, k + n + 1});
    wall.triangles.push_back({k, k + n + 1, k + n});
  }
  return wall;
}

// The 4 x 4 floor at z = 0 and a wall `h` high standing on two of its sides (c -> b -> a, a
// corner), unrolled straight.
FlatStrip corner_floor() {
  return flat_floor(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 4, 0), Vec3(0, 4, 0));
}
FlatStrip corner_wall(double h) {
  const Vec3 a(0, 0, 0), b(4, 0, 0), c(4, 4, 0), up(0, 0, h);
  FlatStrip wall;
  wall.id = 1;
  wall.source_strip = 1;
  wall.vertices3d = {c, b, a, c + up, b + up, a + up};
  wall.vertices2d = {{0, 0}, {4, 0}, {8, 0}, {0, h}, {4, h}, {8, h}};
  wall.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  return wall;
}

// A floor and a narrow wall standing on some of its sides: merge_congruent leaves them apart
// (the shared edges bend on the floor and run straight on the wall), then join_narrow_strips
// folds the wall out of the floor, into one piece wide over all but a quarter of its area.
std::vector<FlatStrip> join_wall_to_floor(const FlatStrip& floor, const FlatStrip& wall,
                                          double width) {
  const std::vector<FlatStrip> strips = merge_congruent({floor, wall});
  EXPECT_EQ(strips.size(), 2u);
  EXPECT_GT(narrow_area_fraction(strips.back().vertices2d, strips.back().triangles, width), 0.9);
  std::vector<FlatStrip> joined = join_narrow_strips(strips, width, 0.25);
  EXPECT_EQ(joined.size(), 1u);
  expect_valid(joined);
  for (const FlatStrip& s : joined)
    EXPECT_LT(narrow_area_fraction(s.vertices2d, s.triangles, width), 0.25);
  return joined;
}

// A wall 0.2 high around two sides of a 4 x 4 floor (one corner): the wall unfolds straight,
// the floor's two sides turn at the corner, so merge_congruent cannot join them. The wall is
// narrower than 0.5 everywhere; folded out over one side of the floor, its other half leaves
// the floor's other side at a right angle (a seam with room for a tab), and the union is a
// piece wide over all but a tenth of its area.
TEST(JoinNarrowStrips, WallIsFoldedOutOfTheFloorItStandsOn) {
  const FlatStrip floor = corner_floor();
  const FlatStrip wall = corner_wall(0.2);
  const double width = 0.5;
  const auto joined = join_wall_to_floor(floor, wall, width);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].id, 0);
  EXPECT_EQ(joined[0].triangles.size(), 6u);
  // One side of the floor is the hinge; the other is a seam of the piece with itself.
  int seam_edges = 0;
  for (const BoundaryEdge& e : joined[0].boundary) seam_edges += e.kind == EdgeKind::Seam;
  EXPECT_EQ(seam_edges, 2);

  // Without a width bound, or with a share no strip exceeds, nothing is joined.
  EXPECT_EQ(join_narrow_strips({floor, wall}, 0.0, 0.25).size(), 2u);
  EXPECT_EQ(join_narrow_strips({floor, wall}, width, 1.0).size(), 2u);
}

// A floor a -> b -> c -> d whose sides bend by 10 and 90 degrees (4, 4 and 3 long), and a
// wall 0.2 high standing on d -> c -> b -> a, unrolled straight.
std::pair<FlatStrip, FlatStrip> bent_floor_and_wall() {
  const double h = 0.2, turn = 10.0 * std::acos(-1.0) / 180.0;
  const Vec2 a(0, 0), b(4, 0), c = b + 4.0 * Vec2(std::cos(turn), std::sin(turn));
  const Vec2 d = c + 3.0 * Vec2(-std::sin(turn), std::cos(turn));
  auto lift = [](const Vec2& p, double z) { return Vec3(p.x(), p.y(), z); };
  FlatStrip floor;
  floor.id = 0;
  floor.vertices2d = {a, b, c, d};
  for (const Vec2& p : floor.vertices2d) floor.vertices3d.push_back(lift(p, 0));
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  const FlatStrip wall = straight_wall({lift(d, 0), lift(c, 0), lift(b, 0), lift(a, 0)}, h);
  return {floor, wall};
}

// A wall 0.2 high along three sides of a floor that bend by 10 and 90 degrees. Folded out over
// either of the first two sides, the wall passes the 10-degree bend 0.7 from the floor's edge
// (a slit, narrower than the width bound of 1, where no tab fits); over the third, the
// shortest, it leaves the floor at the right angle. That hinge is chosen.
TEST(JoinNarrowStrips, HingeThatLeavesNoSlitIsChosen) {
  const auto [floor, wall] = bent_floor_and_wall();
  const auto joined = join_wall_to_floor(floor, wall, 1.0);
  ASSERT_EQ(joined.size(), 1u);
  // Welded at c and d (the floor's points 2 and 3): 4 + 8 - 2 points, and the wall's first
  // two triangles use the floor's d and c.
  EXPECT_EQ(joined[0].vertices2d.size(), 10u);
  ASSERT_EQ(joined[0].triangles.size(), 8u);
  EXPECT_EQ(joined[0].triangles[2][0], 3);
  EXPECT_EQ(joined[0].triangles[2][1], 2);
}

// The floor and wall of HingeThatLeavesNoSlitIsChosen, the wall now a crumb (2.2 of area
// against min_area 5): join_small_strips folds it out over the floor's shortest side, where it
// leaves the floor at the right angle, and not over the longer side at the other end of the
// chain, the first hinge that lays it flat, where it passes the 10-degree bend 0.7 from the
// floor's edge (a slit, where no tab fits). Without a width to measure the slit by, that first
// hinge is kept.
TEST(JoinSmallStrips, CrumbIsHingedWhereItLeavesNoSlit) {
  const auto [floor, wall] = bent_floor_and_wall();
  const std::vector<FlatStrip> strips = merge_congruent({floor, wall});
  ASSERT_EQ(strips.size(), 2u);
  ASSERT_LT(area_of(strips[1]), 5.0);
  std::vector<int> left;
  const auto joined = join_small_strips(strips, 5.0, {}, &left, 1.0);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_TRUE(left.empty());
  expect_valid(joined);
  // Welded at c and d (the floor's points 2 and 3): the wall's first triangle uses them.
  EXPECT_EQ(joined[0].vertices2d.size(), 10u);
  ASSERT_EQ(joined[0].triangles.size(), 8u);
  EXPECT_EQ(joined[0].triangles[2][0], 3);
  EXPECT_EQ(joined[0].triangles[2][1], 2);

  // Width 0: the first hinge, b -> a (an end of the chain, and longer): welded at a and b.
  const auto first = join_small_strips(strips, 5.0, {}, &left, 0.0);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(first[0].triangles.size(), 8u);
  EXPECT_EQ(first[0].triangles[6][1], 0);
  EXPECT_EQ(first[0].triangles[7][0], 1);
}

// Two walls 0.2 high stacked on one side of a 4 x 4 floor, the upper one first in the order.
// Folded onto the lower wall alone the upper one stays as narrow as it was, so it is passed
// over; once the lower wall is folded out of the floor, the upper one folds out of that union
// (a hinge on the lower wall's top edge, which is now an edge of the floor's piece).
TEST(JoinNarrowStrips, StripPassedOverIsTriedAgainBesideTheUnion) {
  const double h = 0.2;
  const Vec3 a(0, 0, 0), b(4, 0, 0), c(4, 4, 0), d(0, 4, 0), up(0, 0, h);
  const FlatStrip floor = flat_floor(a, b, c, d);
  auto wall = [&](int id, const Vec3& lift) {  // on the floor's side a-b, `lift` above it
    FlatStrip strip;
    strip.id = id;
    strip.source_strip = id;
    strip.vertices3d = {b + lift, a + lift, b + lift + up, a + lift + up};
    strip.vertices2d = {{0, 0}, {4, 0}, {0, h}, {4, h}};
    strip.triangles = {{0, 1, 3}, {0, 3, 2}};
    return strip;
  };
  const std::vector<FlatStrip> strips{floor, wall(1, up), wall(2, Vec3::Zero())};
  const double width = 0.5;
  for (std::size_t i = 1; i < strips.size(); ++i)
    EXPECT_EQ(narrow_area_fraction(strips[i].vertices2d, strips[i].triangles, width), 1.0);
  const auto joined = join_narrow_strips(strips, width, 0.25);
  ASSERT_EQ(joined.size(), 1u);
  expect_valid(joined);
  EXPECT_EQ(joined[0].triangles.size(), 6u);
  EXPECT_LT(narrow_area_fraction(joined[0].vertices2d, joined[0].triangles, width), 0.25);
}

// A wall 0.2 high along three sides of a 1 x 0.6 floor, unrolled straight: folded out over one
// side, the rest of it sticks out beyond the floor's corner, so the piece is narrower than 0.5
// over more than a quarter of its area, more than the floor was. But it is narrow over no more
// area than the wall and the floor were apart (the wall's overhang), with one seam fewer: kept.
TEST(JoinNarrowStrips, BandIsKeptOnANeighbourWhereTheUnionIsNarrowOverNoMoreArea) {
  const double h = 0.2, width = 0.5;
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 0.6, 0), d(0, 0.6, 0);
  const FlatStrip floor = flat_floor(a, b, c, d);
  const FlatStrip wall = straight_wall({d, c, b, a}, h);
  auto share = [&](const FlatStrip& s) {
    return narrow_area_fraction(s.vertices2d, s.triangles, width);
  };
  EXPECT_LT(share(floor), 0.25);
  EXPECT_EQ(share(wall), 1.0);
  const auto joined = join_narrow_strips({floor, wall}, width, 0.25);
  ASSERT_EQ(joined.size(), 1u);
  expect_valid(joined);
  EXPECT_GT(share(joined[0]), 0.25);
  EXPECT_LE(share(joined[0]) * area_of(joined[0]), share(floor) * area_of(floor) + area_of(wall));
}

// A fan of five thin triangles (2 degrees each, radius 10) at a saddle: the rest of the fan
// around its apex, X, spans about 357 degrees laid flat, so folded out over either edge it
// shares with X the band lands on X's other end, and no hinge takes it. It grows instead,
// taking X's triangle beside it, until it is no longer narrow.
TEST(JoinNarrowStrips, FanAtASaddleNoHingeTakesGrowsWide) {
  constexpr double kDegree = M_PI / 180.0, kRadius = 10.0, kWidth = 1.0;
  auto rim = [&](double azimuth, double elevation) -> Vec3 {
    return Vec3(std::cos(azimuth * kDegree) * std::cos(elevation * kDegree),
                std::sin(azimuth * kDegree) * std::cos(elevation * kDegree),
                std::sin(elevation * kDegree)) *
           kRadius;
  };
  const Vec3 apex(0, 0, 0);
  FlatStrip band;
  band.id = 1;
  band.source_strip = 1;
  band.vertices3d = {apex};
  band.vertices2d = {Vec2(0, 0)};
  for (int i = 0; i <= 5; ++i) {
    band.vertices3d.push_back(rim(2.0 * i, 0));
    band.vertices2d.push_back(kRadius *
                              Vec2(std::cos(2.0 * i * kDegree), std::sin(2.0 * i * kDegree)));
    if (i > 0) band.triangles.push_back({0, i, i + 1});
  }
  // X: from the band's last ruling round to its first in eight steps, its rim points up and
  // down by 5 degrees (so its angles at the apex add up to more than the 350 degrees left).
  FlatStrip x;
  x.id = 0;
  x.source_strip = 0;
  x.vertices3d = {apex};
  x.vertices2d = {Vec2(0, 0)};
  double turn = 0.0;
  for (int k = 0; k <= 8; ++k) {
    const double elevation = k == 0 || k == 8 ? 0.0 : (k % 2 ? -5.0 : 5.0);
    x.vertices3d.push_back(k == 8 ? band.vertices3d[1] : rim(10.0 + 43.75 * k, elevation));
    if (k > 0) {
      const Vec3& a = x.vertices3d[k];
      const Vec3& b = x.vertices3d[k + 1];
      turn += std::acos(a.dot(b) / (a.norm() * b.norm()));
      x.triangles.push_back({0, k, k + 1});
    }
    x.vertices2d.push_back(kRadius * Vec2(std::cos(turn), std::sin(turn)));
  }
  ASSERT_GT(turn, 352 * kDegree);
  ASSERT_LT(turn, 359 * kDegree);
  ASSERT_EQ(count_overlapping_pairs(x), 0);
  expect_isometric(x);
  expect_isometric(band);
  auto share = [&](const FlatStrip& s) {
    return narrow_area_fraction(s.vertices2d, s.triangles, kWidth);
  };
  ASSERT_GT(share(band), 0.25);
  ASSERT_LT(share(x), 0.25);

  const auto joined = join_narrow_strips({x, band}, kWidth, 0.25, {}, 256, 1.0);
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(triangle_count(joined), 13u);
  expect_valid(joined);
  const FlatStrip& grown = joined[0].id == 1 ? joined[0] : joined[1];
  ASSERT_EQ(grown.id, 1);
  EXPECT_GT(grown.triangles.size(), 5u);
  for (const FlatStrip& strip : joined) EXPECT_LE(share(strip), 0.25) << strip.id;
}

// An L-shaped prism `h` high: a floor (z = 0) and a ceiling (z = h), each an 8 x 8 square less
// a 4 x 4 notch at (4..8, 0..4), and its wall along the notch's two sides, from (8, 4) by
// (4, 4) to (4, 0) in `steps` segments per side, unrolled straight (8 long). Each plate is a
// fan from (0, 8) over its outline, the notch's sides split where the wall's points are; seen
// from outside the prism the ceiling turns the other way, so it is laid out mirrored.
struct LPrism {
  FlatStrip floor, ceiling, wall;
};

// The floor (the plate at z = 0, counter-clockwise `triangles` over `points`) and the ceiling
// (the same at z = h; seen from outside the prism it turns the other way, so it is laid out
// mirrored) of a prism whose wall is already in place; checks all three.
void add_plates(LPrism& prism, const std::vector<Vec3>& points,
                const std::vector<Triangle>& triangles, double h) {
  prism.floor.id = 0, prism.ceiling.id = 2;
  prism.floor.source_strip = 0, prism.ceiling.source_strip = 2;
  for (const Vec3& p : points) {
    prism.floor.vertices3d.push_back(p);
    prism.floor.vertices2d.emplace_back(p.x(), p.y());
    prism.ceiling.vertices3d.push_back(p + Vec3(0, 0, h));
    prism.ceiling.vertices2d.emplace_back(p.x(), -p.y());
  }
  for (const Triangle& t : triangles) {
    prism.floor.triangles.push_back(t);
    prism.ceiling.triangles.push_back({t[0], t[2], t[1]});
  }
  for (const FlatStrip* s : {&prism.floor, &prism.ceiling, &prism.wall}) {
    expect_isometric(*s);
    EXPECT_EQ(count_overlapping_pairs(*s), 0);
  }
}

LPrism l_prism(double h, int steps) {
  std::vector<Vec3> bottom;  // the wall's foot, walked with the wall on its left
  for (int k = 0; k <= steps; ++k) bottom.emplace_back(8.0 - 4.0 * k / steps, 4.0, 0.0);
  for (int k = 1; k <= steps; ++k) bottom.emplace_back(4.0, 4.0 - 4.0 * k / steps, 0.0);
  LPrism prism;
  prism.wall = straight_wall(bottom, h);
  std::vector<Vec3> outline = {{0, 8, 0}, {0, 0, 0}, {4, 0, 0}};
  for (auto it = bottom.rbegin() + 1; it != bottom.rend(); ++it) outline.push_back(*it);
  outline.emplace_back(8, 8, 0);
  std::vector<Triangle> fan;
  for (int k = 1; k + 1 < static_cast<int>(outline.size()); ++k) fan.push_back({0, k, k + 1});
  add_plates(prism, outline, fan, h);
  return prism;
}

// The prism 0.2 high with a wall of four triangles. Folded out of the floor or the ceiling
// over any edge, the wall runs on past the notch's corner into that plate (the plate's sides
// turn by 90 degrees where the wall is straight), so no hinge takes it. Cut at the corner, one
// half folds out of the floor into its notch, the other out of the ceiling into its own: two
// pieces, neither narrow.
// The prism's narrow wall (0.5 wide at most) joined by join_narrow_strips: checks that the
// pieces left are valid, that none is the wall and none narrow, and returns them.
std::vector<FlatStrip> wall_folded_out(const LPrism& prism) {
  const double width = 0.5;
  auto share = [&](const FlatStrip& s) {
    return narrow_area_fraction(s.vertices2d, s.triangles, width);
  };
  EXPECT_GT(share(prism.wall), 0.9);
  const std::vector<FlatStrip> strips = merge_congruent({prism.floor, prism.wall, prism.ceiling});
  EXPECT_EQ(strips.size(), 3u);
  const auto joined = join_narrow_strips(strips, width, 0.25);
  expect_valid(joined);
  for (const FlatStrip& strip : joined) {
    EXPECT_NE(strip.id, prism.wall.id);
    EXPECT_LE(share(strip), 0.25) << strip.id;
  }
  return joined;
}

TEST(JoinNarrowStrips, BandNoHingeTakesWholeIsCutInTwoAndEachHalfFoldedOut) {
  const auto joined = wall_folded_out(l_prism(0.2, 1));
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(triangle_count(joined), 12u);
  for (const FlatStrip& strip : joined)
    EXPECT_EQ(strip.triangles.size(), 6u) << strip.id;  // its plate and two of the wall's
}

// A U-shaped prism `h` high: floor and ceiling a 12 x 8 plate less a 4 x 4 notch at
// (4..8, 0..4), and its wall along the notch's three sides, from (8, 0) by (8, 4) and (4, 4) to
// (4, 0), unrolled straight (12 long). The plates are triangulated by hand (the U is not
// star-shaped); the ceiling is laid out mirrored, as in l_prism.
// A prism `h` high whose wall stands on `bottom` (walked with the wall on its left), unrolled
// straight, and whose plates are `triangles` over `points` (add_plates).
LPrism walled_prism(const std::vector<Vec3>& bottom, const std::vector<Vec3>& points,
                    const std::vector<Triangle>& triangles, double h) {
  LPrism prism;
  prism.wall = straight_wall(bottom, h);
  add_plates(prism, points, triangles, h);
  return prism;
}

LPrism u_prism(double h) {
  // A, B, C, D, E, F, G, H, and I, J on the plate's sides.
  return walled_prism(
      {{8, 0, 0}, {8, 4, 0}, {4, 4, 0}, {4, 0, 0}},
      {{0, 0, 0},
       {4, 0, 0},
       {4, 4, 0},
       {8, 4, 0},
       {8, 0, 0},
       {12, 0, 0},
       {12, 8, 0},
       {0, 8, 0},
       {0, 4, 0},
       {12, 4, 0}},
      {{0, 1, 2}, {0, 2, 8}, {7, 8, 2}, {7, 2, 3}, {7, 3, 9}, {7, 9, 6}, {3, 4, 5}, {3, 5, 9}}, h);
}

// The U prism 0.2 high. Cut anywhere in two, the wall leaves a half that turns a corner of the
// notch, and that half, folded out of either plate, runs on past the corner into the plate. Cut
// at both corners, each side folds out of a plate into its notch, neighbouring sides onto
// different plates (on one plate they would overlap in the notch's corner): two pieces, neither
// the wall, neither narrow.
TEST(JoinNarrowStrips, BandWhoseNeighboursTurnTwiceIsCutInThree) {
  const auto joined = wall_folded_out(u_prism(0.2));
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(triangle_count(joined), 22u);  // 8 on each plate and the wall's 6
  // The floor takes the two sides (4 triangles), the ceiling the side between them (2).
  std::vector<std::size_t> sizes = {joined[0].triangles.size(), joined[1].triangles.size()};
  std::sort(sizes.begin(), sizes.end());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{10, 12}));
}

// A plate 12 x 8 with a 4 x 4 hole at (4..8, 2..6), `h` thick: floor, ceiling, and the wall
// round the hole, a closed band opened at the hole's corner (8, 2) (a seam with itself),
// unrolled straight (16 long). The plates are triangulated by hand round the hole.
LPrism holed_prism(double h) {
  // A, B, C, D the plate's corners, E, F, G, H the hole's.
  return walled_prism(
      {{8, 2, 0}, {8, 6, 0}, {4, 6, 0}, {4, 2, 0}, {8, 2, 0}},
      {{0, 0, 0}, {12, 0, 0}, {12, 8, 0}, {0, 8, 0}, {4, 2, 0}, {8, 2, 0}, {8, 6, 0}, {4, 6, 0}},
      {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}}, h);
}

// The holed prism 0.2 high. Any piece of the wall that turns a corner of the hole, folded out of
// either plate, runs on past the corner into the plate; so the band is cut at the three corners
// it still turns, into four sides, and each side folds into the hole, neighbouring sides onto
// different plates (on one plate they would overlap in the hole's corner). Cut in three at
// most, one piece turns a corner, and the band stayed a narrow piece of its own.
TEST(JoinNarrowStrips, BandRoundAHoleIsCutInFour) {
  const auto joined = wall_folded_out(holed_prism(0.2));
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(triangle_count(joined), 24u);  // 8 on each plate and the wall's 8
  // Each plate takes two opposite sides (4 triangles).
  for (const FlatStrip& strip : joined) EXPECT_EQ(strip.triangles.size(), 12u) << strip.id;

  // Cut in three at most (the merge node's depth before it refines in 3D), the wall stays a
  // piece of its own.
  const LPrism prism = holed_prism(0.2);
  MergeOptions three;
  three.most_band_pieces = 3;
  const auto kept = join_narrow_strips(merge_congruent({prism.floor, prism.wall, prism.ceiling}),
                                       0.5, 0.25, three);
  EXPECT_EQ(kept.size(), 3u);
}

// The same prism with its wall in 160 triangles (40 along each side of the notch), and a
// min_area above the wall's: a crumb no hinge takes whole, too many triangles to take apart one
// by one, is cut in two, each half folded out of a plate, rather than grown.
TEST(JoinSmallStrips, CrumbNoHingeTakesWholeIsCutInTwoAndEachHalfFoldedOut) {
  const double width = 0.5, min_area = 2.0;  // the wall: 8 x 0.2
  const LPrism prism = l_prism(0.2, 40);
  ASSERT_EQ(prism.wall.triangles.size(), 160u);
  ASSERT_LT(area_of(prism.wall), min_area);
  const std::vector<FlatStrip> strips = merge_congruent({prism.floor, prism.wall, prism.ceiling});
  ASSERT_EQ(strips.size(), 3u);

  std::vector<int> left;
  const auto joined = join_small_strips(strips, min_area, {}, &left, width);
  EXPECT_TRUE(left.empty());
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(triangle_count(joined), triangle_count(strips));
  expect_valid(joined);
  for (const FlatStrip& strip : joined) {
    EXPECT_NE(strip.id, prism.wall.id);
    EXPECT_LE(narrow_area_fraction(strip.vertices2d, strip.triangles, width), 0.25) << strip.id;
  }
}

// Two bands side by side: joining them would leave a piece as narrow as each, so both stay.
TEST(JoinNarrowStrips, TwoBandsAreNotJoinedIntoOneAsNarrow) {
  const int n = 16;
  std::vector<FlatStrip> strips;
  append(strips, ring_strip(1.0, 0.0, 1.0, 0.1, n));
  append(strips, ring_strip(1.0, 0.1, 0.9, 0.2, n));
  strips = merge_congruent(strips);
  ASSERT_EQ(strips.size(), 2u);
  EXPECT_EQ(join_narrow_strips(strips, 0.5, 0.25).size(), 2u);
}

// A 4 x 4 floor and a wall 1.5 high around two of its sides (a corner): neither a crumb nor
// narrow, and merge_congruent cannot join them (the floor's sides turn, the wall runs
// straight). The wall's 12 is under twice a min_area of 10, so hinge_modest_strips folds it
// out of the floor: one piece, all its triangles, none overlapping, the floor's other side a
// seam of the piece with itself.
TEST(HingeModestStrips, PieceUnderTwiceMinAreaIsFoldedOutOfItsNeighbour) {
  const std::vector<FlatStrip> strips = merge_congruent({corner_floor(), corner_wall(1.5)});
  ASSERT_EQ(strips.size(), 2u);
  const double min_area = 10.0, width = 0.5;
  std::vector<int> left;
  ASSERT_EQ(join_small_strips(strips, min_area, {}, &left, width).size(), 2u);
  ASSERT_EQ(join_narrow_strips(strips, width, 0.25).size(), 2u);

  const auto joined = hinge_modest_strips(strips, 2.0 * min_area);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].triangles.size(), 6u);
  EXPECT_NEAR(area_of(joined[0]), 28.0, 1e-9);
  expect_valid(joined);
  int seam_edges = 0;
  for (const BoundaryEdge& e : joined[0].boundary) seam_edges += e.kind == EdgeKind::Seam;
  EXPECT_EQ(seam_edges, 2);

  // The merge node's joins do it at the default factor of 2, and not at a factor of 1; a wall
  // as large as 2 min_area stays.
  EXPECT_EQ(join_small_and_narrow_strips(strips, min_area, width, {}, &left).size(), 1u);
  EXPECT_TRUE(left.empty());
  MergeOptions never;
  never.modest_join_factor = 1.0;
  EXPECT_EQ(join_small_and_narrow_strips(strips, min_area, width, never).size(), 2u);
  EXPECT_EQ(hinge_modest_strips(strips, 2.0 * 6.0).size(), 2u);
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

// The seam edges of `strips` (label_seams run) by their 3D segment: how many boundary edges
// each segment has. Exact seams: two for every segment (the two sides of one seam).
std::map<std::array<double, 6>, int> seam_edges_by_segment(const std::vector<FlatStrip>& strips) {
  std::map<std::array<double, 6>, int> count;
  for (const FlatStrip& s : strips)
    for (const BoundaryEdge& e : s.boundary) {
      if (e.kind != EdgeKind::Seam) continue;
      Vec3 p = s.vertices3d[e.v0], q = s.vertices3d[e.v1];
      if (std::make_tuple(q.x(), q.y(), q.z()) < std::make_tuple(p.x(), p.y(), p.z()))
        std::swap(p, q);
      ++count[{p.x(), p.y(), p.z(), q.x(), q.y(), q.z()}];
    }
  return count;
}

// No two triangles of `strips` on the same three 3D points.
void expect_every_triangle_once(const std::vector<FlatStrip>& strips) {
  std::set<std::array<double, 9>> corners;
  for (const FlatStrip& s : strips)
    for (const Triangle& t : s.triangles) {
      std::array<std::array<double, 3>, 3> c;
      for (int k = 0; k < 3; ++k)
        c[k] = {s.vertices3d[t[k]].x(), s.vertices3d[t[k]].y(), s.vertices3d[t[k]].z()};
      std::sort(c.begin(), c.end());
      EXPECT_TRUE(corners
                      .insert({c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0],
                               c[2][1], c[2][2]})
                      .second)
          << "strip " << s.id;
    }
}

// trimesh's 1002_tray_bottom.STL at 2% and 200 mm: the strips of two parts (11: 104 triangles,
// 13: 60) both fill the stretch between the points of their shared cut where it zigzags across
// a flat face, with the same 16 triangles. Printed as they are, four seam edges lie on one
// segment and no seam can be told from the other. Dropped from the later strip, each segment
// has the two sides of one seam, every triangle is printed once and the rest is untouched.
TEST(DropDoubleCoveredTriangles, TwoPartsFillingTheirZigzagCutPrintItOnce) {
  const MergeFixture fixture = read_fixture("tray_bottom_strips_11_13_both_cover_a_zigzag.json");
  ASSERT_EQ(fixture.strips.size(), 2u);
  // As merged without the drop: segments with more than two seam edges.
  int crowded = 0;
  for (const auto& [segment, edges] : seam_edges_by_segment(merge_congruent(fixture.strips)))
    crowded += edges > 2;
  EXPECT_GT(crowded, 0);

  std::size_t dropped = 0;
  const auto once = drop_double_covered_triangles(fixture.strips, &dropped);
  EXPECT_EQ(dropped, 16u);
  ASSERT_EQ(once.size(), 2u);
  EXPECT_EQ(once[0].triangles.size(), 104u);  // the first keeps its own
  EXPECT_EQ(once[1].triangles.size(), 60u - 16u);
  EXPECT_EQ(once[1].id, 13);
  expect_every_triangle_once(once);
  EXPECT_NEAR(area_of(once[0]), area_of(fixture.strips[0]), 1e-12 * area_of(fixture.strips[0]));
  const auto merged = merge_congruent(once);
  expect_valid(merged);
  for (const auto& [segment, edges] : seam_edges_by_segment(merged)) EXPECT_EQ(edges, 2);
  // Nothing printed twice: nothing dropped.
  std::size_t again = 1;
  EXPECT_EQ(drop_double_covered_triangles(once, &again).size(), 2u);
  EXPECT_EQ(again, 0u);
}

// elephant at 5%: strip 12 (62 triangles) prints 3 triangles of strip 9 too, across its middle.
// Dropped, what is left of 12 falls apart: each piece is a strip of its own, the largest keeping
// id 12, the others new ids after every strip's; every triangle is printed once and each piece
// keeps its layout (isometric, no overlap), its seams exact once merged.
TEST(DropDoubleCoveredTriangles, AStripTheDroppedTrianglesCrossIsSplitIntoItsPieces) {
  const MergeFixture fixture = read_fixture("elephant_5pc_strips_9_12_split_by_the_drop.json");
  ASSERT_EQ(fixture.strips.size(), 2u);
  std::size_t dropped = 0;
  const auto once = drop_double_covered_triangles(fixture.strips, &dropped);
  EXPECT_EQ(dropped, 3u);
  ASSERT_GT(once.size(), 2u);
  EXPECT_EQ(once[0].id, 9);
  EXPECT_EQ(once[0].triangles.size(), 78u);
  EXPECT_EQ(once[1].id, 12);
  for (std::size_t k = 2; k < once.size(); ++k) {
    EXPECT_EQ(once[k].id, static_cast<int>(11 + k));  // 13, 14, ...
    EXPECT_LE(once[k].triangles.size(), once[1].triangles.size());
  }
  EXPECT_EQ(triangle_count(once), 78u + 62u - 3u);
  expect_every_triangle_once(once);
  const auto merged = merge_congruent(once);
  expect_valid(merged);
  for (const auto& [segment, edges] : seam_edges_by_segment(merged)) EXPECT_EQ(edges, 2);
}

// A fan of triangles round a vertex: its centre and the 3D ends of its spokes (`spokes`, shared
// with the fan beside it), laid out in the plane with its corners `degrees` wide. Its first and
// last spokes are seams with strip `neighbour` (where `seam_last` for the last), its rim open.
FlatStrip fan(int id, int neighbour, const std::vector<Vec3>& spokes,
              const std::vector<double>& degrees, bool seam_last = true) {
  FlatStrip strip;
  strip.id = id;
  strip.vertices3d.push_back(Vec3::Zero());
  strip.vertices2d.push_back(Vec2::Zero());
  double angle = 0.0;
  for (std::size_t k = 0; k < spokes.size(); ++k) {
    if (k > 0) angle += degrees[k - 1] * M_PI / 180.0;
    strip.vertices3d.push_back(spokes[k]);
    strip.vertices2d.emplace_back(std::cos(angle), std::sin(angle));
  }
  const int n = static_cast<int>(spokes.size());
  for (int k = 1; k < n; ++k) strip.triangles.push_back({0, k, k + 1});
  strip.boundary = flat_boundary(strip.triangles);
  for (BoundaryEdge& e : strip.boundary) {
    const bool first = e.v0 == 0 && e.v1 == 1, last = e.v0 == n && e.v1 == 0;
    e.kind = first || (last && seam_last) ? EdgeKind::Seam : EdgeKind::Open;
    if (e.kind == EdgeKind::Seam) e.neighbour_strip = neighbour;
  }
  return strip;
}

// The spokes of two fans round a vertex (a zigzag about the plane z = 0): the first fan's
// four, then the second's, which begins at the first's last and ends at its first.
std::pair<std::vector<Vec3>, std::vector<Vec3>> spokes_of_two_fans() {
  std::vector<Vec3> spokes;
  for (int k = 0; k < 6; ++k)
    spokes.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.1 * (k % 2));
  return {{spokes[0], spokes[1], spokes[2], spokes[3]},
          {spokes[3], spokes[4], spokes[5], spokes[0]}};
}

// Two fans holding all of the surface round a vertex, each glued to the other along both its
// spokes there: their corners round it sum to 360 degrees where the surface is flat there and
// to more where it is a saddle, and a seam of one edge has no vertex inside it.
TEST(WidestCornerRoundASeamVertex, SumsBothPiecesCornersRoundTheVertexInsideTheirSeam) {
  const auto [first, second] = spokes_of_two_fans();
  const FlatStrip a = fan(1, 2, first, {50, 50, 50});
  EXPECT_NEAR(widest_corner_round_a_seam_vertex(a, fan(2, 1, second, {70, 70, 70})), 360.0, 1e-9);
  const FlatStrip saddle = fan(2, 1, second, {80, 80, 70});
  EXPECT_NEAR(widest_corner_round_a_seam_vertex(a, saddle), 380.0, 1e-9);
  EXPECT_NEAR(widest_corner_round_a_seam_vertex(saddle, a), 380.0, 1e-9);
  // Glued along one spoke only: the seam is one edge, with no vertex inside it.
  EXPECT_EQ(widest_corner_round_a_seam_vertex(fan(1, 2, first, {50, 50, 50}, false), saddle), 0.0);
  // Not a seam with that strip.
  FlatStrip other = saddle;
  other.id = 3;
  EXPECT_EQ(widest_corner_round_a_seam_vertex(a, other), 0.0);
}

// Folded out of the other fan over either spoke, a fan lies flat beside it where their corners
// sum to 360 degrees, and overlaps it round the saddle; strips with no seam do not fold.
TEST(FoldsFlatOnto, AFanFoldsFlatOntoItsNeighbourUnlessTheyMeetRoundASaddle) {
  const auto [first, second] = spokes_of_two_fans();
  // Each fan laid out turned and moved on the page, as a strip lies anywhere.
  const auto moved = [](FlatStrip strip, double turn, const Vec2& by) {
    const Eigen::Rotation2Dd rotation(turn);
    for (Vec2& p : strip.vertices2d) p = rotation * p + by;
    return strip;
  };
  const FlatStrip a = moved(fan(1, 2, first, {50, 50, 50}), 1.0, Vec2(5, -3));
  const FlatStrip flat = moved(fan(2, 1, second, {70, 70, 70}), -2.0, Vec2(-4, 8));
  const FlatStrip saddle = moved(fan(2, 1, second, {80, 80, 70}), 0.5, Vec2(1, 1));
  EXPECT_TRUE(folds_flat_onto(a, flat));
  EXPECT_TRUE(folds_flat_onto(flat, a));
  EXPECT_FALSE(folds_flat_onto(a, saddle));
  EXPECT_FALSE(folds_flat_onto(saddle, a));
  // Glued over one spoke only: the seam has no vertex inside it, but folded over that spoke
  // the fans still meet round the saddle's vertex.
  const FlatStrip one_spoke = fan(1, 2, first, {50, 50, 50}, false);
  EXPECT_TRUE(folds_flat_onto(one_spoke, flat));
  EXPECT_FALSE(folds_flat_onto(one_spoke, saddle));
  FlatStrip other = flat;
  other.id = 3;
  EXPECT_FALSE(folds_flat_onto(a, other));
}

}  // namespace
}  // namespace papercraft
