#include "nodes/cut/through_witness.h"

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

}  // namespace
}  // namespace papercraft
