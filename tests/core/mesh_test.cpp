#include "core/mesh.h"

#include <gtest/gtest.h>

#include "core/errors.h"

namespace papercraft {
namespace {

// Two triangles forming a unit square: one boundary loop of 4 vertices.
TEST(Mesh, SquareHasOneBoundaryLoop) {
  TriangleMesh square;
  square.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  Mesh mesh = to_mesh(square);
  auto loops = boundary_loops(mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 4u);
  EXPECT_EQ(euler_characteristic(mesh), 1);
  EXPECT_EQ(connected_components(mesh), 1);
  EXPECT_NEAR(surface_area(mesh), 1.0, 1e-15);
  EXPECT_NEAR(surface_area(to_triangle_mesh(mesh)), 1.0, 1e-15);
}

TEST(Mesh, NonManifoldTriangleThrows) {
  TriangleMesh fan;
  fan.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0, -1, 0)};
  fan.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  EXPECT_THROW(to_mesh(fan), TopologyException);
}

}  // namespace
}  // namespace papercraft
