#pragma once
// The loading tests' fixture and files: a temporary folder per test, files written into it,
// errors expected with their keys, and small meshes (a tetrahedron) in every format.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/mesh.h"
#include "nodes/load/openmesh.h"

namespace papercraft::testing {

namespace fs = std::filesystem;

// Tetrahedron with outward (counter-clockwise seen from outside) faces.
inline const double kTetraPoints[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
inline const int kTetraFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

inline void put_u8(std::string& out, std::uint8_t value) {
  out.push_back(static_cast<char>(value));
}
inline void put_u32(std::string& out, std::uint32_t value, bool big_endian = false) {
  for (int i = 0; i < 4; ++i) {
    const int shift = big_endian ? 8 * (3 - i) : 8 * i;
    out.push_back(static_cast<char>((value >> shift) & 0xffu));
  }
}
inline void put_f32(std::string& out, float value, bool big_endian = false) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  put_u32(out, bits, big_endian);
}

inline std::string tetra_off(const std::string& extra_vertices = "",
                             const std::string& extra_faces = "", int added_vertices = 0,
                             int added_faces = 0) {
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

inline std::string tetra_ply_binary(bool big_endian, const std::string& header_extra = "") {
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

inline std::string tetra_stl_binary(const std::string& header) {
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
inline std::string stl_facet(std::initializer_list<int> corners) {
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
inline std::string obj_vertices(const double (&points)[N][3]) {
  std::string obj;
  for (const auto& q : points)
    obj += "v " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) +
           "\n";
  return obj;
}

inline int input_vertex_of(const Mesh& mesh, Mesh::VertexHandle v) {
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

}  // namespace papercraft::testing
