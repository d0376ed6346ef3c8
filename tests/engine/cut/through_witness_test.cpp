#include "engine/cut/through_witness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/mesh.h"

namespace papercraft {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Half an annulus one triangle wide: every vertex lies on its one boundary loop.
TriangleMesh half_ring_band(int segments) {
  TriangleMesh band;
  for (int i = 0; i <= segments; ++i) {
    const double angle = kPi * i / segments;
    band.vertices.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    band.vertices.emplace_back(1.1 * std::cos(angle), 1.1 * std::sin(angle), 0.0);
  }
  for (int i = 0; i < segments; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    band.triangles.push_back({a, d, b});
    band.triangles.push_back({a, c, d});
  }
  return band;
}

// A fan whose apex lies on its base loop has no field f between its boundaries; a witness
// near one end of the band (on the fan, off the part) used to shave a tip off the band, and
// the refinement ended at max_depth. The cut now halves the band.
TEST(CutThroughWitness, BandWithoutFieldIsHalved) {
  const Mesh part = to_mesh(half_ring_band(40));
  const auto loops = boundary_loops(part);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), part.n_vertices());
  const std::vector<int>& first = loops[0];
  const std::vector<int> second = {first[first.size() / 3]};
  const WitnessCut cut = cut_through_witness(part, first, second, Vec3(1.3, 0.05, 0.0));
  ASSERT_EQ(cut.pieces.size(), 2u);
  const double area = surface_area(part);
  for (const Mesh& piece : cut.pieces) EXPECT_GT(surface_area(piece), 0.25 * area);
}

// A piece under twice min_area that is not one strip would be cut into pieces that all fall
// short of min_area: it falls short as they would. One that is a strip is judged by its area
// on paper; one large enough to be cut in two that reach min_area, or already short, as it is.
TEST(CutShortfall, PieceTooSmallToCutAgainMustBeOneStrip) {
  TriangleMesh square;
  square.vertices = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Mesh> pieces = {to_mesh(square)};  // area 100
  PieceLimits limits;
  limits.min_area = 80.0;
  int asked = 0;
  const OneStrip not_a_strip = [&](const Mesh&) -> std::optional<double> {
    return ++asked, std::nullopt;
  };
  const OneStrip a_strip = [&](const Mesh&) -> std::optional<double> { return ++asked, 100.0; };
  // A strip whose rulings cut across a dome prints smaller than the surface.
  const OneStrip a_flatter_strip = [&](const Mesh&) -> std::optional<double> {
    return ++asked, 60.0;
  };
  EXPECT_EQ(cut_shortfall(pieces, limits), 0.0);  // no look ahead
  EXPECT_NEAR(cut_shortfall(pieces, limits, not_a_strip), 1.0 - 100.0 / 160.0, 1e-12);
  EXPECT_EQ(cut_shortfall(pieces, limits, a_strip), 0.0);
  EXPECT_NEAR(cut_shortfall(pieces, limits, a_flatter_strip), 1.0 - 60.0 / 80.0, 1e-12);
  EXPECT_EQ(asked, 3);
  limits.min_area = 40.0;  // room for two pieces of 40
  EXPECT_EQ(cut_shortfall(pieces, limits, not_a_strip), 0.0);
  limits.min_area = 125.0;  // short already (by 0.2): judged as it is
  EXPECT_NEAR(cut_shortfall(pieces, limits, not_a_strip), 0.2, 1e-12);
  EXPECT_NEAR(cut_shortfall(pieces, limits, a_flatter_strip), 0.2, 1e-12);
  EXPECT_EQ(asked, 3);
}

// An open tube of radius 1 and length 10 round the z axis, in rings 0.1 apart, with a hole
// near its lower end: the faces of the rings from z = 0.2 to 1.2 within 30 degrees of the x
// axis taken out.
TriangleMesh tube_with_hole_near_end() {
  constexpr int kAround = 48, kRings = 100;
  TriangleMesh tube;
  for (int r = 0; r <= kRings; ++r)
    for (int i = 0; i < kAround; ++i) {
      const double angle = 2.0 * kPi * i / kAround;
      tube.vertices.emplace_back(std::cos(angle), std::sin(angle), 0.1 * r);
    }
  for (int r = 0; r < kRings; ++r)
    for (int i = 0; i < kAround; ++i) {
      const double angle = 2.0 * kPi * (i + 0.5) / kAround;
      const double z = 0.1 * (r + 0.5);
      if (z > 0.2 && z < 1.2 && std::abs(std::remainder(angle, 2.0 * kPi)) < kPi / 6) continue;
      const int j = (i + 1) % kAround;
      const int a = r * kAround + i, b = r * kAround + j;
      tube.triangles.push_back({a, b, b + kAround});
      tube.triangles.push_back({a, b + kAround, a + kAround});
    }
  // The vertices inside the hole are on no face: drop them.
  std::vector<int> index(tube.vertices.size(), -1);
  TriangleMesh used;
  for (auto& t : tube.triangles)
    for (int& v : t) {
      if (index[v] < 0)
        index[v] = static_cast<int>(used.vertices.size()),
        used.vertices.push_back(tube.vertices[v]);
      v = index[v];
    }
  used.triangles = std::move(tube.triangles);
  return used;
}

