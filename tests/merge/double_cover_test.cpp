// drop_double_covered_triangles: triangles two parts' strips both print are dropped from the later
// one, which is split into its pieces where it falls apart; every seam then has two sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"

namespace papercraft {
namespace {

using merge_testing::area_of;
using merge_testing::expect_valid;
using merge_testing::MergeFixture;
using merge_testing::read_fixture;
using merge_testing::triangle_count;

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

}  // namespace
}  // namespace papercraft
