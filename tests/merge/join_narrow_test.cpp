// join_narrow_strips: a band folded out of a neighbour over the hinge that leaves the least slit,
// tried again beside a union, kept whole beside a wide neighbour, or grown where no hinge takes it.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/piece_width.h"
#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using merge_testing::append;
using merge_testing::area_of;
using merge_testing::bent_floor_and_wall;
using merge_testing::corner_floor;
using merge_testing::corner_wall;
using merge_testing::expect_valid;
using merge_testing::flat_floor;
using merge_testing::straight_wall;
using merge_testing::triangle_count;
using unfold_testing::count_overlapping_pairs;
using unfold_testing::expect_isometric;
using unfold_testing::ring_strip;

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

}  // namespace
}  // namespace papercraft
