#pragma once
// The records of a mesh file as read, before any validation: what OpenMesh's reader reports
// through the recording importer (recording_importer.h), or what the pre-scan of a plain ascii
// OFF reads itself (prescan.h).

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <cstddef>

#include "core/appearance.h"
#include <map>
#include <string>
#include <vector>

namespace papercraft::load_internal {

using OpenMesh::Vec2d;
using OpenMesh::Vec3d;

/// The file's data as read: nothing validated, nothing dropped.
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
  // Materials of a scene format (glTF, 3MF): their textures resolved or held in memory, and
  // per face the material (-1: none), once any face had one.
  std::vector<Material> materials;
  std::vector<int> face_material;

  std::size_t n_faces() const { return face_start.size() - 1; }
};

}  // namespace papercraft::load_internal
