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

namespace papercraft {
namespace {

namespace fs = std::filesystem;

// Tetrahedron with outward (counter-clockwise seen from outside) faces.
const double kTetraPoints[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kTetraFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

void put_u8(std::string& out, std::uint8_t value) {
  out.push_back(static_cast<char>(value));
}
void put_u32(std::string& out, std::uint32_t value, bool big_endian = false) {
  for (int i = 0; i < 4; ++i) {
    const int shift = big_endian ? 8 * (3 - i) : 8 * i;
    out.push_back(static_cast<char>((value >> shift) & 0xffu));
  }
}
void put_f32(std::string& out, float value, bool big_endian = false) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  put_u32(out, bits, big_endian);
}

std::string tetra_off(const std::string& extra_vertices = "", const std::string& extra_faces = "",
                      int added_vertices = 0, int added_faces = 0) {
  std::string text =
      "OFF\n" + std::to_string(4 + added_vertices) + " " + std::to_string(4 + added_faces) + " 0\n";
  for (const auto& p : kTetraPoints) {
    text += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  }
  text += extra_vertices;
  for (const auto& f : kTetraFaces) {
    text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
            "\n";
  }
  return text + extra_faces;
}

std::string tetra_ply_binary(bool big_endian, const std::string& header_extra = "") {
  std::string data = std::string("ply\nformat ") +
                     (big_endian ? "binary_big_endian" : "binary_little_endian") +
                     " 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 4\nproperty list uchar int vertex_indices\n" +
                     header_extra + "end_header\n";
  for (const auto& p : kTetraPoints) {
    for (double c : p) put_f32(data, static_cast<float>(c), big_endian);
  }
  for (const auto& f : kTetraFaces) {
    put_u8(data, 3);
    for (int i : f) put_u32(data, static_cast<std::uint32_t>(i), big_endian);
  }
  return data;
}

std::string tetra_stl_binary(const std::string& header) {
  std::string data = header;
  data.resize(80, ' ');
  put_u32(data, 4);
  for (const auto& f : kTetraFaces) {
    for (int i = 0; i < 3; ++i) put_f32(data, 0.0f);
    for (int corner : f) {
      for (double c : kTetraPoints[corner]) put_f32(data, static_cast<float>(c));
    }
    data += std::string(2, '\0');
  }
  return data;
}

// One ascii STL facet on the tetrahedron's corners `corners`.
std::string stl_facet(std::initializer_list<int> corners) {
  std::string text = "  facet normal 0 0 0\n    outer loop\n";
  for (int corner : corners) {
    const auto& p = kTetraPoints[corner];
    text += "      vertex " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " +
            std::to_string(p[2]) + "\n";
  }
  return text + "    endloop\n  endfacet\n";
}

// The OBJ vertex lines of `points`, one "v x y z" each.
template <std::size_t N>
std::string obj_vertices(const double (&points)[N][3]) {
  std::string obj;
  for (const auto& q : points)
    obj += "v " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) +
           "\n";
  return obj;
}

int input_vertex_of(const Mesh& mesh, Mesh::VertexHandle v) {
  OpenMesh::VPropHandleT<int> handle;
  if (!mesh.get_property_handle(handle, "v:input_vertex")) {
    ADD_FAILURE() << "no v:input_vertex property";
    return -1;
  }
  return mesh.property(handle, v);
}

class LoadOpenMeshTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() /
           ("papercraft_load_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  fs::path write(const std::string& name, const std::string& content) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
  }

  // Loads `path`, expecting exception E whose message starts with the path and contains every
  // key; returns the message.
  template <class E>
  std::string expect_error(const fs::path& path, std::initializer_list<const char*> keys,
                           const LoadOptions& options = {}) {
    std::string message;
    try {
      load_mesh(path, options);
      ADD_FAILURE() << "no exception for " << path;
      return {};
    } catch (const E& error) {
      message = error.what();
    } catch (const std::exception& error) {
      ADD_FAILURE() << "wrong exception type for " << path << ": " << error.what();
      return {};
    }
    EXPECT_EQ(message.rfind(path.string(), 0), 0u) << message;
    for (const char* key : keys) {
      EXPECT_NE(message.find(key), std::string::npos) << "'" << key << "' not in: " << message;
    }
    return message;
  }

  // Two closed tetrahedra apart: 8 vertices, 8 faces, two components, no boundary.
  static void expect_two_closed_tetrahedra(const LoadedMesh& loaded) {
    EXPECT_EQ(loaded.mesh.n_vertices(), 8u);
    EXPECT_EQ(loaded.mesh.n_faces(), 8u);
    EXPECT_EQ(connected_components(loaded.mesh), 2);
    EXPECT_TRUE(boundary_loops(loaded.mesh).empty());
    EXPECT_EQ(euler_characteristic(loaded.mesh), 4);
  }
  static void expect_closed_tetrahedron(const LoadedMesh& loaded) {
    EXPECT_EQ(loaded.mesh.n_vertices(), 4u);
    EXPECT_EQ(loaded.mesh.n_faces(), 4u);
    EXPECT_EQ(loaded.mesh.n_edges(), 6u);
    EXPECT_TRUE(boundary_loops(loaded.mesh).empty());
    EXPECT_EQ(euler_characteristic(loaded.mesh), 2);
    // Outward orientation: positive signed volume 1/6.
    double volume = 0.0;
    for (auto f : loaded.mesh.faces()) {
      std::vector<OpenMesh::Vec3d> p;
      for (auto v : f.vertices()) p.push_back(loaded.mesh.point(v));
      volume += OpenMesh::dot(p[0], OpenMesh::cross(p[1], p[2])) / 6.0;
    }
    EXPECT_NEAR(volume, 1.0 / 6.0, 1e-12);
  }

  fs::path dir_;
};

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
  EXPECT_TRUE(loaded.repairs.empty()) << testing::PrintToString(loaded.repairs);
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
  })) << testing::PrintToString(loaded.repairs);
}

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
  })) << testing::PrintToString(repairs);
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
  })) << testing::PrintToString(repairs);
  EXPECT_TRUE(std::any_of(repairs.begin(), repairs.end(), [](const std::string& r) {
    return r.find("reoriented 2 faces") != std::string::npos;
  })) << testing::PrintToString(repairs);
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
  const fs::path path =
      write("bowtie.off",
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
  EXPECT_NE(std::find(loaded.repairs.begin(), loaded.repairs.end(), "ear-clipped 1 non-convex polygon"),
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
