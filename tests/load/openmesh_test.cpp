// Loading every format: good files, and bad ones refused with a message that names the problem.
#include "nodes/load/openmesh.h"

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
#include "support/load_files.h"

namespace papercraft {
namespace {

namespace fs = std::filesystem;
using namespace testing;  // load_files.h

// ---------------------------------------------------------------------------------------------
// Good files

TEST_F(LoadOpenMeshTest, ObjWithTextureCoordinatesAndMaterial) {
  write("materials/wood.mtl", "newmtl wood\nKd 1 1 1\nmap_Kd textures/wood.png\n");
  const fs::path path = write("tetra.obj",
                              "# tetrahedron\nmtllib materials/wood.mtl\n"
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                              "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
                              "usemtl wood\n"
                              "f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\nf 2/2 3/3 4/4\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  EXPECT_TRUE(loaded.has_uvs);
  EXPECT_EQ(loaded.uv_seam_vertices, 0u);
  ASSERT_TRUE(loaded.mesh.has_vertex_texcoords2D());
  EXPECT_FALSE(loaded.mesh.has_halfedge_texcoords2D());
  EXPECT_EQ(loaded.mesh.texcoord2D(Mesh::VertexHandle(1)), OpenMesh::Vec2d(1, 0));
  EXPECT_EQ(loaded.mesh.texcoord2D(Mesh::VertexHandle(3)), OpenMesh::Vec2d(1, 1));
  EXPECT_EQ(fs::path(loaded.texture_path), dir_ / "materials/textures/wood.png");
  EXPECT_TRUE(loaded.repairs.empty());
  EXPECT_EQ(loaded.input_vertices, 4u);
  EXPECT_EQ(loaded.input_faces, 4u);
  for (auto v : loaded.mesh.vertices()) EXPECT_EQ(input_vertex_of(loaded.mesh, v), v.idx());
}

// Rhino writes a long face over several lines, each but the last ending in a backslash. The
// statement is read whole (OpenMesh's reader takes a copy with the lines joined, in a folder of
// its own with a link to the material library), so the faces, UVs and the material survive;
// a message about a continued statement names the line it starts on.
TEST_F(LoadOpenMeshTest, ObjLinesContinuedByABackslash) {
  write("materials/wood.mtl", "newmtl wood\nKd 1 1 1\nmap_Kd textures/wood.png\n");
  const fs::path path = write("continued.obj",
                              "mtllib materials/wood.mtl\n"
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                              "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
                              "usemtl wood\n"
                              "f 1/1 3/3 \\\n  2/2\nf 1/1 \\\n2/2 \\\n4/4\nf 1/1 4/4 3/3\n"
                              "f 2/2 3/3 4/4\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  EXPECT_TRUE(loaded.has_uvs);
  EXPECT_EQ(loaded.mesh.texcoord2D(Mesh::VertexHandle(3)), OpenMesh::Vec2d(1, 1));
  EXPECT_EQ(fs::path(loaded.texture_path), dir_ / "materials/textures/wood.png");
  EXPECT_EQ(loaded.input_faces, 4u);
  EXPECT_TRUE(loaded.repairs.empty()) << ::testing::PrintToString(loaded.repairs);
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    EXPECT_EQ(entry.path().filename().string().find("papercraft-clean-" +
                                                    std::to_string(::getpid()) + "-"),
              std::string::npos)
        << entry.path();
  expect_error<InvalidInputException>(
      write("continued_bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n2 x\n"),
      {"continued_bad.obj", "line 4", "bad vertex reference 'x'"});
}

// A CAD polygon with a corner in the middle of a side (where a neighbour's corner meets it): a
// fan from the first corner would make a triangle of no area along that side, which the repair
// would then have to heal or refuse. It is ear-clipped instead, into triangles of area.

TEST_F(LoadOpenMeshTest, ObjUvSeamKeepsVerticesAndStoresCornerUvs) {
  // Vertex 1 (OBJ 1) has a different UV in the last face that touches it.
  const fs::path path = write("seam.obj",
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                              "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
                              "f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/5 4/4 3/3\nf 2/2 3/3 4/4\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  EXPECT_TRUE(loaded.has_uvs);
  EXPECT_EQ(loaded.uv_seam_vertices, 1u);
  ASSERT_TRUE(loaded.mesh.has_halfedge_texcoords2D());
  int seam_corners = 0;
  for (auto h : loaded.mesh.halfedges()) {
    if (!h.is_boundary() && h.to().idx() == 0 &&
        loaded.mesh.texcoord2D(h) == OpenMesh::Vec2d(0.5, 0.5)) {
      ++seam_corners;
    }
  }
  EXPECT_EQ(seam_corners, 1);
}

TEST_F(LoadOpenMeshTest, OffAscii) {
  const LoadedMesh loaded = load_mesh(write("tetra.off", tetra_off()));
  expect_closed_tetrahedron(loaded);
  EXPECT_TRUE(loaded.repairs.empty());
  EXPECT_FALSE(loaded.has_uvs);
}

// A plain OFF is read by the pre-scan, so its header may be looser than OpenMesh's reader
// allows: blanks before the keyword, the counts on the keyword's line, even glued to it (trimesh's
// whitespace.off starts "\t   OFF8 6 12 # or nah"). With a prefix (OpenMesh reads those) or
// BINARY the header stays strict.
TEST_F(LoadOpenMeshTest, OffHeaderWithBlanksAndCountsOnItsLine) {
  const std::string off = tetra_off();
  const std::string body = off.substr(off.find("0\n") + 2);  // after "OFF\n4 4 0\n"
  for (const char* header : {"  OFF 4 4 0\n", "\t OFF4 4 0 # a comment\n", "OFF\t4 4 0\n"}) {
    SCOPED_TRACE(header);
    const LoadedMesh loaded = load_mesh(write("loose.off", std::string(header).append(body)));
    expect_closed_tetrahedron(loaded);
  }
  expect_error<InvalidInputException>(
      write("loose_c.off", std::string(" COFF\n4 4 0\n").append(body)), {"expected 'OFF'"});
  expect_error<InvalidInputException>(
      write("loose_counts.off", std::string("OFF 4 4\n").append(body)), {"expected 3 counts"});
  expect_error<InvalidInputException>(write("loose_binary.off", " OFF BINARY\n"),
                                      {"exactly as 'OFF BINARY'"});
}

// OFF is free-format: libigl's inspired_mesh_quads_*.off write a face one value a line
// ("4 887\n46\n888\n0"). The pre-scan reads a face's indices on over the next lines.
TEST_F(LoadOpenMeshTest, OffFaceIndicesOverSeveralLines) {
  std::string off = tetra_off();
  off.replace(off.find("3 0 1 3\n"), 8, "3 0 \n1\n 3\n");
  expect_closed_tetrahedron(load_mesh(write("lines.off", off)));
  // A face whose indices run out at the end of the file is still refused.
  std::string cut = tetra_off();
  cut.resize(cut.rfind("3 1 2 3\n"));
  cut += "3 1 2\n";
  expect_error<InvalidInputException>(write("short.off", cut), {"face 3", "declares 3"});
  // Not where OpenMesh's reader reads the file (a prefix such as ST): it takes a face from its
  // line, and read on, a fuzzed file's face count from the next line asked for four billion
  // corners. Such a face is refused, naming its line.
  std::string st = "N" + tetra_off();
  std::size_t at = st.find('\n', st.find('\n') + 1);  // the end of the counts line
  for (int vertex = 0; vertex < 4; ++vertex) {        // a normal after each position
    at = st.find('\n', at + 1);
    st.insert(at, " 0 0 1");
    at += 6;
  }
  ASSERT_EQ(load_mesh(write("normals.off", st)).mesh.n_faces(), 4u);
  st.replace(st.find("3 0 1 3\n"), 8, "3 0 \n1 3\n");
  expect_error<InvalidInputException>(
      write("normals_lines.off", st),
      {"normals_lines.off", "face 1", "declares 3 vertices but lists 1"});
}

TEST_F(LoadOpenMeshTest, OffBinary) {
  std::string data = "OFF BINARY\n";
  put_u32(data, 4);
  put_u32(data, 4);
  put_u32(data, 0);
  for (const auto& p : kTetraPoints) {
    for (double c : p) put_f32(data, static_cast<float>(c));
  }
  for (const auto& f : kTetraFaces) {
    put_u32(data, 3);
    for (int i : f) put_u32(data, static_cast<std::uint32_t>(i));
  }
  expect_closed_tetrahedron(load_mesh(write("binary.off", data)));
  expect_error<InvalidInputException>(write("cut_binary.off", data.substr(0, data.size() - 4)),
                                      {"truncated"});
}

TEST_F(LoadOpenMeshTest, ExtensionIsCaseInsensitive) {
  expect_closed_tetrahedron(load_mesh(write("TETRA.OFF", tetra_off())));
}

TEST_F(LoadOpenMeshTest, PlyAsciiWithVertexUvsAndTexture) {
  const fs::path path = write("tetra.ply",
                              "ply\nformat ascii 1.0\ncomment TextureFile skin.png\n"
                              "element vertex 4\nproperty float x\nproperty float y\n"
                              "property float z\nproperty float u\nproperty float v\n"
                              "element face 4\nproperty list uchar int vertex_indices\n"
                              "end_header\n"
                              "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const LoadedMesh loaded = load_mesh(path);
  expect_closed_tetrahedron(loaded);
  EXPECT_TRUE(loaded.has_uvs);
  EXPECT_EQ(loaded.uv_seam_vertices, 0u);
  EXPECT_EQ(loaded.mesh.texcoord2D(Mesh::VertexHandle(2)), OpenMesh::Vec2d(0, 1));
  EXPECT_EQ(fs::path(loaded.texture_path), dir_ / "skin.png");
}

// MeshLab writes a textured PLY with a texture coordinate list per face (u v per corner),
// after the vertex indices, and colours with alpha; OpenMesh's reader cannot read that list, so
// the pre-scan reads such a file itself, ascii or binary. Every corner keeps its own UV (here
// all differ, so every vertex is on a UV seam), and the TextureFile comment names the texture.
TEST_F(LoadOpenMeshTest, PlyWithATextureCoordinateListPerFace) {
  const auto uv = [](int face, int corner) {
    return OpenMesh::Vec2d(0.125 * face + 0.03125 * corner, 0.5 + 0.0625 * corner);
  };
  const std::string header =
      "comment TextureFile skin uv.png\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      "property uchar alpha\nelement face 4\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nproperty uchar alpha\nend_header\n";
  std::string ascii = "ply\nformat ascii 1.0\n" + header;
  std::string binary = "ply\nformat binary_little_endian 1.0\n" + header;
  for (const auto& p : kTetraPoints) {
    for (double c : p) {
      ascii += std::to_string(c) + " ";
      put_f32(binary, static_cast<float>(c));
    }
    ascii += "51 102 153 255\n";
    for (int c : {51, 102, 153, 255}) put_u8(binary, static_cast<std::uint8_t>(c));
  }
  for (int f = 0; f < 4; ++f) {
    ascii += "3";
    put_u8(binary, 3);
    for (int k = 0; k < 3; ++k) {
      ascii += " " + std::to_string(kTetraFaces[f][k]);
      put_u32(binary, static_cast<std::uint32_t>(kTetraFaces[f][k]));
    }
    ascii += " 6";
    put_u8(binary, 6);
    for (int k = 0; k < 3; ++k) {
      ascii += " " + std::to_string(uv(f, k)[0]) + " " + std::to_string(uv(f, k)[1]);
      put_f32(binary, static_cast<float>(uv(f, k)[0]));
      put_f32(binary, static_cast<float>(uv(f, k)[1]));
    }
    ascii += " 255 255 255 255\n";
    for (int k = 0; k < 4; ++k) put_u8(binary, 255);
  }
  for (const auto& [name, data] :
       {std::pair{"meshlab_ascii.ply", ascii}, std::pair{"meshlab_binary.ply", binary}}) {
    SCOPED_TRACE(name);
    const LoadedMesh loaded = load_mesh(write(name, data));
    expect_closed_tetrahedron(loaded);
    EXPECT_TRUE(loaded.repairs.empty());
    EXPECT_TRUE(loaded.has_uvs);
    EXPECT_EQ(loaded.uv_seam_vertices, 4u);
    EXPECT_EQ(fs::path(loaded.texture_path), dir_ / "skin uv.png");
    ASSERT_TRUE(loaded.mesh.has_halfedge_texcoords2D());
    for (auto f : loaded.mesh.faces()) {
      for (auto h : f.halfedges()) {
        const int k = static_cast<int>(
            std::find(kTetraFaces[f.idx()], kTetraFaces[f.idx()] + 3, h.to().idx()) -
            kTetraFaces[f.idx()]);
        ASSERT_LT(k, 3);
        EXPECT_EQ(loaded.mesh.texcoord2D(h), uv(f.idx(), k)) << "face " << f.idx();
      }
    }
  }
  // A face whose list is not two values per corner has no UVs, so none are kept.
  std::string short_list = ascii;
  const std::size_t last_face = short_list.rfind("3 1 2 3 6 ");
  short_list.replace(last_face, short_list.find(" 255", last_face) - last_face,
                     "3 1 2 3 4 0 0 1 0");
  const LoadedMesh partial = load_mesh(write("meshlab_short.ply", short_list));
  expect_closed_tetrahedron(partial);
  EXPECT_FALSE(partial.has_uvs);
  ASSERT_EQ(partial.repairs.size(), 1u);
  EXPECT_EQ(partial.repairs[0], "ignored texture coordinates: only 3 of 4 faces have them");
}

TEST_F(LoadOpenMeshTest, PlyBinaryLittleAndBigEndian) {
  expect_closed_tetrahedron(load_mesh(write("little.ply", tetra_ply_binary(false))));
  expect_closed_tetrahedron(load_mesh(write("big.ply", tetra_ply_binary(true))));
}

// Found by fuzzing: OpenMesh's reader never returns on a version it cannot read as a number.
TEST_F(LoadOpenMeshTest, PlyVersionOtherThanOneIsRefused) {
  std::string data = tetra_ply_binary(false);
  data.replace(data.find("1.0"), 3, "\x11.0");
  expect_error<InvalidInputException>(write("version.ply", data),
                                      {"version.ply", "line 2", "unsupported PLY version"});
  std::string two = tetra_ply_binary(false);
  two.replace(two.find("1.0"), 3, "2.0");
  expect_error<InvalidInputException>(write("two.ply", two), {"unsupported PLY version '2.0'"});
}

TEST_F(LoadOpenMeshTest, StlAsciiIsWelded) {
  std::string text = "solid tetra\n";
  for (const auto& f : kTetraFaces) text += stl_facet({f[0], f[1], f[2]});
  text += "endsolid tetra\n";
  const LoadedMesh loaded = load_mesh(write("tetra.stl", text));
  expect_closed_tetrahedron(loaded);
  EXPECT_EQ(loaded.input_vertices, 12u);
  EXPECT_EQ(loaded.input_faces, 4u);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_NE(loaded.repairs[0].find("merged 8 exactly duplicate vertices"), std::string::npos);
}

TEST_F(LoadOpenMeshTest, StlBinaryIsWelded) {
  const LoadedMesh loaded = load_mesh(write("tetra.stl", tetra_stl_binary("binary tetrahedron")));
  expect_closed_tetrahedron(loaded);
  EXPECT_EQ(loaded.input_vertices, 12u);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_NE(loaded.repairs[0].find("merged 8 exactly duplicate vertices"), std::string::npos);
}

TEST_F(LoadOpenMeshTest, StlBinaryWhoseHeaderStartsWithSolid) {
  expect_closed_tetrahedron(
      load_mesh(write("solid.stl", tetra_stl_binary("solid but actually binary"))));
}

TEST_F(LoadOpenMeshTest, OpenSurfaceKeepsItsBoundary) {
  const fs::path path =
      write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  const LoadedMesh loaded = load_mesh(path);
  EXPECT_EQ(loaded.mesh.n_faces(), 3u);
  EXPECT_EQ(boundary_loops(loaded.mesh).size(), 1u);
  EXPECT_TRUE(loaded.repairs.empty());
}

TEST_F(LoadOpenMeshTest, ConcurrentLoadsAreIndependent) {
  std::vector<fs::path> paths;
  for (int i = 0; i < 4; ++i) {
    paths.push_back(write("c" + std::to_string(i) + ".ply", tetra_ply_binary(i % 2 == 1)));
    paths.push_back(write("c" + std::to_string(i) + ".off", tetra_off()));
  }
  std::vector<std::size_t> faces(paths.size(), 0);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    threads.emplace_back([&, i] {
      for (int repeat = 0; repeat < 20; ++repeat) faces[i] += load_mesh(paths[i]).mesh.n_faces();
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (std::size_t count : faces) EXPECT_EQ(count, 80u);
}

TEST_F(LoadOpenMeshTest, MissingFile) {
  expect_error<IOException>(dir_ / "missing.obj", {"missing.obj", "no such file"});
}

TEST_F(LoadOpenMeshTest, UnknownExtension) {
  expect_error<InvalidInputException>(write("mesh.xyz", tetra_off()),
                                      {"unknown extension", ".xyz"});
}

TEST_F(LoadOpenMeshTest, EmptyFile) {
  expect_error<InvalidInputException>(write("empty.obj", ""), {"empty"});
  expect_error<InvalidInputException>(write("empty.stl", ""), {"empty"});
}

TEST_F(LoadOpenMeshTest, ZeroFaces) {
  expect_error<InvalidInputException>(write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
                                      {"no faces", "3 vertices"});
  expect_error<InvalidInputException>(write("points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
                                      {"no faces"});
  expect_error<InvalidInputException>(
      write("points.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 0 0\n"),
      {"no faces"});
}

TEST_F(LoadOpenMeshTest, TruncatedOff) {
  // The header promises 4 faces, there are 2: OpenMesh alone would repeat the last one.
  const std::string full = tetra_off();
  const std::string truncated = full.substr(0, full.rfind("3 0 3 2"));
  expect_error<InvalidInputException>(write("truncated.off", truncated),
                                      {"truncated", "4 faces", "2 face lines"});
}

TEST_F(LoadOpenMeshTest, OffWithMoreDataThanDeclared) {
  expect_error<InvalidInputException>(write("extra.off", tetra_off("", "3 1 2 0\n")),
                                      {"more data follows", "line 11"});
}

TEST_F(LoadOpenMeshTest, TruncatedBinaryPly) {
  const std::string full = tetra_ply_binary(false);
  expect_error<InvalidInputException>(write("cut.ply", full.substr(0, full.size() - 10)),
                                      {"truncated", "4 faces"});
  // Exactly enough bytes for the shortest faces, but the last face claims 5 vertices.
  std::string longer = full;
  longer[longer.size() - 13] = 5;
  expect_error<InvalidInputException>(write("long_face.ply", longer),
                                      {"truncated", "face 3 (of 4)"});
}

TEST_F(LoadOpenMeshTest, TruncatedAsciiPly) {
  expect_error<InvalidInputException>(
      write("cut_ascii.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
            "end_header\n0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n0.0 0.0 1.0\n"
            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2\n"),
      {"truncated", "face 3"});
}

TEST_F(LoadOpenMeshTest, HugePlyHeaderFailsFast) {
  const fs::path path =
      write("huge.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
            "property float x\nproperty float y\nproperty float z\nelement face 1\n"
            "property list uchar int vertex_indices\nend_header\n" +
                std::string(100, '\0'));
  const auto start = std::chrono::steady_clock::now();
  expect_error<InvalidInputException>(path, {"truncated", "4000000000 vertices"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.2);

  const fs::path ascii = write("huge_ascii.off", "OFF\n4000000000 4000000000 0\n0 0 0\n");
  expect_error<InvalidInputException>(ascii, {"truncated", "4000000000 faces"});
}

TEST_F(LoadOpenMeshTest, HugeBinaryStlCountIsNotBinary) {
  std::string data = tetra_stl_binary("binary");
  data[80] = data[81] = data[82] = data[83] = '\xff';
  expect_error<InvalidInputException>(write("huge.stl", data),
                                      {"not an STL", "4294967295 triangles"});
}

TEST_F(LoadOpenMeshTest, FaceLimit) {
  LoadOptions small;
  small.max_faces = 3;
  expect_error<InvalidInputException>(write("limit.off", tetra_off()), {"max_faces", "4 faces"},
                                      small);
}

TEST_F(LoadOpenMeshTest, NaNCoordinates) {
  expect_error<InvalidInputException>(
      write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n"),
      {"non-finite", "'nan'", "line 2", "vertex 1"});
  std::string ply = tetra_ply_binary(false);
  const std::size_t data = ply.find("end_header\n") + 11;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&ply[data + 12], &nan, 4);  // vertex 1, x
  expect_error<InvalidInputException>(write("nan.ply", ply), {"non-finite", "first vertex 1"});
  std::string stl = tetra_stl_binary("binary");
  std::memcpy(&stl[84 + 12], &nan, 4);
  expect_error<InvalidInputException>(write("nan.stl", stl), {"non-finite", "triangle 0"});
}

TEST_F(LoadOpenMeshTest, InfiniteCoordinates) {
  expect_error<InvalidInputException>(write("inf.off",
                                            "OFF\n4 4 0\n0 0 0\ninf 0 0\n0 1 0\n0 0 1\n"
                                            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
                                      {"non-finite", "'inf'", "line 4"});
  expect_error<InvalidInputException>(write("big.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"),
                                      {"non-finite", "'1e39'"});
  std::string ply = tetra_ply_binary(false);
  const std::size_t data = ply.find("end_header\n") + 11;
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(&ply[data + 8], &inf, 4);  // vertex 0, z
  expect_error<InvalidInputException>(write("inf.ply", ply), {"non-finite", "first vertex 0"});
}

TEST_F(LoadOpenMeshTest, OutOfRangeIndex) {
  expect_error<InvalidInputException>(write("range.off",
                                            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                            "3 0 2 1\n3 0 1 3\n3 0 3 7\n3 1 2 3\n"),
                                      {"out-of-range", "face 2", "vertex 7", "4 vertices"});
  expect_error<InvalidInputException>(write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                                      {"out-of-range", "vertex 8"});
}

TEST_F(LoadOpenMeshTest, OffCommentsAndBlankLines) {
  // CGAL writes a block of comments before the keyword; others comment sections and values.
  std::string text = tetra_off();
  text.replace(text.find("OFF\n"), 4, "OFF # keyword\n");
  text.insert(text.find("4 4 0\n") + 6, "\n# vertices\n");
  text.replace(text.find("3 0 2 1\n"), 8, "# faces\n\n3 0 2 1   # first face\n");
  const LoadedMesh loaded =
      load_mesh(write("commented.off", "# Output of a CGAL tool\n#CBP\n\n# ENDCBP\n\n" + text));
  expect_closed_tetrahedron(loaded);
  EXPECT_TRUE(loaded.repairs.empty());
  // An error after comments still names the right line.
  std::string broken = "# header\n" + tetra_off();
  broken.replace(broken.find("3 0 2 1\n"), 8, "3 0 2 x\n");
  expect_error<InvalidInputException>(write("broken.off", broken), {"line 8", "'x'"});
}

TEST_F(LoadOpenMeshTest, LayoutsOpenMeshWouldMisread) {
  // A comment right before end_header shifts OpenMesh's binary data by one byte.
  expect_error<InvalidInputException>(
      write("comment.ply", tetra_ply_binary(false, "comment made by hand\n")),
      {"misplace the binary data"});
  // Face colors without a COFF header would be read as the next face's vertex count; they are
  // dropped before OpenMesh reads the faces.
  std::string colored = tetra_off();
  colored.replace(colored.find("3 0 2 1\n"), 8, "3 0 2 1 255 0 0\n");
  const LoadedMesh loaded = load_mesh(write("colors.off", colored));
  expect_closed_tetrahedron(loaded);
  ASSERT_EQ(loaded.repairs.size(), 1u);
  EXPECT_EQ(loaded.repairs[0],
            "ignored the values after the vertex indices of 1 face (face colors need a COFF "
            "header)");
  // A list OpenMesh cannot skip (a face's texcoord list the pre-scan reads itself).
  expect_error<InvalidInputException>(
      write("quality_list.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "property list uchar float quality\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
            "3 0 1 2 1 0\n"),
      {"line 9", "quality", "not supported"});
}

TEST_F(LoadOpenMeshTest, StlTruncated) {
  std::string ascii =
      "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
      "   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n";
  expect_error<InvalidInputException>(write("no_end.stl", ascii), {"truncated", "endsolid"});
  expect_error<InvalidInputException>(write("mid_facet.stl", ascii.substr(0, 57)), {"truncated"});
  const std::string binary = tetra_stl_binary("binary");
  expect_error<InvalidInputException>(write("cut.stl", binary.substr(0, binary.size() - 7)),
                                      {"not an STL", "4 triangles", "284 bytes"});
}

}  // namespace
}  // namespace papercraft
