// smooth_seams: a triangle at a sawtooth corner handed across its seam where that pays, and
// hinge_modest_strips declining a hinge that costs more than the piece it saves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/effort.h"
#include "core/flat_boundary.h"
#include "core/strip.h"
#include "nodes/merge/congruent.h"
#include "support/merge_strips.h"

namespace papercraft {
namespace {

using merge_testing::area_of;
using merge_testing::expect_valid;

FlatStrip plane_strip(int id, const std::vector<Vec2>& points, std::vector<Triangle> triangles) {
  FlatStrip strip;
  strip.id = id;
  strip.source_strip = id;
  for (const Vec2& p : points) {
    strip.vertices2d.push_back(p);
    strip.vertices3d.push_back({p.x(), p.y(), 0.0});
  }
  strip.triangles = std::move(triangles);
  strip.boundary = flat_boundary(strip.triangles);
  return strip;
}

// A 40 x 20 mm sheet cut across its middle, the cut running round one tooth of the lower piece
// 3 mm high and 2 mm wide: three sawtooth corners on each side of the seam.
std::vector<FlatStrip> toothed_sheet() {
  FlatStrip lower = plane_strip(0, {{0, 0}, {40, 0}, {40, 10}, {21, 10}, {19, 10}, {0, 10}, {20, 13}},
                                {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {4, 3, 6}});
  FlatStrip upper = plane_strip(1, {{0, 10}, {19, 10}, {20, 13}, {21, 10}, {40, 10}, {40, 20}, {0, 20}},
                                {{0, 1, 6}, {1, 2, 6}, {2, 5, 6}, {2, 3, 5}, {3, 4, 5}});
  return {lower, upper};
}

int sawtooth_of(const std::vector<FlatStrip>& strips) {
  int count = 0;
  for (const FlatStrip& strip : strips) {
    std::vector<Vec2> loop;
    for (const BoundaryEdge& e : strip.boundary) loop.push_back(strip.vertices2d[e.v0]);
    count += count_sawtooth_corners(loop);
  }
  return count;
}

TEST(SmoothSeams, ATriangleAtASawtoothCornerGoesAcrossItsSeam) {
  const std::vector<FlatStrip> sheet = toothed_sheet();
  ASSERT_EQ(sawtooth_of(sheet), 6);
  MergeOptions options;
  options.mm_per_unit = 1.0;
  const std::vector<FlatStrip> smooth = smooth_seams(sheet, 100.0, 0.0, 0.25, options);
  ASSERT_EQ(smooth.size(), 2u);
  expect_valid(smooth);
  EXPECT_EQ(sawtooth_of(smooth), 0);
  EXPECT_EQ(smooth[0].triangles.size(), 4u);
  EXPECT_EQ(smooth[1].triangles.size(), 6u);
  EXPECT_NEAR(area_of(smooth[0]), 400.0, 1e-9);
  EXPECT_NEAR(area_of(smooth[1]), 400.0, 1e-9);
  // The seam now runs straight: one chain of 40 mm on each side.
  for (const FlatStrip& strip : smooth) {
    double seam = 0.0;
    for (const BoundaryEdge& e : strip.boundary)
      if (e.kind == EdgeKind::Seam) seam += (strip.vertices2d[e.v1] - strip.vertices2d[e.v0]).norm();
    EXPECT_NEAR(seam, 40.0, 1e-9);
  }
}

TEST(SmoothSeams, NothingMovesWithoutAPrintScaleOrWhereThePieceLeftWouldBeTooSmall) {
  const std::vector<FlatStrip> sheet = toothed_sheet();
  EXPECT_EQ(sawtooth_of(smooth_seams(sheet, 100.0, 0.0, 0.25, MergeOptions{})), 6);
  MergeOptions options;
  options.mm_per_unit = 1.0;
  // Either piece left without the tooth would be under 500 mm^2.
  EXPECT_EQ(sawtooth_of(smooth_seams(sheet, 500.0, 0.0, 0.25, options)), 6);
}

// A cone of 3 model-unit rulings cut open along one of them (corners summing to 358 degrees
// round its apex), as two pieces: three of its four fan triangles, and the fourth. Hinged
// together over either ruling they share, the other opens into a slit 2 degrees wide: at 10 mm
// per unit, 30 mm long and at most 1 mm wide, too thin for a glue flap.
std::vector<FlatStrip> opened_cone_in_two() {
  const double fan = (2 * std::numbers::pi - 2 * std::numbers::pi / 180) / 4, radius = 3.0;
  const double rim = std::sqrt(2.0) * radius * std::sin(fan / 2);
  const double height = std::sqrt(radius * radius - rim * rim);
  std::vector<Vec2> flat{{0, 0}};
  std::vector<Vec3> points{{0, 0, height}};
  for (int i = 0; i <= 4; ++i) {
    flat.push_back({radius * std::cos(i * fan), radius * std::sin(i * fan)});
    const double a = 0.5 * std::numbers::pi * (i % 4);
    points.push_back({rim * std::cos(a), rim * std::sin(a), 0});
  }
  auto piece = [&](int id, std::vector<Triangle> triangles) {
    FlatStrip strip;
    strip.id = id;
    strip.source_strip = id;
    strip.vertices2d = flat;
    strip.vertices3d = points;
    strip.triangles = std::move(triangles);
    strip.boundary = flat_boundary(strip.triangles);
    return strip;
  };
  // Vertices unused by a piece are harmless to the merge; each keeps the whole fan's points.
  return {piece(0, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}), piece(1, {{0, 4, 5}})};
}

TEST(HingeModestStrips, WeighsThePieceSavedAgainstTheJoiningStripItsSlitNeeds) {
  const std::vector<FlatStrip> cone = opened_cone_in_two();
  const double min_area = 3.0;  // the small piece's 4.5 is legal but under twice that
  ASSERT_GT(area_of(cone[1]), min_area);
  ASSERT_LT(area_of(cone[1]), 2 * min_area);
  // Judged by the slit alone it is hinged: one piece with a seam of its own.
  EXPECT_EQ(hinge_modest_strips(cone, 2 * min_area).size(), 1u);
  // Judged by what it costs a person: one piece less, but one joining strip more, so the hinge
  // gains only the 30 mm of glue line it saves. Where glue length costs nothing, it does not
  // pay and both pieces stay.
  MergeOptions options;
  options.mm_per_unit = 10.0;
  options.weights.glue_per_metre = 0.0;
  const std::vector<FlatStrip> kept = hinge_modest_strips(cone, 2 * min_area, options);
  ASSERT_EQ(kept.size(), 2u);
  expect_valid(kept);
  options.weights.glue_per_metre = 1.0;
  EXPECT_EQ(hinge_modest_strips(cone, 2 * min_area, options).size(), 1u);
}

}  // namespace
}  // namespace papercraft
