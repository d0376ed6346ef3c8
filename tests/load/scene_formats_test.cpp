// glTF/GLB and 3MF input: the same triangles as the OBJ of the same mesh, with UVs, colours and
// transforms; broken files are clear errors naming the file.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "core/errors.h"
#include "nodes/load/openmesh.h"
#include "support/scene_writers.h"
#include "support/temp_dir.h"

namespace papercraft {
namespace {

using testing::SceneMesh;

// The atlas box with a colour per side, for the 3MF.
SceneMesh textured_box() {
  SceneMesh mesh = testing::atlas_box();
  for (const auto& t : mesh.triangles) {
    const int side = testing::box_side((mesh.positions[t[1]] - mesh.positions[t[0]])
                                           .cross(mesh.positions[t[2]] - mesh.positions[t[0]]));
    mesh.triangle_colour.push_back({static_cast<unsigned char>(40 * side), 200, 100});
  }
  return mesh;
}

std::vector<std::uint8_t> tiny_png() {
  // A valid 1 x 1 PNG (red).
  return {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
          0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
          0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x08,
          0xd7, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0x18, 0xdd, 0x8d,
          0xb0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
}

// Each face as its corner positions (and UVs), turned to start at its least corner: the
// same set for two loads means the same triangles, facing the same way.
using Corner = std::array<double, 5>;
std::set<std::array<Corner, 3>> faces_of(const LoadedMesh& loaded) {
  std::set<std::array<Corner, 3>> faces;
  const SurfaceAppearance& a = loaded.appearance;
  for (auto f : loaded.mesh.faces()) {
    std::array<Corner, 3> face;
    int k = 0;
    for (auto v : f.vertices()) {
      const auto p = loaded.mesh.point(v);
      Vec2 uv(0, 0);
      if (!a.face_uv.empty()) {
        for (int c = 0; c < 3; ++c)
          if (a.face_vertices[f.idx()][c] == v.idx()) uv = a.face_uv[f.idx()][c];
      }
      // Rounded, as glTF and 3MF store single precision (and glTF turns v down).
      auto r = [](double x) { return std::round(x * 1e5) / 1e5; };
      face[k++] = {r(p[0]), r(p[1]), r(p[2]), r(uv.x()), r(uv.y())};
    }
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    faces.insert(face);
  }
  return faces;
}

TEST(SceneFormats, GlbGltfAnd3mfLoadToTheSameTrianglesAsTheObj) {
  const auto dir = testing::fresh_temp_dir("scene_formats");
  const SceneMesh box = textured_box();
  testing::write_obj(dir / "box.obj", box);
  testing::GltfOptions glb;
  glb.png = tiny_png();
  ASSERT_TRUE(testing::write_gltf(dir / "box.glb", box, glb));
  testing::GltfOptions gltf = glb;
  gltf.binary = false;
  ASSERT_TRUE(testing::write_gltf(dir / "box.gltf", box, gltf));
  ASSERT_TRUE(std::filesystem::exists(dir / "box.bin"));
  ASSERT_TRUE(testing::write_3mf(dir / "box.3mf", box));

  const LoadedMesh obj = load_mesh(dir / "box.obj");
  const auto expected = faces_of(obj);
  const std::size_t faces = box.triangles.size(), vertices = box.positions.size();
  ASSERT_EQ(expected.size(), faces);
  for (const char* name : {"box.glb", "box.gltf"}) {
    SCOPED_TRACE(name);
    const LoadedMesh loaded = load_mesh(dir / name);
    EXPECT_EQ(loaded.mesh.n_vertices(), vertices);  // split at UV seams in the file, welded again
    EXPECT_TRUE(loaded.has_uvs);
    EXPECT_EQ(faces_of(loaded), expected);
    ASSERT_EQ(loaded.appearance.materials.size(), 1u);
    EXPECT_TRUE(loaded.appearance.has_texture());
  }
  // The GLB holds the image; the glTF names the file beside it.
  EXPECT_TRUE(load_mesh(dir / "box.glb").appearance.materials[0].texture_bytes != nullptr);
  EXPECT_EQ(load_mesh(dir / "box.gltf").appearance.materials[0].texture,
            (dir / "texture.png").string());

  const LoadedMesh package = load_mesh(dir / "box.3mf");
  EXPECT_EQ(package.mesh.n_vertices(), vertices);
  auto without_uv = [](std::set<std::array<Corner, 3>> faces) {
    std::set<std::array<Corner, 3>> out;
    for (auto face : faces) {
      for (Corner& c : face) c[3] = c[4] = 0;
      std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
      out.insert(face);
    }
    return out;
  };
  EXPECT_EQ(without_uv(faces_of(package)), without_uv(expected));
  // Per-triangle colours become corner colours (sRGB bytes / 255).
  ASSERT_EQ(package.appearance.face_colour.size(), faces);
  std::set<int> reds;
  for (const auto& corners : package.appearance.face_colour) {
    EXPECT_NEAR(corners[0].y(), 200 / 255.0, 1e-9);
    reds.insert(static_cast<int>(std::lround(corners[0].x() * 255)));
  }
  EXPECT_EQ(reds, (std::set<int>{0, 40, 80, 120, 160, 200}));
}

TEST(SceneFormats, NodeTransformIsApplied) {
  const auto dir = testing::fresh_temp_dir("scene_transform");
  SceneMesh box = textured_box();
  box.corner_uv.clear();
  testing::GltfOptions options;
  options.scale = Vec3(2, 2, 2);
  const double s = std::sqrt(0.5);
  options.rotation = std::array<double, 4>{0, 0, s, s};  // 90 degrees about z
  options.translation = Vec3(10, 0, 0);
  ASSERT_TRUE(testing::write_gltf(dir / "moved.glb", box, options));
  const LoadedMesh loaded = load_mesh(dir / "moved.glb");
  ASSERT_EQ(loaded.mesh.n_faces(), box.triangles.size());
  // (x, y, z) -> (10 - 2y, 2x, 2z): the box spans x 8..12, y -2..2, z -2..2.
  OpenMesh::Vec3d low(1e9, 1e9, 1e9), high(-1e9, -1e9, -1e9);
  for (auto v : loaded.mesh.vertices()) {
    low.minimize(loaded.mesh.point(v));
    high.maximize(loaded.mesh.point(v));
  }
  EXPECT_NEAR(low[0], 8, 1e-6);
  EXPECT_NEAR(high[0], 12, 1e-6);
  EXPECT_NEAR(low[1], -2, 1e-6);
  EXPECT_NEAR(high[2], 2, 1e-6);
  // Still facing outwards: the signed volume is that of a 4 x 4 x 4 box.
  double volume = 0;
  for (auto f : loaded.mesh.faces()) {
    std::array<OpenMesh::Vec3d, 3> p;
    int k = 0;
    for (auto v : f.vertices()) p[k++] = loaded.mesh.point(v) - OpenMesh::Vec3d(10, 0, 0);
    volume += OpenMesh::dot(p[0], OpenMesh::cross(p[1], p[2])) / 6;
  }
  EXPECT_NEAR(volume, 64, 1e-6);

  // A mirroring scale turns the faces back: still outward.
  options.scale = Vec3(-1, 1, 1);
  options.rotation.reset();
  options.translation.reset();
  ASSERT_TRUE(testing::write_gltf(dir / "mirrored.glb", box, options));
  const LoadedMesh mirrored = load_mesh(dir / "mirrored.glb");
  volume = 0;
  for (auto f : mirrored.mesh.faces()) {
    std::array<OpenMesh::Vec3d, 3> p;
    int k = 0;
    for (auto v : f.vertices()) p[k++] = mirrored.mesh.point(v);
    volume += OpenMesh::dot(p[0], OpenMesh::cross(p[1], p[2])) / 6;
  }
  EXPECT_NEAR(volume, 8, 1e-6);
}

TEST(SceneFormats, TriangleStripIsConvertedKeepingTheWinding) {
  const auto dir = testing::fresh_temp_dir("scene_strip");
  SceneMesh quad;
  quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  quad.triangles = {{0, 1, 2}, {2, 1, 3}};
  testing::GltfOptions options;
  options.mode = TINYGLTF_MODE_TRIANGLE_STRIP;
  ASSERT_TRUE(testing::write_gltf(dir / "strip.glb", quad, options));
  const LoadedMesh loaded = load_mesh(dir / "strip.glb");
  ASSERT_EQ(loaded.mesh.n_faces(), 2u);
  for (auto f : loaded.mesh.faces()) EXPECT_GT(loaded.mesh.calc_face_normal(f)[2], 0.99);
}

TEST(SceneFormats, ComponentsOf3mfAreEachPlaced) {
  const auto dir = testing::fresh_temp_dir("scene_components");
  SceneMesh box = textured_box();
  box.triangle_colour.clear();
  ASSERT_TRUE(testing::write_3mf(dir / "two.3mf", box, 2, 5.0));
  const LoadedMesh loaded = load_mesh(dir / "two.3mf");
  EXPECT_EQ(loaded.mesh.n_faces(), 2 * box.triangles.size());
  EXPECT_EQ(loaded.mesh.n_vertices(), 2 * box.positions.size());
  EXPECT_TRUE(loaded.appearance.face_colour.empty());  // no colours given: none invented
}

void expect_refused(const std::filesystem::path& path, const std::string& words) {
  try {
    load_mesh(path);
    ADD_FAILURE() << path << " was accepted";
  } catch (const InvalidInputException& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ":", 0), 0u) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
}

TEST(SceneFormats, BrokenFilesAreClearErrors) {
  const auto dir = testing::fresh_temp_dir("scene_broken");
  const SceneMesh box = textured_box();
  ASSERT_TRUE(testing::write_gltf(dir / "box.glb", box, {}));
  std::string bytes;
  {
    std::ifstream in(dir / "box.glb", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(dir / "truncated.glb", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  expect_refused(dir / "truncated.glb", "glTF");
  std::ofstream(dir / "text.gltf") << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"mesh\": 3}],"
                                      " \"scenes\": [{\"nodes\": [0]}]}";
  expect_refused(dir / "text.gltf", "mesh 3");
  std::ofstream(dir / "empty.gltf") << "{\"asset\": {\"version\": \"2.0\"}}";
  expect_refused(dir / "empty.gltf", "no triangles");
  std::ofstream(dir / "garbage.glb", std::ios::binary) << "glTF\x02\0\0\0garbage";
  expect_refused(dir / "garbage.glb", "glTF");

  ASSERT_TRUE(testing::write_3mf(dir / "box.3mf", box));
  {
    std::ifstream in(dir / "box.3mf", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(dir / "broken.3mf", std::ios::binary) << bytes.substr(0, bytes.size() - 40);
  expect_refused(dir / "broken.3mf", "3MF");
  std::ofstream(dir / "random.3mf", std::ios::binary) << "PK\x03\x04 this is no zip";
  expect_refused(dir / "random.3mf", "3MF");
}

}  // namespace
}  // namespace papercraft
