// Polygons as triangles: fans, ear clipping, folding least out of the plane.
#include "nodes/load/triangulate.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "core/errors.h"
#include "core/mesh.h"
#include "nodes/load/raw_mesh.h"
#include "nodes/load/soup.h"
#include "support/load_files.h"

namespace papercraft {
namespace {

namespace fs = std::filesystem;
using namespace testing;  // load_files.h

TEST_F(LoadOpenMeshTest, PolygonWithACornerOnAStraightSideGetsNoFlatTriangle) {
  // The square 0 0 - 3 3 with two more corners on its bottom side: the fan from corner 0 makes
  // two triangles of no area along it, each the other's neighbour across its longest edge, so
  // the repair of flat triangles could not heal them and the file was refused.
  const fs::path path = write("midpoints.obj",
                              "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 3 3 0\nv 0 3 0\n"
                              "f 1 2 3 4 5 6\n");
  const LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(loaded.mesh.n_faces(), 4u);
  for (auto f : loaded.mesh.faces()) EXPECT_GT(loaded.mesh.calc_face_area(f), 0.1);
  EXPECT_NEAR(surface_area(loaded.mesh), 9.0, 1e-12);
  EXPECT_TRUE(std::any_of(loaded.repairs.begin(), loaded.repairs.end(), [](const std::string& r) {
    return r.find("with a corner on a straight side") != std::string::npos;
  })) << ::testing::PrintToString(loaded.repairs);
}

TEST_F(LoadOpenMeshTest, ObjQuadsAreTriangulated) {
  const fs::path path = write("cube.obj",
                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                              "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                              "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(loaded.mesh.n_vertices(), 8u);
  EXPECT_EQ(loaded.mesh.n_faces(), 12u);
  EXPECT_TRUE(boundary_loops(loaded.mesh).empty());
  EXPECT_EQ(euler_characteristic(loaded.mesh), 2);
  EXPECT_EQ(loaded.input_faces, 6u);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0], "triangulated 6 polygons into 12 triangles");
  EXPECT_FALSE(loaded.has_uvs);
}

TEST_F(LoadOpenMeshTest, ObjQuadWithTextureCoordinates) {
  const fs::path path = write("quad.obj",
                              "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                              "f 1/1 2/2 3/3 4/4\n");
  const LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(loaded.mesh.n_faces(), 2u);
  EXPECT_EQ(boundary_loops(loaded.mesh).size(), 1u);
  ASSERT_TRUE(loaded.has_uvs);
  EXPECT_EQ(loaded.uv_seam_vertices, 0u);
  for (auto v : loaded.mesh.vertices()) {
    const OpenMesh::Vec3d p = loaded.mesh.point(v);
    EXPECT_EQ(loaded.mesh.texcoord2D(v), OpenMesh::Vec2d(p[0] / 2, p[1]));
  }
}

TEST_F(LoadOpenMeshTest, NonConvexPolygonIsEarClipped) {
  // An L-shaped hexagon whose fan from the first corner folds over; its area is 1.5.
  const LoadedMesh loaded = load_mesh(write("ell.obj",
                                            "v 1 1 0\nv 0 1 0\nv 0 0 0\nv 2 0 0\nv 2 0.5 0\n"
                                            "v 1 0.5 0\nf 1 2 3 4 5 6\n"));
  EXPECT_EQ(loaded.mesh.n_faces(), 4u);
  EXPECT_NEAR(surface_area(loaded.mesh), 1.5, 1e-12);
  for (auto f : loaded.mesh.faces()) {
    EXPECT_GT(loaded.mesh.calc_face_normal(f)[2], 0.0) << "every triangle keeps the orientation";
  }
  ASSERT_EQ(boundary_loops(loaded.mesh).size(), 1u);
  EXPECT_NE(
      std::find(loaded.repairs.begin(), loaded.repairs.end(), "ear-clipped 1 non-convex polygon"),
      loaded.repairs.end());
  // The same L with its normal pointing down (corners in the other order) and in the yz plane.
  const LoadedMesh flipped = load_mesh(write("ell_yz.obj",
                                             "v 0 1 1\nv 0 0.5 1\nv 0 0.5 2\nv 0 0 2\nv 0 0 0\n"
                                             "v 0 1 0\nf 1 2 3 4 5 6\n"));
  EXPECT_EQ(flipped.mesh.n_faces(), 4u);
  EXPECT_NEAR(surface_area(flipped.mesh), 1.5, 1e-12);
  // A self-intersecting (bow-tie) pentagon has no consistent triangulation.
  expect_error<InvalidInputException>(
      write("star.obj", "v 0 0 0\nv 2 2 0\nv 2 0 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5\n"),
      {"1 self-intersecting polygon", "first face 0"});
}

// A pentagon out of its plane (trimesh's polygonfaces.obj: a square with a fifth corner raised
// above one side) has no ear to clip seen along its normal, but is no bow tie in a plane: it is
// triangulated so that its worst fold is least. Every triangulation of a pentagon is a fan from
// one corner; the one loaded folds no worse than the best of them.
TEST_F(LoadOpenMeshTest, APolygonOutOfItsPlaneIsTriangulatedFoldingLeast) {
  const double p[5][3] = {
      {-500, 0, 500}, {500, 0, 500}, {500, 0, -500}, {-500, 0, -500}, {0, 500, -500}};
  const std::string obj = obj_vertices(p);
  const LoadedMesh loaded = load_mesh(write("raised.obj", obj + "f 1 2 3 4 5\n"));
  ASSERT_EQ(loaded.mesh.n_faces(), 3u);
  EXPECT_NE(std::find(loaded.repairs.begin(), loaded.repairs.end(),
                      "triangulated 1 polygon out of its plane that crossed itself seen along its "
                      "normal so that its triangles fold least"),
            loaded.repairs.end());
  const auto point = [&](int i) { return Vec3(p[i][0], p[i][1], p[i][2]); };
  const auto unit_normal = [&](int a, int b, int c) {
    return (point(b) - point(a)).cross(point(c) - point(a)).normalized();
  };
  // The worst fold of the fan from corner k: triangles (k, k+1, k+2), (k, k+2, k+3),
  // (k, k+3, k+4), neighbours over the diagonals k-(k+2) and k-(k+3).
  double best = -2.0;
  for (int k = 0; k < 5; ++k) {
    const Vec3 a = unit_normal(k, (k + 1) % 5, (k + 2) % 5);
    const Vec3 b = unit_normal(k, (k + 2) % 5, (k + 3) % 5);
    const Vec3 c = unit_normal(k, (k + 3) % 5, (k + 4) % 5);
    best = std::max(best, std::min(a.dot(b), b.dot(c)));
  }
  double worst = 1.0;
  for (auto e : loaded.mesh.edges()) {
    if (loaded.mesh.is_boundary(e)) continue;
    const auto m = loaded.mesh.calc_face_normal(e.h0().face());
    const auto n = loaded.mesh.calc_face_normal(e.h1().face());
    worst = std::min(worst, static_cast<double>(OpenMesh::dot(m, n)));
  }
  EXPECT_NEAR(worst, best, 1e-6);
  EXPECT_GT(best, -0.5);  // no fan folds it flat onto itself
}

TEST_F(LoadOpenMeshTest, ATwistedQuadIsSplitAlongTheDiagonalThatFoldsLeast) {
  // Face 4596 of the Beast (common-3d-test-models): seen along its Newell normal, a bow tie
  // (no ear to clip). Either diagonal folds it sharply: the cosine between the two triangles'
  // normals is -0.56 over 0-2 and -0.70 over 1-3.
  const double p[4][3] = {{12.880048, 236.295380, 43.735176},
                          {12.819249, 236.278671, 43.792137},
                          {12.944972, 236.356552, 42.972511},
                          {12.883921, 236.197540, 42.910332}};
  const std::string obj = obj_vertices(p);
  const LoadedMesh loaded = load_mesh(write("twisted.obj", obj + "f 1 2 3 4\n"));
  ASSERT_EQ(loaded.mesh.n_faces(), 2u);
  EXPECT_NE(std::find(loaded.repairs.begin(), loaded.repairs.end(),
                      "split 1 twisted quad (self-intersecting seen along its normal) along the "
                      "diagonal whose two triangles fold least"),
            loaded.repairs.end());
  // The cosine between the normals of the two triangles over each diagonal.
  auto cosine = [&](int a, int b, int c, int d, int e, int f) {
    const auto point = [&](int i) { return Vec3(p[i][0], p[i][1], p[i][2]); };
    const Vec3 m = (point(b) - point(a)).cross(point(c) - point(a)).normalized();
    const Vec3 n = (point(e) - point(d)).cross(point(f) - point(d)).normalized();
    return m.dot(n);
  };
  const double over_02 = cosine(0, 1, 2, 0, 2, 3), over_13 = cosine(0, 1, 3, 1, 2, 3);
  ASSERT_GT(over_02, over_13 + 0.1);
  std::vector<Vec3> normals;
  for (auto f : loaded.mesh.faces()) {
    const auto n = loaded.mesh.calc_face_normal(f);
    normals.emplace_back(n[0], n[1], n[2]);
  }
  EXPECT_NEAR(normals[0].normalized().dot(normals[1].normalized()), over_02,
              1e-4);  // OBJ: single precision
  // Both triangles hold the diagonal 0-2 (file vertices 1 and 3).
  for (auto f : loaded.mesh.faces()) {
    std::set<int> corners;
    for (auto v : f.vertices()) corners.insert(v.idx());
    EXPECT_TRUE(corners.count(0) && corners.count(2));
  }
}

// Random simple polygons (star-shaped about a point, 3 to 12 corners, in random planes):
// n - 2 triangles over the polygon's corners, whose areas sum to the polygon's and whose
// normals all point the polygon's way.
TEST(LoadTriangulate, TrianglesCoverThePolygonFacingItsWay) {
  using load_internal::Vec3d;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int round = 0; round < 200; ++round) {
    const int n = 3 + round % 10;
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2 * M_PI * (i + 0.1 + 0.8 * unit(random)) / n);
    // A random frame: the polygon's plane.
    const Vec3d a = Vec3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5).normalized();
    Vec3d b = OpenMesh::cross(a, Vec3d(0.3, 0.7, -0.2));
    b.normalize();
    const Vec3d normal = OpenMesh::cross(a, b);
    const Vec3d origin(unit(random), unit(random), unit(random));
    load_internal::RawMesh raw;
    std::vector<std::pair<double, double>> flat;
    for (double angle : angles) {
      const double r = 0.3 + unit(random);
      flat.push_back({r * std::cos(angle), r * std::sin(angle)});
      raw.positions.push_back(origin + a * flat.back().first + b * flat.back().second);
      raw.corners.push_back(static_cast<int>(raw.corners.size()));
    }
    raw.face_start.push_back(raw.corners.size());
    double area = 0.0;
    for (int i = 0; i < n; ++i) {
      const auto& [x0, y0] = flat[i];
      const auto& [x1, y1] = flat[(i + 1) % n];
      area += 0.5 * (x0 * y1 - x1 * y0);
    }
    std::vector<std::string> repairs;
    const load_internal::Soup soup = load_internal::triangulate(raw, false, {}, "polygon", repairs);
    SCOPED_TRACE("round " + std::to_string(round) + ", " + std::to_string(n) + " corners");
    ASSERT_EQ(soup.triangles.size(), static_cast<std::size_t>(n - 2));
    double covered = 0.0;
    for (const auto& t : soup.triangles) {
      for (int v : t) {
        EXPECT_GE(v, 0);
        EXPECT_LT(v, n);
      }
      const Vec3d cross = OpenMesh::cross(soup.positions[t[1]] - soup.positions[t[0]],
                                          soup.positions[t[2]] - soup.positions[t[0]]);
      EXPECT_GT(OpenMesh::dot(cross, normal), 0.0) << "a triangle faces away from its polygon";
      covered += 0.5 * cross.norm();
    }
    EXPECT_NEAR(covered, area, 1e-9 * area);
  }
}

}  // namespace
}  // namespace papercraft
