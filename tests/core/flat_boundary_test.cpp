// widest_corner_round_a_seam_vertex and folds_flat_onto on two fans round a vertex, flat there or
// a saddle.
#include "core/flat_boundary.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

namespace papercraft {
namespace {

// A fan of triangles round a vertex: its centre and the 3D ends of its spokes (`spokes`, shared
// with the fan beside it), laid out in the plane with its corners `degrees` wide. Its first and
// last spokes are seams with strip `neighbour` (where `seam_last` for the last), its rim open.
FlatStrip fan(int id, int neighbour, const std::vector<Vec3>& spokes,
              const std::vector<double>& degrees, bool seam_last = true) {
  FlatStrip strip;
  strip.id = id;
  strip.vertices3d.push_back(Vec3::Zero());
  strip.vertices2d.push_back(Vec2::Zero());
  double angle = 0.0;
  for (std::size_t k = 0; k < spokes.size(); ++k) {
    if (k > 0) angle += degrees[k - 1] * M_PI / 180.0;
    strip.vertices3d.push_back(spokes[k]);
    strip.vertices2d.emplace_back(std::cos(angle), std::sin(angle));
  }
  const int n = static_cast<int>(spokes.size());
  for (int k = 1; k < n; ++k) strip.triangles.push_back({0, k, k + 1});
  strip.boundary = flat_boundary(strip.triangles);
  for (BoundaryEdge& e : strip.boundary) {
    const bool first = e.v0 == 0 && e.v1 == 1, last = e.v0 == n && e.v1 == 0;
    e.kind = first || (last && seam_last) ? EdgeKind::Seam : EdgeKind::Open;
    if (e.kind == EdgeKind::Seam) e.neighbour_strip = neighbour;
  }
  return strip;
}

// The spokes of two fans round a vertex (a zigzag about the plane z = 0): the first fan's
// four, then the second's, which begins at the first's last and ends at its first.
std::pair<std::vector<Vec3>, std::vector<Vec3>> spokes_of_two_fans() {
  std::vector<Vec3> spokes;
  for (int k = 0; k < 6; ++k)
    spokes.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.1 * (k % 2));
  return {{spokes[0], spokes[1], spokes[2], spokes[3]},
          {spokes[3], spokes[4], spokes[5], spokes[0]}};
}

// Two fans holding all of the surface round a vertex, each glued to the other along both its
// spokes there: their corners round it sum to 360 degrees where the surface is flat there and
// to more where it is a saddle, and a seam of one edge has no vertex inside it.
TEST(WidestCornerRoundASeamVertex, SumsBothPiecesCornersRoundTheVertexInsideTheirSeam) {
  const auto [first, second] = spokes_of_two_fans();
  const FlatStrip a = fan(1, 2, first, {50, 50, 50});
  EXPECT_NEAR(widest_corner_round_a_seam_vertex(a, fan(2, 1, second, {70, 70, 70})), 360.0, 1e-9);
  const FlatStrip saddle = fan(2, 1, second, {80, 80, 70});
  EXPECT_NEAR(widest_corner_round_a_seam_vertex(a, saddle), 380.0, 1e-9);
  EXPECT_NEAR(widest_corner_round_a_seam_vertex(saddle, a), 380.0, 1e-9);
  // Glued along one spoke only: the seam is one edge, with no vertex inside it.
  EXPECT_EQ(widest_corner_round_a_seam_vertex(fan(1, 2, first, {50, 50, 50}, false), saddle), 0.0);
  // Not a seam with that strip.
  FlatStrip other = saddle;
  other.id = 3;
  EXPECT_EQ(widest_corner_round_a_seam_vertex(a, other), 0.0);
}

// Folded out of the other fan over either spoke, a fan lies flat beside it where their corners
// sum to 360 degrees, and overlaps it round the saddle; strips with no seam do not fold.
TEST(FoldsFlatOnto, AFanFoldsFlatOntoItsNeighbourUnlessTheyMeetRoundASaddle) {
  const auto [first, second] = spokes_of_two_fans();
  // Each fan laid out turned and moved on the page, as a strip lies anywhere.
  const auto moved = [](FlatStrip strip, double turn, const Vec2& by) {
    const Eigen::Rotation2Dd rotation(turn);
    for (Vec2& p : strip.vertices2d) p = rotation * p + by;
    return strip;
  };
  const FlatStrip a = moved(fan(1, 2, first, {50, 50, 50}), 1.0, Vec2(5, -3));
  const FlatStrip flat = moved(fan(2, 1, second, {70, 70, 70}), -2.0, Vec2(-4, 8));
  const FlatStrip saddle = moved(fan(2, 1, second, {80, 80, 70}), 0.5, Vec2(1, 1));
  EXPECT_TRUE(folds_flat_onto(a, flat));
  EXPECT_TRUE(folds_flat_onto(flat, a));
  EXPECT_FALSE(folds_flat_onto(a, saddle));
  EXPECT_FALSE(folds_flat_onto(saddle, a));
  // Glued over one spoke only: the seam has no vertex inside it, but folded over that spoke
  // the fans still meet round the saddle's vertex.
  const FlatStrip one_spoke = fan(1, 2, first, {50, 50, 50}, false);
  EXPECT_TRUE(folds_flat_onto(one_spoke, flat));
  EXPECT_FALSE(folds_flat_onto(one_spoke, saddle));
  FlatStrip other = flat;
  other.id = 3;
  EXPECT_FALSE(folds_flat_onto(a, other));
}

}  // namespace
}  // namespace papercraft
