// join_small_strips: a crumb hinged whole where it leaves no slit, taken apart one triangle at a
// time, or grown from its neighbours; one that finds no place stays and is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "core/piece_width.h"
#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using merge_testing::area_of;
using merge_testing::bent_floor_and_wall;
using merge_testing::expect_valid;
using merge_testing::find_id;
using merge_testing::MergeFixture;
using merge_testing::read_fixture;
using merge_testing::triangle_count;
using unfold_testing::count_overlapping_pairs;
using unfold_testing::expect_isometric;

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
  const double turn =
      std::atan2((c2 - d2).y(), (c2 - d2).x()) - std::atan2((cy - dy).y(), (cy - dy).x());
  auto landed = [&](const Vec3& p) {
    const Vec2 q = Vec2(p.x(), p.y()) - dy;
    return Vec2(Vec2(std::cos(turn) * q.x() - std::sin(turn) * q.y(),
                     std::sin(turn) * q.x() + std::cos(turn) * q.y()) +
                d2);
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

// elephant-with-holes: crumb 79 (7 triangles, 55 mm^2) beside strip 78. Its first growths
// past min_area leave a piece narrower than min_width over more of its area than before (and
// than a quarter); it grows on until one does not, instead of giving up there.
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

}  // namespace
}  // namespace papercraft
