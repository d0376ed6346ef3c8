// hinge_modest_strips: a legal but small piece folded out of its neighbour where the union lies
// flat, and the merge node's joins doing it at the default factor.
#include <gtest/gtest.h>

#include <vector>

#include "core/strip.h"
#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"

namespace papercraft {
namespace {

using merge_testing::area_of;
using merge_testing::corner_floor;
using merge_testing::corner_wall;
using merge_testing::expect_valid;

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

}  // namespace
}  // namespace papercraft
