// glue_pieces and one_strip_of: the merge node's join in 3D of a piece left too small or too
// narrow with a neighbouring piece. Two pieces of one surface, cut apart, glue back into the
// surface they were; where that surface is one strip within the tolerance that lies flat in one
// piece, one_strip_of gives its strip, certified, and its unfolding.

#include "engine/refine/rejoin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>

#include "core/flat_boundary.h"
#include "core/generate.h"
#include "core/mesh.h"
#include "engine/refine/refine.h"

namespace papercraft {
namespace {

// The triangles of `mesh` that `keep` takes, as a mesh of their own (vertices renumbered).
Mesh piece_of(const TriangleMesh& mesh, const std::function<bool(const Vec3&)>& keep) {
  TriangleMesh piece;
  std::map<int, int> index;
  for (const auto& t : mesh.triangles) {
    const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    if (!keep(centroid)) continue;
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = index.try_emplace(t[k], static_cast<int>(piece.vertices.size()));
      if (added) piece.vertices.push_back(mesh.vertices[t[k]]);
      corners[k] = it->second;
    }
    piece.triangles.push_back(corners);
  }
  return to_mesh(piece);
}

// A cylinder of radius 1 and height 2 in 8 rings, cut at z = -0.75 into a band one ring high
// (0.25: narrow) and the rest: glued, they are the cylinder again, which is one strip (it is
// developable) and unfolds into one rectangle of its area.
TEST(Rejoin, ACylinderCutIntoTwoBandsGluesBackIntoOneStrip) {
  const TriangleMesh cylinder =
      open_cylinder({.radius = 1.0, .height = 2.0, .segments = 32, .rings = 8});
  const Mesh band = piece_of(cylinder, [](const Vec3& c) { return c.z() < -0.75; });
  const Mesh rest = piece_of(cylinder, [](const Vec3& c) { return c.z() >= -0.75; });
  ASSERT_EQ(band.n_faces(), 64u);
  const std::optional<Mesh> glued = glue_pieces(band, rest);
  ASSERT_TRUE(glued.has_value());
  EXPECT_EQ(glued->n_faces(), 512u);
  EXPECT_EQ(glued->n_vertices(), 32u * 9u);  // the 32 vertices of the cut are one each
  EXPECT_EQ(boundary_loops(*glued).size(), 2u);
  EXPECT_EQ(euler_characteristic(*glued), 0);
  EXPECT_NEAR(surface_area(*glued), surface_area(band) + surface_area(rest), 1e-12);

  const std::optional<JoinedStrip> one = one_strip_of(*glued, at_tolerance({}, 0.01));
  ASSERT_TRUE(one.has_value());
  EXPECT_TRUE(one->refined.verdict.accept);
  EXPECT_TRUE(one->refined.verdict.certified);
  EXPECT_LE(one->refined.verdict.upper_bound, 0.01);
  EXPECT_NEAR(flat_area(one->flat), surface_area(*glued), 1e-9);
}

// Pieces that share no edge do not glue: two bands with a ring between them, and two
// triangles that touch at one corner.
TEST(Rejoin, PiecesThatShareNoEdgeDoNotGlue) {
  const TriangleMesh cylinder =
      open_cylinder({.radius = 1.0, .height = 2.0, .segments = 32, .rings = 8});
  const Mesh bottom = piece_of(cylinder, [](const Vec3& c) { return c.z() < -0.75; });
  const Mesh top = piece_of(cylinder, [](const Vec3& c) { return c.z() > -0.5; });
  EXPECT_FALSE(glue_pieces(bottom, top).has_value());

  TriangleMesh a, b;
  a.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  a.triangles = {{0, 1, 2}};
  b.vertices = {Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
  b.triangles = {{0, 1, 2}};
  EXPECT_FALSE(glue_pieces(to_mesh(a), to_mesh(b)).has_value());
}

// A hemisphere is no strip within a tolerance far below its radius: one_strip_of refuses it,
// whereas its two halves glue.
TEST(Rejoin, ACurvedUnionBeyondTheToleranceIsNoStrip) {
  const TriangleMesh ball = sphere({});
  const Mesh north_east = piece_of(ball, [](const Vec3& c) { return c.z() > 0 && c.x() > 0; });
  const Mesh north_west = piece_of(ball, [](const Vec3& c) { return c.z() > 0 && c.x() <= 0; });
  const std::optional<Mesh> north = glue_pieces(north_east, north_west);
  ASSERT_TRUE(north.has_value());
  EXPECT_EQ(boundary_loops(*north).size(), 1u);
  EXPECT_FALSE(one_strip_of(*north, at_tolerance({}, 0.001)).has_value());
}

}  // namespace
}  // namespace papercraft
