// one_flat_strip_area: the cut's look-ahead counts a piece as one strip only when its strip is
// within the tolerance and also unfolds without overlapping itself, since the unfolding splits
// one that overlaps into pieces each under half its area; and it judges that strip by its area
// on paper, which over a curved surface is the rulings' and not the surface's.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/mesh.h"
#include "core/piece_limits.h"
#include "engine/cut/through_witness.h"
#include "engine/refine/refine.h"
#include "engine/unfold/sequential.h"

namespace papercraft {
namespace {

// A band between the unit circle and a loop of radius 1.3 that rises and falls `amplitude`
// six times round: one ring of triangles, so one strip. Flat (amplitude 0) it lies flat as
// the annulus it is; ruffled, its outer loop is longer than the annulus's, so on paper the
// band opened along a ruling curls round by more than a full turn and overlaps itself.
Mesh ruffled_band(double amplitude) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr int kSegments = 96;
  TriangleMesh mesh;
  for (int i = 0; i < kSegments; ++i) {
    const double t = 2.0 * kPi * i / kSegments;
    mesh.vertices.push_back(Vec3(std::cos(t), std::sin(t), 0.0));
    mesh.vertices.push_back(
        Vec3(1.3 * std::cos(t), 1.3 * std::sin(t), amplitude * std::sin(6 * t)));
  }
  for (int i = 0; i < kSegments; ++i) {
    const int j = (i + 1) % kSegments;
    const int in = 2 * i, out = 2 * i + 1, in_next = 2 * j, out_next = 2 * j + 1;
    mesh.triangles.push_back({in, out, out_next});
    mesh.triangles.push_back({in, out_next, in_next});
  }
  return to_mesh(mesh);
}

// A barrel: a band round the z axis from z = 0 to 1 whose radius swells from 1 at its rims to
// 1 + bulge halfway up, in `rows` rings of triangles. Within a tolerance above the bulge its
// strip is the cylinder of radius 1 between the rims, whose rulings cut straight across the
// swelling: on paper it is the cylinder's area (the 96-gon's perimeter), less than the
// barrel's surface.
Mesh barrel(double bulge, int rows) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr int kSegments = 96;
  TriangleMesh mesh;
  for (int r = 0; r <= rows; ++r) {
    const double z = static_cast<double>(r) / rows;
    const double radius = 1.0 + bulge * std::sin(kPi * z);
    for (int i = 0; i < kSegments; ++i) {
      const double t = 2.0 * kPi * i / kSegments;
      mesh.vertices.push_back(Vec3(radius * std::cos(t), radius * std::sin(t), z));
    }
  }
  for (int r = 0; r < rows; ++r)
    for (int i = 0; i < kSegments; ++i) {
      const int j = (i + 1) % kSegments;
      const int a = r * kSegments + i, b = r * kSegments + j;
      const int c = a + kSegments, d = b + kSegments;
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({a, d, c});
    }
  return to_mesh(mesh);
}

RefineOptions decision_only(double tolerance) {
  RefineOptions options = at_tolerance({}, tolerance);
  options.decide.bounded.locate_maximum = false;
  return options;
}

constexpr double kTolerance = 0.05;

// The steps one_flat_strip_area runs, apart: is the strip within the tolerance, and into how
// many flat strips does it unfold?
struct Apart {
  bool accept = false;
  std::size_t flat_strips = 0;
};

Apart apart(const Mesh& piece) {
  const RefineOptions options = decision_only(kTolerance);
  const StripBoundaries sides = select_strip_boundaries(piece, options);
  const RuledStrip strip = build_strip(piece, sides, options);
  Apart result;
  result.accept = decide_strip(piece, sides, strip, options).accept;
  result.flat_strips = unfold_strip(strip, 0, 0).size();
  return result;
}

TEST(OneFlatStrip, AStripThatOverlapsItselfOnPaperIsNotOne) {
  const Mesh ramp = ruffled_band(0.1);
  const Apart steps = apart(ramp);
  ASSERT_TRUE(steps.accept) << "the band is one strip within the tolerance";
  EXPECT_EQ(steps.flat_strips, 2u) << "on paper it curls round by more than a turn";
  EXPECT_FALSE(one_flat_strip_area(ramp, decision_only(kTolerance)).has_value());
}

TEST(OneFlatStrip, AStripThatLiesFlatIsOne) {
  const Mesh ramp = ruffled_band(0.0);
  const Apart steps = apart(ramp);
  ASSERT_TRUE(steps.accept);
  EXPECT_EQ(steps.flat_strips, 1u);
  const std::optional<double> paper = one_flat_strip_area(ramp, decision_only(kTolerance));
  ASSERT_TRUE(paper.has_value());
  EXPECT_NEAR(*paper, surface_area(to_triangle_mesh(ramp)), 1e-9 * *paper)
      << "a flat piece prints at its own area";
}

// The barrel's strip is the cylinder between its rims: one strip that lies flat, whose area on
// paper is the cylinder's (the 96-gon's perimeter times the height), several percent under the
// barrel's surface.
TEST(OneFlatStrip, ACurvedStripPrintsAtTheAreaOfItsRulings) {
  constexpr double kPi = 3.14159265358979323846;
  const Mesh swollen = barrel(0.2, 8);
  const double surface = surface_area(to_triangle_mesh(swollen));
  const double cylinder = 96 * 2.0 * std::sin(kPi / 96);  // the 96-gon's perimeter, height 1
  ASSERT_GT(surface, 1.05 * cylinder);
  const std::optional<double> paper = one_flat_strip_area(swollen, decision_only(0.25));
  ASSERT_TRUE(paper.has_value()) << "within 0.25 the barrel is one strip";
  EXPECT_NEAR(*paper, cylinder, 1e-9 * cylinder);
  // Below the bulge it is not one strip.
  EXPECT_FALSE(one_flat_strip_area(swollen, decision_only(0.1)).has_value());
  // The look-ahead: a piece that reaches min_area on the surface but not on paper falls short
  // by the paper's lack.
  PieceLimits limits;
  limits.min_area = 0.5 * (surface + cylinder);
  const OneStrip one_strip = [](const Mesh& piece) {
    return one_flat_strip_area(piece, decision_only(0.25));
  };
  EXPECT_NEAR(piece_shortfall_ahead(swollen, limits, one_strip), 1.0 - cylinder / limits.min_area,
              1e-9);
  EXPECT_EQ(piece_shortfall_ahead(swollen, limits), 0.0) << "without the look-ahead, as it is";
}

// The look-ahead with it: a piece under twice min_area that would unfold into two falls short
// as its halves would; one that lies flat in one piece meets the limits.
TEST(OneFlatStrip, TheLookAheadCountsTheUnfoldingsSplit) {
  const OneStrip one_strip = [](const Mesh& piece) {
    return one_flat_strip_area(piece, decision_only(kTolerance));
  };
  for (double amplitude : {0.0, 0.1}) {
    const Mesh ramp = ruffled_band(amplitude);
    const double area = surface_area(to_triangle_mesh(ramp));
    PieceLimits limits;
    limits.min_area = 0.8 * area;  // room for one piece, not for two
    const double shortfall = piece_shortfall_ahead(ramp, limits, one_strip);
    if (amplitude == 0.0)
      EXPECT_EQ(shortfall, 0.0);
    else
      EXPECT_NEAR(shortfall, 1.0 - area / (2.0 * limits.min_area), 1e-12);
  }
}

}  // namespace
}  // namespace papercraft