// The tube with a hole near its end, with its boundary loops: the ends at z = 0 and z = 10
// (first and second) and the hole.
struct TubeWithHole {
  Mesh part;
  std::vector<int> first, second, hole;
};
TubeWithHole tube_and_loops() {
  TubeWithHole tube{to_mesh(tube_with_hole_near_end()), {}, {}, {}};
  const auto loops = boundary_loops(tube.part);
  EXPECT_EQ(loops.size(), 3u);
  for (const auto& loop : loops) {
    const double z = tube.part.point(tube.part.vertex_handle(loop.front()))[2];
    if (loop.size() == 48 && z == 0.0)
      tube.first = loop;
    else if (loop.size() == 48 && z > 9.9)
      tube.second = loop;
    else
      tube.hole = loop;
  }
  EXPECT_FALSE(tube.first.empty() || tube.second.empty() || tube.hole.empty());
  return tube;
}

// The cut through a hole goes through the middle of it; where that leaves a piece under
// min_area (the ring between the tube's end and the hole, about 4 here), another cut through
// the hole (or across the part by it) that leaves none replaces it; and it opens the hole, so
// that no piece keeps it (a piece with a third boundary loop would have to be cut again).
TEST(CutThroughHole, AHoleNearTheEndLeavesNoCrumb) {
  const auto [part, first, second, hole] = tube_and_loops();
  ASSERT_FALSE(first.empty() || second.empty() || hole.empty());
  WitnessCutOptions options;
  const WitnessCut middle = cut_through_hole(part, first, second, hole, options);
  ASSERT_EQ(middle.pieces.size(), 2u) << "without limits: through the middle of the hole";
  double smallest = 1e9;
  for (const Mesh& piece : middle.pieces) smallest = std::min(smallest, surface_area(piece));
  ASSERT_LT(smallest, 5.0) << "the ring below the hole";
  options.limits.min_area = 5.0;
  const WitnessCut cut = cut_through_hole(part, first, second, hole, options);
  ASSERT_GE(cut.pieces.size(), 2u);
  for (const Mesh& piece : cut.pieces) {
    EXPECT_GE(surface_area(piece), 5.0);
    EXPECT_LE(boundary_loops(piece).size(), 2u) << "the hole is still in a piece";
  }
  EXPECT_EQ(cut_shortfall(cut.pieces, options.limits), 0.0);
}

// With a count of holes, a cut through the hole whose pieces hold more of them than the
// middle cut's is passed over (its iso-line crosses the loop and also runs round the part
// elsewhere, leaving the hole in a piece). Here a stand-in count says every piece of 5 to 20
// (the ring any other cut through this hole leaves by the end, with the limits met) keeps a
// hole: each such cut is passed over, and the middle cut stays, crumb and all.
TEST(CutThroughHole, ACutThatLeavesAHoleInAPieceIsPassedOver) {
  const auto [part, first, second, hole] = tube_and_loops();
  ASSERT_FALSE(first.empty() || second.empty() || hole.empty());
  WitnessCutOptions options;
  const WitnessCut middle = cut_through_hole(part, first, second, hole, options);
  options.limits.min_area = 5.0;
  int asked = 0;
  const HoleCount holes = [&](const Mesh& piece) {
    ++asked;
    const double area = surface_area(piece);
    return area >= 5.0 && area < 20.0 ? 1 : 0;
  };
  const WitnessCut kept = cut_through_hole(part, first, second, hole, options, {}, holes);
  EXPECT_GT(asked, 2) << "the middle cut's pieces and another cut's";
  EXPECT_EQ(kept.value, middle.value);
  EXPECT_EQ(kept.pieces.size(), middle.pieces.size());
  // Counting no holes, the other cut is taken (AHoleNearTheEndLeavesNoCrumb).
  const WitnessCut moved =
      cut_through_hole(part, first, second, hole, options, {}, [](const Mesh&) { return 0; });
  EXPECT_NE(moved.value, middle.value);
  EXPECT_EQ(cut_shortfall(moved.pieces, options.limits), 0.0);
}

}  // namespace
}  // namespace papercraft
