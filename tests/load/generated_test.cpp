// The loader on generated meshes in every format it reads: counts and topology survive.

#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <filesystem>

#include "core/generate.h"
#include "nodes/load/openmesh.h"

namespace papercraft {
namespace {

TEST(LoadGenerated, EveryShapeInEveryFormatKeepsCountsAndTopology) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("papercraft-load-generated-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const std::string& shape : shape_names()) {
    const Mesh mesh = to_mesh(generate_shape(shape, {}));
    const std::size_t loops = boundary_loops(mesh).size();
    for (const char* extension : {".obj", ".off", ".ply", ".stl"}) {
      SCOPED_TRACE(shape + extension);
      const auto path = dir / (shape + extension);
      OpenMesh::IO::Options options = OpenMesh::IO::Options::Default;
      if (std::string(extension) == ".stl") options = OpenMesh::IO::Options::Binary;
      ASSERT_TRUE(OpenMesh::IO::write_mesh(mesh, path.string(), options, 17));
      const LoadedMesh loaded = load_mesh(path);
      EXPECT_EQ(loaded.mesh.n_vertices(), mesh.n_vertices());
      EXPECT_EQ(loaded.mesh.n_faces(), mesh.n_faces());
      EXPECT_EQ(euler_characteristic(loaded.mesh), euler_characteristic(mesh));
      EXPECT_EQ(boundary_loops(loaded.mesh).size(), loops);
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace papercraft
