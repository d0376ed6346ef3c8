#include "engine/refine/maximal_strip.h"

#include <gtest/gtest.h>

#include "core/generate.h"
#include "engine/select/geodesic.h"

namespace papercraft {
namespace {

// An open cylinder (radius 1, z in [0, 2]) whose upper half bulges out: only the lower half
// is one developable strip.
Mesh bulged_cylinder() {
  OpenCylinderOptions options;
  options.rings = 16;
  TriangleMesh mesh = open_cylinder(options);
  for (Vec3& p : mesh.vertices) {
    const double z = p.z();
    if (z > 1.0) {
      const double scale = 1.0 + 0.6 * (z - 1.0) * (z - 1.0);
      p.x() *= scale;
      p.y() *= scale;
    }
  }
  return to_mesh(mesh);
}

TEST(MaximalStrip, LeavesTheLargestCertifiedPieceNextToABoundary) {
  const Mesh part = bulged_cylinder();
  const auto loops = boundary_loops(part);
  ASSERT_EQ(loops.size(), 2u);
  const double tolerance = 0.01;
  const WitnessCut cut = cut_maximal_strip(part, loops[0], true, loops[1], true, tolerance);
  ASSERT_GE(cut.pieces.size(), 2u);
  // The piece holding the straight bottom (z = 0) must be one strip within the tolerance and
  // reach close to z = 1 where the bulge starts.
  const Mesh* bottom = nullptr;
  for (const Mesh& piece : cut.pieces) {
    for (auto v : piece.vertices()) {
      if (piece.point(v)[2] == 0.0) bottom = &piece;
    }
  }
  ASSERT_NE(bottom, nullptr);
  double top = 0.0;
  for (auto v : bottom->vertices()) top = std::max(top, bottom->point(v)[2]);
  EXPECT_GT(top, 0.9) << "the strip next to the straight end should extend to the bulge";
  const auto piece_loops = boundary_loops(*bottom);
  ASSERT_EQ(piece_loops.size(), 2u);
  const RuledStrip strip =
      twist_minimizing_strip(selection_polyline(*bottom, piece_loops[0], true),
                             selection_polyline(*bottom, piece_loops[1], true));
  const HausdorffResult check =
      certified_hausdorff_within(to_triangle_mesh(*bottom), strip.mesh, tolerance);
  EXPECT_TRUE(check.within) << "upper bound " << check.upper;
  // Areas add up.
  double area = 0.0;
  for (const Mesh& piece : cut.pieces) area += surface_area(piece);
  EXPECT_NEAR(area, surface_area(part), 1e-9 * area);
}

TEST(MaximalStrip, NothingFoundOnAPartThatNoStripFits) {
  // A sphere band with a tolerance far below its curvature: no piece qualifies.
  SphereOptions options;
  options.subdivisions = 3;
  Mesh sphere_mesh = to_mesh(sphere(options));
  const auto [from, to] = farthest_vertex_pair(sphere_mesh, 4);
  const WitnessCut cut = cut_maximal_strip(sphere_mesh, {from}, false, {to}, false, 1e-6);
  EXPECT_TRUE(cut.pieces.empty());
}

}  // namespace
}  // namespace papercraft
