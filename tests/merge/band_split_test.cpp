// A band no hinge takes whole cut in two, three or four, each part folded out of a neighbour
// (join_narrow_strips' and join_small_strips' cut), on prisms whose wall runs round a notch or a
// hole.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/piece_width.h"
#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"
#include "support/unfold_checks.h"

namespace papercraft {
namespace {

using merge_testing::area_of;
using merge_testing::expect_valid;
using merge_testing::straight_wall;
using merge_testing::triangle_count;
using unfold_testing::count_overlapping_pairs;
using unfold_testing::expect_isometric;

// The three strips of a prism: its two plates and the wall between them.
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

// An L-shaped prism `h` high: a floor (z = 0) and a ceiling (z = h), each an 8 x 8 square less
// a 4 x 4 notch at (4..8, 0..4), and its wall along the notch's two sides, from (8, 4) by
// (4, 4) to (4, 0) in `steps` segments per side, unrolled straight (8 long). Each plate is a
// fan from (0, 8) over its outline, the notch's sides split where the wall's points are; seen
// from outside the prism the ceiling turns the other way, so it is laid out mirrored.
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

// The prism 0.2 high with a wall of four triangles. Folded out of the floor or the ceiling
// over any edge, the wall runs on past the notch's corner into that plate (the plate's sides
// turn by 90 degrees where the wall is straight), so no hinge takes it. Cut at the corner, one
// half folds out of the floor into its notch, the other out of the ceiling into its own: two
// pieces, neither narrow.
TEST(JoinNarrowStrips, BandNoHingeTakesWholeIsCutInTwoAndEachHalfFoldedOut) {
  const auto joined = wall_folded_out(l_prism(0.2, 1));
  ASSERT_EQ(joined.size(), 2u);
  EXPECT_EQ(triangle_count(joined), 12u);
  for (const FlatStrip& strip : joined)
    EXPECT_EQ(strip.triangles.size(), 6u) << strip.id;  // its plate and two of the wall's
}

// A prism `h` high whose wall stands on `bottom` (walked with the wall on its left), unrolled
// straight, and whose plates are `triangles` over `points` (add_plates).
LPrism walled_prism(const std::vector<Vec3>& bottom, const std::vector<Vec3>& points,
                    const std::vector<Triangle>& triangles, double h) {
  LPrism prism;
  prism.wall = straight_wall(bottom, h);
  add_plates(prism, points, triangles, h);
  return prism;
}

// A U-shaped prism `h` high: floor and ceiling a 12 x 8 plate less a 4 x 4 notch at
// (4..8, 0..4), and its wall along the notch's three sides, from (8, 0) by (8, 4) and (4, 4) to
// (4, 0), unrolled straight (12 long). The plates are triangulated by hand (the U is not
// star-shaped); the ceiling is laid out mirrored, as in l_prism.
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

}  // namespace
}  // namespace papercraft
