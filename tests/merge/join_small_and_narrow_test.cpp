// join_small_and_narrow_strips: the merge node's joins in order, the crumbs given up tried again
// after the narrow joins.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"

namespace papercraft {
namespace {

using merge_testing::area_of;
using merge_testing::expect_valid;
using merge_testing::find_id;
using merge_testing::MergeFixture;
using merge_testing::read_fixture;
using merge_testing::triangle_count;

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

}  // namespace
}  // namespace papercraft
