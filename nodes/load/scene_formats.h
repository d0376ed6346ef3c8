#pragma once
// Scene formats: glTF 2.0 (tinygltf) and 3MF (lib3mf). A scene holds meshes placed by a tree of
// transforms; each reader flattens it into the RawMesh every format ends in, with the
// transforms applied, so that the validation, repairs and messages of load_mesh are the same as
// for OBJ, OFF, PLY and STL. Why these libraries: docs/stages/load.md.

#include <filesystem>
#include <string>

#include "nodes/load/openmesh.h"
#include "nodes/load/prescan.h"
#include "nodes/load/raw_mesh.h"

namespace papercraft::load_internal {

/// A .gltf (with its .bin and images beside it, or data URIs) or a .glb: every triangle
/// primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; points and lines are skipped) of the
/// default scene (else the first; else every root node) with its nodes' transforms applied
/// (a mirroring transform turns the faces back). Per corner: TEXCOORD_n of the material's
/// base-colour texture (v turned up as OBJ's), COLOR_0 and the base-colour factor as colours.
/// The texture is the image file beside a .gltf or the bytes a .glb holds. Fills `raw` and
/// returns the counts with `read_natively` set.
/// \throws InvalidInputException naming `file`: not glTF, truncated, an accessor or buffer
///   view out of its buffer, an index out of range, a cyclic node tree, an extension it needs
///   that is not read (Draco, meshopt), or no triangles.
Prescan read_gltf(const std::filesystem::path& path, const std::string& file,
                  const LoadOptions& options, RawMesh& raw);

/// A .3mf: every build item's object, mesh objects and components objects (recursively) with
/// the item's and components' transforms; per-triangle colours (colour groups and base
/// materials, else the object's default), as face colours.
/// \throws InvalidInputException naming `file`: not a 3MF package (a broken zip, no model
///   part), an invalid model, or no triangles.
Prescan read_3mf(const std::filesystem::path& path, const std::string& file,
                 const LoadOptions& options, RawMesh& raw);

}  // namespace papercraft::load_internal
