// The safe repairs of loading: unreferenced and duplicate vertices, orientation, non-manifold
// edges and vertices, degenerate and duplicate faces.
#include "nodes/load/repair.h"

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
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "core/errors.h"
#include "core/mesh.h"
#include "nodes/load/soup.h"
#include "support/load_files.h"

namespace papercraft {
namespace {

namespace fs = std::filesystem;
using namespace testing;  // load_files.h

// ---------------------------------------------------------------------------------------------
// Repairs

TEST_F(LoadOpenMeshTest, UnreferencedVertexIsRemovedAndReported) {
  const fs::path path = write("unreferenced.off", tetra_off("5 5 5\n", "", 1, 0));
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0], "removed 1 unreferenced vertex");
  EXPECT_EQ(loaded.input_vertices, 5u);

  LoadOptions keep;
  keep.repair = false;
  const LoadedMesh kept = load_mesh(path, keep);
  EXPECT_EQ(kept.mesh.n_vertices(), 5u);
  EXPECT_TRUE(kept.repairs.empty());
}

TEST_F(LoadOpenMeshTest, InputVertexPropertyFollowsRemovals) {
  // The unreferenced vertex comes first, so every kept vertex moves down by one.
  const fs::path path = write("shifted.off",
                              "OFF\n5 4 0\n9 9 9\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                              "3 1 3 2\n3 1 2 4\n3 1 4 3\n3 2 3 4\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  for (auto v : loaded.mesh.vertices()) EXPECT_EQ(input_vertex_of(loaded.mesh, v), v.idx() + 1);
}

TEST_F(LoadOpenMeshTest, ExactDuplicateVerticesAreMergedAndReported) {
  // A triangle soup: every face has its own three vertices.
  std::string text;
  for (const auto& f : kTetraFaces) {
    for (int corner : f) {
      const auto& p = kTetraPoints[corner];
      text += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " +
              std::to_string(p[2]) + "\n";
    }
  }
  text += "f 1 2 3\nf 4 5 6\nf 7 8 9\nf 10 11 12\n";
  const fs::path path = write("soup.obj", text);
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0], "merged 8 exactly duplicate vertices");

  LoadOptions keep;
  keep.repair = false;
  const LoadedMesh kept = load_mesh(path, keep);
  EXPECT_EQ(kept.mesh.n_vertices(), 12u);
  EXPECT_EQ(boundary_loops(kept.mesh).size(), 4u);
}

TEST_F(LoadOpenMeshTest, NearDuplicatesMergeOnlyWithinEpsilon) {
  const fs::path path = write("near.off",
                              "OFF\n5 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.0001 0 0\n"
                              "3 0 2 1\n3 0 1 3\n3 4 3 2\n3 1 2 3\n");
  const LoadedMesh exact = load_mesh(path);
  EXPECT_EQ(exact.mesh.n_vertices(), 5u);
  EXPECT_EQ(boundary_loops(exact.mesh).size(), 1u);

  LoadOptions welding;
  welding.duplicate_vertex_epsilon = 0.001;
  const LoadedMesh welded = load_mesh(path, welding);
  EXPECT_EQ(welded.mesh.n_vertices(), 4u);
  EXPECT_TRUE(boundary_loops(welded.mesh).empty());
  ASSERT_EQ(welded.repairs.size(), 1u);
  EXPECT_NE(welded.repairs[0].find("merged 1 duplicate vertex (within 0.001)"), std::string::npos);
}

TEST_F(LoadOpenMeshTest, InconsistentOrientationIsRepairedOrRefused) {
  // Face 3 reversed.
  const fs::path path = write("flipped_face.off",
                              "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 3 2\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0], "reoriented 1 face to agree with their neighbours");

  LoadOptions keep;
  keep.repair = false;
  expect_error<InvalidInputException>(path, {"not consistently oriented", "faces"}, keep);
}

TEST_F(LoadOpenMeshTest, ReorientationKeepsTheMajorityOrientation) {
  // An open surface (no volume to decide by) whose first face disagrees with the other two.
  const fs::path path = write(
      "open_flipped.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 3 2\n");
  const LoadedMesh loaded = load_mesh(path);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0], "reoriented 1 face to agree with their neighbours");
  // Face 1 kept its orientation 0 -> 1 -> 3.
  std::vector<int> corners;
  for (auto v : loaded.mesh.fv_range(Mesh::FaceHandle(1))) corners.push_back(v.idx());
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
  EXPECT_EQ(corners, (std::vector<int>{0, 1, 3}));
}

