#include "core/piece_effort.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/flat_boundary.h"
#include "core/seams.h"

namespace papercraft {
namespace {

TriangleGrid2 grid_of(const std::vector<Triangle2>& triangles) {
  TriangleGrid2 grid(1.0);
  for (const Triangle2& t : triangles) grid.insert(t);
  return grid;
}

// A 10 mm square above the x axis, as two triangles.
std::vector<Triangle2> square() { return {{{{0, 0}, {10, 0}, {10, 10}}}, {{{0, 0}, {10, 10}, {0, 10}}}}; }

TEST(FlapFits, BesideAFreeEdge) {
  TriangleGrid2 piece = grid_of(square());
  EXPECT_TRUE(flap_fits({{0, 0}, {10, 0}}, piece, 1.0));
  // The same edge walked the other way puts the flap over the square.
  EXPECT_FALSE(flap_fits({{10, 0}, {0, 0}}, piece, 1.0));
}

TEST(FlapFits, NotWhereThePieceComesBackWithinTheFlapsHeight) {
  std::vector<Triangle2> triangles = square();
  // Another part of the piece 0.5 mm below the edge, all along it: a slit.
  triangles.push_back({{{-1, -0.5}, {5, -6}, {11, -0.5}}});
  TriangleGrid2 slit = grid_of(triangles);
  EXPECT_FALSE(flap_fits({{0, 0}, {10, 0}}, slit, 1.0));
  // 2 mm below: room for a 1 mm flap, not for a 3 mm one.
  triangles.back() = {{{-1, -2}, {5, -8}, {11, -2}}};
  TriangleGrid2 gap = grid_of(triangles);
  EXPECT_TRUE(flap_fits({{0, 0}, {10, 0}}, gap, 1.0));
  EXPECT_FALSE(flap_fits({{0, 0}, {10, 0}}, gap, 3.0));
}

TEST(FlapFits, APartOfALongEdgeAndNoneOnATinyOne) {
  std::vector<Triangle2> triangles = square();
  // Below the left half of the edge only.
  triangles.push_back({{{-1, -0.5}, {2, -6}, {5, -0.5}}});
  TriangleGrid2 piece = grid_of(triangles);
  EXPECT_TRUE(flap_fits({{0, 0}, {10, 0}}, piece, 1.0));
  TriangleGrid2 plain = grid_of(square());
  EXPECT_FALSE(flap_fits({{0, 0}, {0.3, 0}}, plain, 1.0));
}

TEST(FlapFits, AlongABentSideOfManyShortEdges) {
  // A quarter disc of radius 10 mm seen from outside: its arc in 0.2 mm steps, bulging out.
  std::vector<Triangle2> fan;
  std::vector<Vec2> arc;
  const int steps = 78;
  for (int i = 0; i <= steps; ++i) {
    const double a = -0.5 * std::numbers::pi * i / steps;
    arc.push_back({10 * std::sin(-a), 10 * std::cos(a)});
  }
  for (int i = 0; i < steps; ++i) fan.push_back({{{0, 0}, arc[i + 1], arc[i]}});
  // The arc runs from (0, 10) to (10, 0) clockwise round the centre: the disc on its right, so
  // walked the other way it has the disc on its left and room outside.
  std::vector<Vec2> side(arc.rbegin(), arc.rend());
  TriangleGrid2 piece = grid_of(fan);
  EXPECT_TRUE(flap_fits(side, piece, 1.0));
  EXPECT_FALSE(flap_fits(arc, piece, 1.0));
}

// A cone cut open along one ruling: a fan of four triangles round its apex (vertex 0), the
// ruling's two copies (vertices 1 and 5) `deficit_degrees` apart in the plane, `radius` long.
FlatStrip opened_cone(double radius, double deficit_degrees, int id) {
  const double fan = (2 * std::numbers::pi - deficit_degrees * std::numbers::pi / 180) / 4;
  const double rim = std::sqrt(2.0) * radius * std::sin(fan / 2);  // 3D circle radius
  const double height = std::sqrt(radius * radius - rim * rim);
  FlatStrip strip;
  strip.id = id;
  strip.vertices2d.push_back({0, 0});
  strip.vertices3d.push_back({0, 0, height});
  for (int i = 0; i <= 4; ++i) {
    strip.vertices2d.push_back({radius * std::cos(i * fan), radius * std::sin(i * fan)});
    const double a = 0.5 * std::numbers::pi * (i % 4);
    strip.vertices3d.push_back({rim * std::cos(a), rim * std::sin(a), 0});
  }
  for (int i = 1; i <= 4; ++i) strip.triangles.push_back({0, i, i + 1});
  strip.boundary = flat_boundary(strip.triangles);
  return strip;
}

TEST(LocalEffort, AThinSlitNeedsAJoiningStripAWideOneNot) {
  const PieceEffortOptions options{.mm_per_unit = 1.0};
  // 20 mm rulings 2 degrees apart: the slit opens 0.7 mm at its mouth, too thin for a flap.
  std::vector<FlatStrip> thin{opened_cone(20, 2, 0)};
  label_seams(thin);
  const EffortTerms t = local_effort_terms(thin, {0}, options);
  EXPECT_EQ(t.printed_pieces, 1);
  EXPECT_EQ(t.seam_chains, 1);
  EXPECT_EQ(t.self_seams, 1);
  EXPECT_EQ(t.joining_strips, 1);
  EXPECT_EQ(t.things_to_cut, 2);
  EXPECT_NEAR(t.glue_length_mm, 20.0, 1e-9);
  EXPECT_EQ(t.sawtooth_corners, 0);  // the slit is longer than the 4 mm a sawtooth spans
  // 40 degrees apart: room for a flap in the slit.
  std::vector<FlatStrip> wide{opened_cone(20, 40, 0)};
  label_seams(wide);
  EXPECT_EQ(local_effort_terms(wide, {0}, options).joining_strips, 0);
  // 3 mm rulings: the slit's tip and mouth turn sharply within 4 mm of each other.
  std::vector<FlatStrip> short_slit{opened_cone(3, 2, 0)};
  label_seams(short_slit);
  const EffortTerms s = local_effort_terms(short_slit, {0}, options);
  EXPECT_EQ(s.joining_strips, 1);
  EXPECT_EQ(s.sawtooth_corners, 3);
}

TEST(LocalEffort, TwoSquaresAndTheirSeam) {
  // Two unit squares side by side (x in [0, 1] and [1, 2]), 10 mm on paper each way.
  auto square_strip = [](double x0, int id) {
    FlatStrip s;
    s.id = id;
    for (const Vec2& p : {Vec2(x0, 0), Vec2(x0 + 1, 0), Vec2(x0 + 1, 1), Vec2(x0, 1)}) {
      s.vertices2d.push_back(p);
      s.vertices3d.push_back({p.x(), p.y(), 0});
    }
    s.triangles = {{0, 1, 2}, {0, 2, 3}};
    s.boundary = flat_boundary(s.triangles);
    return s;
  };
  std::vector<FlatStrip> strips{square_strip(0, 0), square_strip(1, 1)};
  label_seams(strips);
  const PieceEffortOptions options{.mm_per_unit = 10.0, .min_area_mm2 = 150.0};
  const EffortTerms both = local_effort_terms(strips, {0, 1}, options);
  EXPECT_EQ(both.printed_pieces, 2);
  EXPECT_EQ(both.seam_chains, 1);
  EXPECT_EQ(both.self_seams, 0);
  EXPECT_EQ(both.joining_strips, 0);
  EXPECT_NEAR(both.glue_length_mm, 10.0, 1e-9);
  EXPECT_EQ(both.sawtooth_corners, 0);
  EXPECT_EQ(both.small_pieces, 2);  // 100 mm^2 each
  // One of them: the seam touches it, the other piece is not counted.
  const EffortTerms one = local_effort_terms(strips, {1}, options);
  EXPECT_EQ(one.printed_pieces, 1);
  EXPECT_EQ(one.seam_chains, 1);
  EXPECT_EQ(one.small_pieces, 1);
  const EffortWeights w;
  EXPECT_DOUBLE_EQ(local_effort(strips, {0, 1}, options),
                   2 * w.piece + w.seam + 0.01 * w.glue_per_metre + 2 * w.small_piece);
}

}  // namespace
}  // namespace papercraft
