#pragma once
// Step 2 of loading: OpenMesh's reader fills a recording importer that keeps the raw vertex
// positions, face index lists and texture coordinates, dropping nothing.

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "nodes/load/prescan.h"

namespace papercraft::load_internal {

using OpenMesh::Vec2d;
using OpenMesh::Vec3d;

/// The file's data as OpenMesh's reader reported it: nothing validated, nothing dropped.
struct RawMesh {
  std::vector<Vec3d> positions;
  std::vector<std::size_t> face_start{0};  // face f has corners [face_start[f], face_start[f+1])
  std::vector<int> corners;
  // Per-corner texture coordinates, parallel to `corners` once any face had them.
  std::vector<Vec2d> corner_uv;
  std::vector<char> face_has_uv;
  // Per-vertex texture coordinates, once any vertex had them.
  std::vector<Vec2d> vertex_uv;
  std::vector<char> vertex_has_uv;
  std::map<int, std::string> textures;  // OBJ texture id -> map_Kd
  std::map<int, std::size_t> faces_per_texture;
  std::vector<int> face_texture;  // per face: its texture id (0: none), once any face had one
  // Colours in 0..1, once any vertex (face) had one.
  std::vector<Vec3d> vertex_colour;
  std::vector<char> vertex_has_colour;
  std::vector<Vec3d> face_colour;
  std::vector<char> face_has_colour;

  std::size_t n_faces() const { return face_start.size() - 1; }
};

/// Reads the file with OpenMesh's reader (serialised: its readers are process-wide singletons);
/// an ascii OFF with comments or face extras goes through a cleaned temporary copy.
/// \throws IOException when the reader fails or the cleaned copy cannot be written.
RawMesh read_with_openmesh(const std::filesystem::path& path, const std::string& file,
                           const Prescan& scan);

}  // namespace papercraft::load_internal