TEST_F(LoadOpenMeshTest, InsideOutClosedComponentIsFlipped) {
  const fs::path path = write("inside_out.off",
                              "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                              "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0], "flipped 1 closed component that faced inwards (4 faces)");
}

// ---------------------------------------------------------------------------------------------
// Bad files

TEST_F(LoadOpenMeshTest, EdgeSharedByThreeFaces) {
  // Three triangles hinge on edge 0-1: two lie flat in z = 0, a fin stands up between them.
  const fs::path fin = write("fin.off",
                             "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
                             "3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  LoadOptions strict;
  strict.repair = false;
  expect_error<InvalidInputException>(fin, {"1 non-manifold edge", "vertices 0-1", "faces 0, 1, 2"},
                                      strict);
  // Repaired: the flattest pair (the two in z = 0) stays joined across the edge; the fin gets
  // the edge as a boundary, with its own copies of 0 and 1 moved into it.
  const LoadedMesh loaded = load_mesh(fin);
  EXPECT_EQ(loaded.mesh.n_faces(), 3u);
  EXPECT_EQ(loaded.mesh.n_vertices(), 7u);
  EXPECT_EQ(connected_components(loaded.mesh), 2);
  std::size_t joined = 0;
  for (auto e : loaded.mesh.edges()) {
    if (loaded.mesh.is_boundary(e)) continue;
    ++joined;  // the edge 0-1 between the flat two: no corner of either is raised
    for (auto h : {e.h0(), e.h1()})
      for (auto v : h.face().vertices()) EXPECT_LE(loaded.mesh.point(v)[2], 0.0);
  }
  EXPECT_EQ(joined, 1u);
}

// A closed tetrahedron (0 1 3 4) set on the edge 0-1 of a face of a surface (1 0 2), as in a
// pocket a modeller left on a surface: three faces on edge 0-1, and pairing them does not part
// them, since around both 0 and 1 the tetrahedron's faces join the pair to the face left over.
// The repair opens one edge of the tetrahedron at one end of 0-1 (the sharper crease), so the
// face left over gets its own copy of that end. Without the repair it is an error.
TEST_F(LoadOpenMeshTest, SheetsThatMeetAgainAroundAnEdgeArePartedByOpeningAnEdge) {
  const fs::path path = write("pocket.off",
                              "OFF\n5 5 0\n0 0 0\n1 0 0\n0.5 -1 0\n0.5 0.5 0.5\n0.5 1 0\n"
                              "3 1 0 2\n3 0 4 1\n3 0 1 3\n3 1 4 3\n3 4 0 3\n");
  LoadOptions strict;
  strict.repair = false;
  expect_error<InvalidInputException>(path, {"1 non-manifold edge", "vertices 0-1"}, strict);
  const LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(loaded.mesh.n_faces(), 5u);
  EXPECT_EQ(loaded.mesh.n_vertices(), 6u);  // one end of 0-1 copied
  // The surface is unchanged (the copy moved by 1e-7 of the diagonal at most).
  const std::vector<OpenMesh::Vec3d> p = {
      {0, 0, 0}, {1, 0, 0}, {0.5, -1, 0}, {0.5, 0.5, 0.5}, {0.5, 1, 0}};
  double area = 0.0;
  for (auto [i, j, k] :
       std::vector<std::array<int, 3>>{{1, 0, 2}, {0, 4, 1}, {0, 1, 3}, {1, 4, 3}, {4, 0, 3}})
    area += 0.5 * OpenMesh::cross(p[j] - p[i], p[k] - p[i]).norm();
  EXPECT_NEAR(surface_area(loaded.mesh), area, 1e-6);
  int boundary = 0;
  for (auto e : loaded.mesh.edges()) boundary += loaded.mesh.is_boundary(e);
  // The surface face's two outer edges, the tetrahedron's 0-1 (its face there left over), and
  // the opened edge's two sides.
  EXPECT_EQ(boundary, 5);
  EXPECT_EQ(connected_components(loaded.mesh), 1);
  const auto& repairs = loaded.repairs;
  EXPECT_TRUE(std::any_of(repairs.begin(), repairs.end(), [](const std::string& r) {
    return r.find("opened 1 edge next to non-manifold edges") != std::string::npos;
  })) << ::testing::PrintToString(repairs);
}

// Two closed tetrahedra touching along edge 0-1, each on its own side (the second is the
// first turned half a turn about that edge): four faces on the edge, two of each solid. The
// repair pairs them by solid, so each stays closed, and moves the second's copies of 0 and 1
// into it by at most 1e-7 of the diagonal, so the two share no point; without the repair it
// is an error, as before.
TEST_F(LoadOpenMeshTest, TwoSolidsTouchingAlongAnEdgeAreCutApart) {
  const fs::path path = write("touching.off",
                              "OFF\n6 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 -1 0\n0 0 -1\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                              "3 0 4 1\n3 0 1 5\n3 0 5 4\n3 1 4 5\n");
  LoadOptions strict;
  strict.repair = false;
  expect_error<InvalidInputException>(path, {"non-manifold edge", "vertices 0-1"}, strict);
  const LoadedMesh loaded = load_mesh(path);
  expect_two_closed_tetrahedra(loaded);
  EXPECT_NEAR(surface_area(loaded.mesh), 2 * (1.5 + std::sqrt(3.0) / 2.0), 1e-6);
  int copies = 0;
  for (auto v : loaded.mesh.vertices()) {
    const int input = input_vertex_of(loaded.mesh, v);
    if (input > 1) continue;
    const OpenMesh::Vec3d file_point(input == 1 ? 1.0 : 0.0, 0.0, 0.0);
    const double moved = (loaded.mesh.point(v) - file_point).norm();
    EXPECT_LE(moved, 3e-7 * (1 + 1e-12));  // the diagonal of [0,1] x [-1,1] x [-1,1] is 3
    copies += moved > 0.0;
  }
  EXPECT_EQ(copies, 2);  // one copy of each end moved; the originals stay
  ASSERT_FALSE(loaded.repairs.empty());
  EXPECT_NE(loaded.repairs[0].find("cut 1 non-manifold edge apart"), std::string::npos)
      << loaded.repairs[0];
}

// The same two solids with one face of each facing the wrong way (0 3 1 and 0 4 5), as a
// two-sided export keeps whichever side it wrote first: the faces around edge 0-1 no longer
// alternate in and out, and paired as they ran, a sheet took a face of each solid and an edge
// had to be opened to part them again. The faces are made to agree with their neighbours
// first, so each solid is paired with itself and stays closed, with nothing opened.
TEST_F(LoadOpenMeshTest, SolidsWithFacesTheWrongWayArePairedBySolid) {
  const fs::path path = write("touching_flipped.off",
                              "OFF\n6 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 -1 0\n0 0 -1\n"
                              "3 0 2 1\n3 0 3 1\n3 0 3 2\n3 1 2 3\n"
                              "3 0 4 1\n3 0 1 5\n3 0 4 5\n3 1 4 5\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_two_closed_tetrahedra(loaded);
  const auto& repairs = loaded.repairs;
  EXPECT_FALSE(std::any_of(repairs.begin(), repairs.end(), [](const std::string& r) {
    return r.find("opened") != std::string::npos;
  })) << ::testing::PrintToString(repairs);
  EXPECT_TRUE(std::any_of(repairs.begin(), repairs.end(), [](const std::string& r) {
    return r.find("reoriented 2 faces") != std::string::npos;
  })) << ::testing::PrintToString(repairs);
}

// A 3 x 3 x 3 grid of cubes with every face of every cell written once, as a volume mesh is:
// of its 252 edges, the 36 inside have four faces and the 72 on the outside between two cells
// three. It is refused as such, quickly, rather than cut into 27 closed boxes. One cell alone
// (a plain cube) loads.
TEST_F(LoadOpenMeshTest, AVolumeMeshIsRefused) {
  const auto grid = [](int n) {
    const auto id = [n](int x, int y, int z) { return (x * (n + 1) + y) * (n + 1) + z; };
    std::ostringstream vertices, faces;
    int count = 0;
    for (int x = 0; x <= n; ++x)
      for (int y = 0; y <= n; ++y)
        for (int z = 0; z <= n; ++z) vertices << x << ' ' << y << ' ' << z << '\n';
    // Each lattice square, in each of the three planes, as two triangles.
    for (int axis = 0; axis < 3; ++axis)
      for (int a = 0; a <= n; ++a)
        for (int b = 0; b < n; ++b)
          for (int c = 0; c < n; ++c) {
            std::array<std::array<int, 3>, 4> p;
            const std::array<std::array<int, 2>, 4> uv = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
            for (int k = 0; k < 4; ++k) {
              std::array<int, 3> q{};
              q[axis] = a;
              q[(axis + 1) % 3] = b + uv[k][0];
              q[(axis + 2) % 3] = c + uv[k][1];
              p[k] = q;
            }
            const auto v = [&](int k) { return id(p[k][0], p[k][1], p[k][2]); };
            faces << "3 " << v(0) << ' ' << v(1) << ' ' << v(2) << "\n3 " << v(0) << ' ' << v(2)
                  << ' ' << v(3) << '\n';
            count += 2;
          }
    return "OFF\n" + std::to_string((n + 1) * (n + 1) * (n + 1)) + ' ' + std::to_string(count) +
           " 0\n" + vertices.str() + faces.str();
  };
  expect_error<InvalidInputException>(write("cells.off", grid(3)),
                                      {"cells.off",
                                       "108 of its 252 edges are shared by three or "
                                       "more faces",
                                       "volume mesh"});
  const LoadedMesh cube = load_mesh(write("cell.off", grid(1)));
  EXPECT_EQ(cube.mesh.n_faces(), 12u);
  EXPECT_TRUE(boundary_loops(cube.mesh).empty());
}

TEST_F(LoadOpenMeshTest, NonManifoldVertex) {
  // Two closed tetrahedra that share only vertex 0; the second's first corner names a
  // different fan of vertex 0 than the first's.
  const fs::path path = write("bowtie.off",
                              "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                              "3 0 5 4\n3 0 4 6\n3 0 6 5\n3 4 5 6\n");
  LoadOptions strict;
  strict.repair = false;
  expect_error<InvalidInputException>(path, {"1 non-manifold vertex", "first vertex 0"}, strict);
  // Repaired: vertex 0 is split, one copy per tetrahedron.
  const LoadedMesh loaded = load_mesh(path);
  expect_two_closed_tetrahedra(loaded);
  int copies_of_zero = 0;
  for (auto v : loaded.mesh.vertices()) {
    if (input_vertex_of(loaded.mesh, v) == 0) {
      ++copies_of_zero;
      EXPECT_EQ(loaded.mesh.point(v), Mesh::Point(0, 0, 0));
    }
  }
  EXPECT_EQ(copies_of_zero, 2);
  ASSERT_FALSE(loaded.repairs.empty());  // (the second tetrahedron also faces inwards)
  EXPECT_EQ(loaded.repairs[0],
            "split 1 non-manifold vertex into one vertex per fan (1 copy added)");
}

TEST_F(LoadOpenMeshTest, DegenerateFaces) {
  LoadOptions strict;
  strict.repair = false;
  // Collinear corners, a face on its own: the repair drops it, and its two vertices only it
  // used; without the repair it is an error.
  const fs::path collinear = write("collinear.off", tetra_off("2 0 0\n3 0 0\n", "3 1 4 5\n", 2, 1));
  const LoadedMesh healed = load_mesh(collinear);
  EXPECT_EQ(healed.mesh.n_faces(), 4u);
  EXPECT_EQ(healed.mesh.n_vertices(), 4u);
  EXPECT_EQ(healed.repairs,
            (std::vector<std::string>{"removed 1 zero-area face (corners on one line), each face "
                                      "across its longest edge split at its middle corner",
                                      "removed 2 vertices used only by the faces removed"}));
  expect_error<InvalidInputException>(
      collinear, {"1 degenerate (zero-area) face", "first face 4", "vertices 1, 4, 5"}, strict);
  // A triangle with a repeated corner (no area): dropped by the repair, else an error.
  const fs::path repeated_off = write("repeated.off", tetra_off("", "3 1 2 2\n", 0, 1));
  expect_error<InvalidInputException>(repeated_off, {"degenerate", "face 4"}, strict);
  const LoadedMesh off = load_mesh(repeated_off);
  expect_closed_tetrahedron(off);
  EXPECT_EQ(off.repairs,
            (std::vector<std::string>{"removed 1 face with a corner repeated (in the file, or once "
                                      "duplicate vertices were merged)"}));
  // In an OBJ, a face of fewer than 3 distinct vertices (OpenMesh's reader drops it), here
  // between faces with texture coordinates (each corner's UV its x and y): the faces after it
  // keep their own.
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0 0\n";
  for (const auto& f : kTetraFaces) {
    obj += "f";
    for (int v : f) obj += " " + std::to_string(v + 1) + "/" + std::to_string(v + 1);
    obj += &f == &kTetraFaces[1] ? "\nf 2/2 3/3 3/3\nf 2/2 3/3\n" : "\n";
  }
  const fs::path repeated_obj = write("repeated.obj", obj);
  expect_error<InvalidInputException>(repeated_obj, {"2 degenerate faces", "line 11"}, strict);
  const LoadedMesh with_uvs = load_mesh(repeated_obj);
  expect_closed_tetrahedron(with_uvs);
  EXPECT_EQ(
      with_uvs.repairs,
      (std::vector<std::string>{"removed 2 faces of fewer than 3 distinct vertices (no area)"}));
  ASSERT_TRUE(with_uvs.has_uvs);
  EXPECT_EQ(with_uvs.uv_seam_vertices, 0u);
  for (auto v : with_uvs.mesh.vertices()) {
    const auto p = with_uvs.mesh.point(v);
    EXPECT_EQ(with_uvs.mesh.texcoord2D(v), Mesh::TexCoord2D(p[0], p[1]));
  }
  // Two corners of an STL triangle coincide (OpenMesh's reader drops it): without the repair
  // an error naming it; with it, the removal is logged and the tetrahedron lacks that face.
  std::string stl = tetra_stl_binary("binary");
  std::memcpy(&stl[84 + 50 * 2 + 24], &stl[84 + 50 * 2 + 12], 12);
  const fs::path flat_stl = write("degenerate.stl", stl);
  expect_error<InvalidInputException>(flat_stl, {"1 degenerate face", "triangle 2"}, strict);
  const LoadedMesh open = load_mesh(flat_stl);
  EXPECT_EQ(open.mesh.n_faces(), 3u);
  EXPECT_EQ(open.input_faces, 4u);
  EXPECT_EQ(boundary_loops(open.mesh).size(), 1u);
  EXPECT_NE(std::find(open.repairs.begin(), open.repairs.end(),
                      "removed 1 triangle two of whose corners coincide (no area)"),
            open.repairs.end());
}

TEST_F(LoadOpenMeshTest, StlNeedleTrianglesAreDropped) {
  // A closed tetrahedron and, as exporters that round their coordinates write them, a needle
  // along its edge 0-1 whose corners 1 and 2 rounded to the same point (binary), and the same
  // needle twice in ascii: dropped, the tetrahedron left closed.
  std::string binary = tetra_stl_binary("binary");
  binary[80] = 5;  // triangle count 5
  for (int i = 0; i < 3; ++i) put_f32(binary, 0.0f);
  for (int corner : {0, 1, 1})
    for (double c : kTetraPoints[corner]) put_f32(binary, static_cast<float>(c));
  binary += std::string(2, '\0');
  std::string ascii = "solid needle\n" + stl_facet({0, 1, 1});
  for (const auto& f : kTetraFaces) ascii += stl_facet({f[0], f[1], f[2]});
  ascii += stl_facet({3, 2, 3});
  ascii += "endsolid needle\n";
  LoadOptions strict;
  strict.repair = false;
  for (const auto& [name, data, needles, first] :
       {std::tuple{"needle.stl", binary, 1, 4}, std::tuple{"needles.stl", ascii, 2, 0}}) {
    SCOPED_TRACE(name);
    const fs::path path = write(name, data);
    const LoadedMesh loaded = load_mesh(path);
    expect_closed_tetrahedron(loaded);
    EXPECT_EQ(loaded.input_faces, 4u + needles);
    const std::string removed = "removed " + std::to_string(needles) +
                                (needles == 1 ? " triangle" : " triangles") +
                                " two of whose corners coincide (no area)";
    EXPECT_NE(std::find(loaded.repairs.begin(), loaded.repairs.end(), removed),
              loaded.repairs.end());
    const std::string count =
        std::to_string(needles) + (needles == 1 ? " degenerate face" : " degenerate faces");
    const std::string first_one = "first triangle " + std::to_string(first);
    expect_error<InvalidInputException>(path, {count.c_str(), first_one.c_str()}, strict);
  }
}

TEST_F(LoadOpenMeshTest, AZeroAreaFaceInASurfaceIsHealedWithoutMovingIt) {
  // The tetrahedron with edge 0-1 split at its middle, vertex 4, on the side of face 0 1 3
  // (0 4 3 and 4 1 3), and a zero-area face 0 1 4 closing the gap against face 0 2 1: every
  // edge has two faces. Each corner's UV is its (x, y).
  const char* obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 0 0\nvt 0.5 0\n"
      "f 1/1 3/3 2/2\nf 1/1 5/5 4/4\nf 5/5 2/2 4/4\nf 1/1 4/4 3/3\nf 2/2 3/3 4/4\n"
      "f 1/1 2/2 5/5\n";
  const fs::path path = write("cap.obj", obj);
  const LoadedMesh loaded = load_mesh(path);
  // The flat face goes, and face 0 2 1 is split at vertex 4: five faces, closed, the same area.
  EXPECT_EQ(loaded.mesh.n_faces(), 6u - 1u + 1u);
  EXPECT_EQ(loaded.mesh.n_vertices(), 5u);
  EXPECT_TRUE(boundary_loops(loaded.mesh).empty());
  EXPECT_NEAR(surface_area(loaded.mesh), 1.5 + std::sqrt(3.0) / 2.0, 1e-12);
  for (auto f : loaded.mesh.faces()) {
    const auto n = loaded.mesh.calc_face_normal(f);
    EXPECT_GT(n.norm(), 0.5) << "no face left without area";
  }
  // The UV of vertex 4 in the split face is interpolated along the edge: (0.5, 0), as its own.
  ASSERT_TRUE(loaded.has_uvs);
  EXPECT_EQ(loaded.uv_seam_vertices, 0u);
  const auto uv = loaded.mesh.texcoord2D(loaded.mesh.vertex_handle(4));
  EXPECT_DOUBLE_EQ(uv[0], 0.5);
  EXPECT_DOUBLE_EQ(uv[1], 0.0);
  EXPECT_NE(std::find(loaded.repairs.begin(), loaded.repairs.end(),
                      "removed 1 zero-area face (corners on one line), each face across its "
                      "longest edge split at its middle corner"),
            loaded.repairs.end());
  LoadOptions strict;
  strict.repair = false;
  expect_error<InvalidInputException>(path, {"1 degenerate (zero-area) face", "first face 5"},
                                      strict);
}

TEST_F(LoadOpenMeshTest, DuplicateFaceIsRemovedByTheRepairAndAnErrorWithout) {
  // Face 0 of the tetrahedron, (0 2 1), given twice.
  const fs::path twice = write("twice.off", tetra_off("", "3 0 2 1\n", 0, 1));
  const LoadedMesh loaded = load_mesh(twice);
  EXPECT_EQ(loaded.mesh.n_faces(), 4u);
  EXPECT_EQ(loaded.mesh.n_vertices(), 4u);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0],
            "removed 1 duplicate face (the same vertices as another face, facing the same way)");
  LoadOptions strict;
  strict.repair = false;
  expect_error<InvalidInputException>(twice, {"1 duplicate face", "face 4 repeats face 0"}, strict);
}

TEST_F(LoadOpenMeshTest, AFlapFoldedFlatOntoItselfIsRemovedWhole) {
  // Vertex 4 is used only by a pair of faces facing opposite ways over edge 0-1 of the
  // tetrahedron (as Blender's Suzanne has, where two quads share three corners): that edge is
  // then used four times. The pair has no area; both go, and vertex 4 with them.
  const LoadedMesh loaded =
      load_mesh(write("flap.off", tetra_off("0.5 -0.5 0\n", "3 0 1 4\n3 0 4 1\n", 1, 2)));
  EXPECT_EQ(loaded.mesh.n_faces(), 4u);
  EXPECT_EQ(loaded.mesh.n_vertices(), 4u);
  EXPECT_NEAR(surface_area(loaded.mesh), 1.5 + std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_EQ(loaded.repairs,
            (std::vector<std::string>{"removed 1 pair of faces on the same vertices facing "
                                      "opposite ways (a flap folded flat onto itself)",
                                      "removed 1 vertex used only by the faces removed"}));
  // Two copies one way and one the other: one pair goes, the first facing the way most do
  // (the tetrahedron's own face 0) stays.
  const LoadedMesh three = load_mesh(write("three.off", tetra_off("", "3 2 1 0\n3 0 1 2\n", 0, 2)));
  EXPECT_EQ(three.mesh.n_faces(), 4u);
  EXPECT_NEAR(surface_area(three.mesh), 1.5 + std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_EQ(three.repairs.size(), 1u);
}

TEST_F(LoadOpenMeshTest, ATwoSidedSurfaceKeepsOneSide) {
  // Every face written once facing each way, as game models do for a surface seen from both
  // sides: one of each pair stays.
  LoadOptions strict;
  strict.repair = false;
  // A square sheet: two triangles, each also written the other way.
  const fs::path sheet = write("sheet.off",
                               "OFF\n4 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                               "3 0 1 2\n3 0 2 3\n3 2 1 0\n3 3 2 0\n");
  const LoadedMesh square = load_mesh(sheet);
  EXPECT_EQ(square.mesh.n_faces(), 2u);
  EXPECT_NEAR(surface_area(square.mesh), 1.0, 1e-12);
  EXPECT_EQ(boundary_loops(square.mesh).size(), 1u);
  EXPECT_EQ(square.repairs, (std::vector<std::string>{
                                "kept one side of a two-sided surface (every face written once "
                                "facing each way): removed 2 faces"}));
  expect_error<InvalidInputException>(sheet, {"sheet.off", "duplicate"}, strict);
  // A closed tetrahedron written twice, the second time facing inwards and its faces first:
  // the faces kept face both ways, and the orientation repair turns them outwards.
  auto face = [](int a, int b, int c) {
    return std::to_string(3) + " " + std::to_string(a) + " " + std::to_string(b) + " " +
           std::to_string(c) + "\n";
  };
  const auto& f = kTetraFaces;
  std::string both = tetra_off("", "", 0, 4);
  both.insert(both.find(face(f[0][0], f[0][1], f[0][2])),
              face(f[0][2], f[0][1], f[0][0]) + face(f[1][2], f[1][1], f[1][0]));
  both += face(f[2][2], f[2][1], f[2][0]) + face(f[3][2], f[3][1], f[3][0]);
  const LoadedMesh tetra = load_mesh(write("two_sided.off", both));
  expect_closed_tetrahedron(tetra);
  // A tetrahedron with a flap is one-sided: the flap goes whole (AFlapFoldedFlatOntoItself...).
}

// ---------------------------------------------------------------------------------------------
// The repairs on generated soups, with exact counts

using load_internal::check_topology_and_orient;
using load_internal::heal_degenerate_triangles;
using load_internal::merge_duplicate_vertices;
using load_internal::remove_duplicate_triangles;
using load_internal::remove_unreferenced_vertices;
using load_internal::Soup;
using load_internal::Triangle3;
using load_internal::Vec3d;

Soup soup_of(const std::vector<Vec3d>& positions, const std::vector<Triangle3>& triangles) {
  Soup soup;
  soup.positions = positions;
  for (std::size_t v = 0; v < positions.size(); ++v)
    soup.source_vertex.push_back(static_cast<int>(v));
  soup.triangles = triangles;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    soup.source_face.push_back(static_cast<int>(t));
  return soup;
}

std::vector<Vec3d> tetra_positions() {
  std::vector<Vec3d> positions;
  for (const auto& p : kTetraPoints) positions.emplace_back(p[0], p[1], p[2]);
  return positions;
}

std::vector<Triangle3> tetra_triangles() {
  std::vector<Triangle3> triangles;
  for (const auto& f : kTetraFaces) triangles.push_back({f[0], f[1], f[2]});
  return triangles;
}

bool has_line(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

TEST(LoadRepairs, VerticesMergedAndDroppedAreCountedExactly) {
  std::vector<Vec3d> positions = tetra_positions();
  positions.push_back(positions[0]);                      // 4: an exact copy of 0
  positions.push_back(positions[1] + Vec3d(1e-9, 0, 0));  // 5: near 1
  positions.push_back(Vec3d(5, 5, 5));                    // 6: used by no face
  std::vector<Triangle3> triangles = tetra_triangles();
  triangles[0] = {4, 2, 1};
  triangles[1] = {0, 5, 3};
  Soup soup = soup_of(positions, triangles);
  EXPECT_EQ(merge_duplicate_vertices(soup, 0.0), 1u);
  EXPECT_EQ(merge_duplicate_vertices(soup, 1e-6), 1u);
  EXPECT_EQ(remove_unreferenced_vertices(soup), 1u);
  ASSERT_EQ(soup.positions.size(), 4u);
  ASSERT_EQ(soup.source_vertex.size(), 4u);
  for (const Triangle3& t : soup.triangles)
    for (int v : t) EXPECT_LT(v, 4);
  std::vector<std::string> repairs;
  check_topology_and_orient(soup, true, "tetra", repairs);
  EXPECT_TRUE(repairs.empty()) << ::testing::PrintToString(repairs);
}

TEST(LoadRepairs, DuplicateFacesAreCountedByKind) {
  {  // a copy facing the same way
    std::vector<Triangle3> triangles = tetra_triangles();
    triangles.push_back(triangles[1]);
    Soup soup = soup_of(tetra_positions(), triangles);
    const auto removed = remove_duplicate_triangles(soup);
    EXPECT_EQ(removed.copies, 1u);
    EXPECT_EQ(removed.folds, 0u);
    EXPECT_EQ(removed.other_sides, 0u);
    EXPECT_EQ(soup.triangles.size(), 4u);
  }
  {  // a flap folded flat onto itself, on a one-sided surface: both faces go
    std::vector<Vec3d> positions = tetra_positions();
    positions.push_back(Vec3d(2, 0, 0));
    std::vector<Triangle3> triangles = tetra_triangles();
    triangles.push_back({0, 1, 4});
    triangles.push_back({1, 0, 4});
    Soup soup = soup_of(positions, triangles);
    const auto removed = remove_duplicate_triangles(soup);
    EXPECT_EQ(removed.copies, 0u);
    EXPECT_EQ(removed.folds, 1u);
    EXPECT_EQ(soup.triangles.size(), 4u);
    EXPECT_EQ(soup.source_face.size(), 4u);
  }
  {  // a two-sided sheet: one face of each pair is kept
    std::vector<Vec3d> positions{Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(0, 1, 0)};
    Soup soup = soup_of(positions, {{0, 1, 2}, {0, 2, 3}, {2, 1, 0}, {3, 2, 0}});
    const auto removed = remove_duplicate_triangles(soup);
    EXPECT_EQ(removed.other_sides, 2u);
    EXPECT_EQ(removed.folds, 0u);
    EXPECT_EQ(soup.triangles.size(), 2u);
  }
}

TEST(LoadRepairs, AFaceWithARepeatedCornerIsDroppedAndCounted) {
  std::vector<Triangle3> triangles = tetra_triangles();
  triangles.push_back({0, 0, 1});
  Soup soup = soup_of(tetra_positions(), triangles);
  const auto healed = heal_degenerate_triangles(soup, 1e-12);
  EXPECT_EQ(healed.collapsed, 1u);
  EXPECT_EQ(healed.flat, 0u);
  EXPECT_EQ(soup.triangles.size(), 4u);
}

TEST(LoadRepairs, TopologyRepairsAreCountedExactly) {
  {  // a bowtie: two triangles sharing one corner get a vertex each
    Soup soup =
        soup_of({Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(-1, 0, 0), Vec3d(-1, -1, 0)},
                {{0, 1, 2}, {0, 3, 4}});
    Soup refused = soup;
    std::vector<std::string> repairs;
    EXPECT_THROW(check_topology_and_orient(refused, false, "bowtie", repairs),
                 InvalidInputException);
    check_topology_and_orient(soup, true, "bowtie", repairs);
    EXPECT_EQ(soup.positions.size(), 6u);
    EXPECT_TRUE(
        has_line(repairs, "split 1 non-manifold vertex into one vertex per fan (1 copy added)"))
        << ::testing::PrintToString(repairs);
    EXPECT_NE(soup.triangles[0][0], soup.triangles[1][0]);
  }
  {  // one face of a tetrahedron the wrong way round
    std::vector<Triangle3> triangles = tetra_triangles();
    std::swap(triangles[2][1], triangles[2][2]);
    Soup soup = soup_of(tetra_positions(), triangles);
    std::vector<std::string> repairs;
    check_topology_and_orient(soup, true, "tetra", repairs);
    EXPECT_TRUE(has_line(repairs, "reoriented 1 face to agree with their neighbours"))
        << ::testing::PrintToString(repairs);
    EXPECT_EQ(soup.triangles, tetra_triangles());
  }
  {  // a tetrahedron inside out
    std::vector<Triangle3> triangles = tetra_triangles();
    for (Triangle3& t : triangles) std::swap(t[1], t[2]);
    Soup soup = soup_of(tetra_positions(), triangles);
    std::vector<std::string> repairs;
    check_topology_and_orient(soup, true, "tetra", repairs);
    EXPECT_EQ(repairs,
              std::vector<std::string>{"flipped 1 closed component that faced inwards (4 faces)"});
    EXPECT_EQ(soup.triangles, tetra_triangles());
  }
}

}  // namespace
}  // namespace papercraft
