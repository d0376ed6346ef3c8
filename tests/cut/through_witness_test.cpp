#include "nodes/cut/through_witness.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace papercraft
