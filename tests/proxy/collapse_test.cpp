#include "nodes/proxy/collapse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/generate.h"
#include "core/mesh.h"
#include "support/brute_force_hausdorff.h"

namespace papercraft {
namespace {

using testing::height_field;

// Input vertices on a boundary edge.
std::set<int> boundary_vertices(const TriangleMesh& mesh) {
  std::set<int> out;
  const Mesh m = to_mesh(mesh);
  for (auto v : m.vertices())
    if (m.is_boundary(v)) out.insert(v.idx());
  return out;
}

void expect_same_topology(const TriangleMesh& input, const CollapseDecimation& result) {
  const Mesh before = to_mesh(input);
  const Mesh after = to_mesh(result.mesh);  // throws if the result is not manifold
  EXPECT_EQ(euler_characteristic(after), euler_characteristic(before));
  EXPECT_EQ(boundary_loops(after).size(), boundary_loops(before).size());
  EXPECT_EQ(connected_components(after), connected_components(before));
  for (std::size_t i = 0; i < result.source_vertex.size(); ++i)
    EXPECT_EQ(result.mesh.vertices[i], input.vertices[result.source_vertex[i]]);
}

// A flat disc, finely triangulated (a grid mapped onto the disc, so no three boundary vertices
// are collinear): every interior vertex can go, so what is left is a triangulation of the
// boundary polygon, exactly (boundary vertices - 2) triangles.
TEST(CollapseDecimation, FlatDiscKeepsOnlyItsBoundary) {
  TriangleMesh input = height_field(20, [](double, double) { return 0.0; }, 0.0, 1);
  for (Vec3& p : input.vertices) {
    const double u = 2 * p.x() - 1, v = 2 * p.y() - 1;
    p = Vec3(u * std::sqrt(1 - v * v / 2), v * std::sqrt(1 - u * u / 2), 0.0);
  }
  const std::set<int> boundary = boundary_vertices(input);
  ASSERT_EQ(boundary.size(), 80u);
  const CollapseDecimation result = collapse_decimation(input, 1e-9);
  expect_same_topology(input, result);
  EXPECT_EQ(result.mesh.triangles.size(), boundary.size() - 2);
  EXPECT_EQ(std::set<int>(result.source_vertex.begin(), result.source_vertex.end()), boundary);
  EXPECT_EQ(result.collapses, input.vertices.size() - boundary.size());
  // Same orientation as the input (+z), and no triangle degenerate.
  for (const Triangle& t : result.mesh.triangles) {
    const Vec3& a = result.mesh.vertices[t[0]];
    const Vec3 n = (result.mesh.vertices[t[1]] - a).cross(result.mesh.vertices[t[2]] - a);
    EXPECT_GT(n.z(), 0.0);
  }
}

// With a zero bound nothing curved may go: a sphere keeps every vertex.
TEST(CollapseDecimation, ZeroBoundKeepsACurvedSurface) {
  const TriangleMesh input = sphere({.radius = 1.0, .subdivisions = 3});
  const CollapseDecimation result = collapse_decimation(input, 0.0);
  EXPECT_EQ(result.collapses, 0u);
  EXPECT_EQ(result.mesh.triangles.size(), input.triangles.size());
  EXPECT_EQ(result.passes, 1);
}

// A closed surface and one with holes keep their topology, faces stay outward, the removed
// part grows with the bound, and the result is the same on every call.
TEST(CollapseDecimation, KeepsTopologyAndOrientationAndIsDeterministic) {
  for (const TriangleMesh& input :
       {sphere({.radius = 1.0, .subdivisions = 4}), torus({.segments = 64, .tube_segments = 24}),
        cylinder_two_holes({})}) {
    std::size_t previous = input.triangles.size() + 1;
    for (double bound : {0.001, 0.01, 0.05}) {
      const CollapseDecimation result = collapse_decimation(input, bound);
      expect_same_topology(input, result);
      EXPECT_LE(result.mesh.triangles.size(), previous);
      previous = result.mesh.triangles.size();
      const CollapseDecimation again = collapse_decimation(input, bound);
      EXPECT_EQ(again.mesh.triangles, result.mesh.triangles);
      EXPECT_EQ(again.source_vertex, result.source_vertex);
    }
    EXPECT_LT(previous, input.triangles.size() / 4);
  }
  // The sphere's faces point away from its centre.
  const CollapseDecimation sphere_result =
      collapse_decimation(sphere({.radius = 1.0, .subdivisions = 4}), 0.05);
  for (const Triangle& t : sphere_result.mesh.triangles) {
    const Vec3& a = sphere_result.mesh.vertices[t[0]];
    const Vec3 n = (sphere_result.mesh.vertices[t[1]] - a).cross(sphere_result.mesh.vertices[t[2]] - a);
    EXPECT_GT(n.dot(a), 0.0);
  }
}

// Boundary vertices are never removed, even where the boundary is straight.
TEST(CollapseDecimation, BoundaryVerticesStay) {
  const TriangleMesh input = height_field(
      30, [](double x, double y) { return 0.2 * std::sin(2 * x) * std::cos(3 * y); }, 0.0, 3);
  const std::set<int> boundary = boundary_vertices(input);
  const CollapseDecimation result = collapse_decimation(input, 0.01);
  expect_same_topology(input, result);
  const std::set<int> kept(result.source_vertex.begin(), result.source_vertex.end());
  for (int v : boundary) EXPECT_TRUE(kept.count(v)) << "boundary vertex " << v << " removed";
  EXPECT_LT(result.mesh.triangles.size(), input.triangles.size() / 2);
}

}  // namespace
}  // namespace papercraft
