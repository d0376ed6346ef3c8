#pragma once
// What the input surface looks like, per face: the material (a texture image), texture
// coordinates at the face's three corners and colours at its corners, as the loader read them.
// The print images of the pieces are baked from this (nodes/export/bake.h), so UV seams,
// several materials and colours need nothing from the strips.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

struct Material {
  std::string name;     // the .mtl's newmtl name, or the texture's file name
  std::string texture;  // image path (resolved against the .mtl's or the mesh's folder); "" none
  /// The image file's bytes where the mesh file holds them (a GLB's or a data URI's image);
  /// `texture` then names it for messages ("cube.glb#image0.png"). Null: read `texture`.
  std::shared_ptr<const std::vector<std::uint8_t>> texture_bytes;
};

/// Parallel to the faces of the loaded mesh (face f of the Mesh), each array either empty (the
/// file has none) or one entry per face. Corner k of face f is vertex face_vertices[f][k].
struct SurfaceAppearance {
  std::vector<Material> materials;
  std::vector<std::array<int, 3>> face_vertices;  // set whenever any other array is
  std::vector<int> face_material;                 // index into materials, -1 for none
  std::vector<std::array<Vec2, 3>> face_uv;       // texture coordinates (v up)
  std::vector<std::array<Vec3, 3>> face_colour;   // linear 0..1 RGB

  bool has_texture() const {
    for (const Material& m : materials)
      if (!m.texture.empty()) return !face_uv.empty();
    return false;
  }
  bool has_colour() const { return !face_colour.empty(); }
  bool empty() const { return !has_texture() && !has_colour(); }
};

}  // namespace papercraft
