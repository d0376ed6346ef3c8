// is_one_flat_strip: the cut's look-ahead counts a piece as one strip only when its strip is
// within the tolerance and also unfolds without overlapping itself, since the unfolding splits
// one that overlaps into pieces each under half its area.

#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh.h"
#include "core/piece_limits.h"
#include "nodes/cut/through_witness.h"
#include "nodes/refine/refine.h"
#include "nodes/unfold/sequential.h"

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

RefineOptions decision_only() {
  RefineOptions options;
  options.decide.bounded.locate_maximum = false;
  return options;
}

constexpr double kTolerance = 0.05;

// The steps is_one_flat_strip runs, apart: is the strip within the tolerance, and into how
// many flat strips does it unfold?
struct Apart {
  bool accept = false;
  std::size_t flat_strips = 0;
};

Apart apart(const Mesh& piece) {
  const RefineOptions options = decision_only();
  const StripBoundaries sides = select_strip_boundaries(piece, kTolerance, options);
  const RuledStrip strip = build_strip(piece, sides, options);
  Apart result;
  result.accept = decide_strip(piece, sides, strip, kTolerance, options).accept;
  result.flat_strips = unfold_strip(strip, 0, 0).size();
  return result;
}

TEST(OneFlatStrip, AStripThatOverlapsItselfOnPaperIsNotOne) {
  const Mesh ramp = ruffled_band(0.1);
  const Apart steps = apart(ramp);
  ASSERT_TRUE(steps.accept) << "the band is one strip within the tolerance";
  EXPECT_EQ(steps.flat_strips, 2u) << "on paper it curls round by more than a turn";
  EXPECT_FALSE(is_one_flat_strip(ramp, kTolerance, decision_only()));
}

TEST(OneFlatStrip, AStripThatLiesFlatIsOne) {
  const Mesh ramp = ruffled_band(0.0);
  const Apart steps = apart(ramp);
  ASSERT_TRUE(steps.accept);
  EXPECT_EQ(steps.flat_strips, 1u);
  EXPECT_TRUE(is_one_flat_strip(ramp, kTolerance, decision_only()));
}

// The look-ahead with it: a piece under twice min_area that would unfold into two falls short
// as its halves would; one that lies flat in one piece meets the limits.
TEST(OneFlatStrip, TheLookAheadCountsTheUnfoldingsSplit) {
  const OneStrip one_strip = [](const Mesh& piece) {
    return is_one_flat_strip(piece, kTolerance, decision_only());
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
