#pragma once
// Test inputs in the scene formats, written with the same libraries the loader reads them with:
// glTF (.gltf with its .bin, or .glb) through tinygltf and 3MF through lib3mf.

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <Model/COM/NMR_DLLInterfaces.h>
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/generate.h"
#include "core/triangle_mesh.h"

namespace papercraft::testing {

/// A triangle soup as exporters write it: per corner a position, and a UV where given.
struct SceneMesh {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<Vec2, 3>> corner_uv;  // empty: none; v up, as OBJ's
  /// Per triangle an sRGB colour (3MF) or none.
  std::vector<std::array<unsigned char, 3>> triangle_colour;
};

/// The side of an axis-aligned box a face with normal `n` lies on: 2 * axis + (n points up).
inline int box_side(const Vec3& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
  return 2 * axis + (n[axis] > 0 ? 1 : 0);
}

/// The generated 2 x 2 x 2 box with a texture atlas: each of its six sides a UV island, the
/// cell (side % 3, side / 3) of a 3 x 2 grid with a margin inside it, so every cube edge is a
/// UV seam.
inline SceneMesh atlas_box() {
  const TriangleMesh box = generate_shape("box", {{"size_x", 2}, {"size_y", 2}, {"size_z", 2}});
  SceneMesh mesh;
  mesh.positions = box.vertices;
  for (const Triangle& t : box.triangles) {
    mesh.triangles.push_back({t[0], t[1], t[2]});
    const int side =
        box_side((box.vertices[t[1]] - box.vertices[t[0]]).cross(box.vertices[t[2]] - box.vertices[t[0]]));
    const int axis = side / 2, u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
    const double cell_u = (side % 3) / 3.0, cell_v = 1.0 - (side / 3 + 1) / 2.0;
    std::array<Vec2, 3> uv;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = box.vertices[t[k]];
      uv[k] = Vec2(cell_u + (0.05 + 0.9 * (p[u_axis] + 1) / 2) / 3.0,
                   cell_v + (0.05 + 0.9 * (p[v_axis] + 1) / 2) / 2.0);
    }
    mesh.corner_uv.push_back(uv);
  }
  return mesh;
}

/// Writes `mesh` as an OBJ after `header` (e.g. its mtllib and usemtl lines): shared vertices,
/// a vt per corner where it has UVs.
inline void write_obj(const std::filesystem::path& path, const SceneMesh& mesh,
                      const std::string& header = "") {
  std::ofstream obj(path);
  obj.precision(17);
  obj << header;
  for (const Vec3& p : mesh.positions) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& uv : mesh.corner_uv)
    for (const Vec2& c : uv) obj << "vt " << c.x() << ' ' << c.y() << '\n';
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    obj << 'f';
    for (int k = 0; k < 3; ++k) {
      obj << ' ' << mesh.triangles[t][k] + 1;
      if (!mesh.corner_uv.empty()) obj << '/' << 3 * t + k + 1;
    }
    obj << '\n';
  }
}

struct GltfOptions {
  bool binary = true;  // .glb; else .gltf with a .bin beside it
  /// The texture: PNG bytes embedded (GLB: in the buffer; glTF: as an image file written
  /// beside it under `image_uri`); none when empty.
  std::vector<std::uint8_t> png;
  std::string image_uri = "texture.png";
  /// The node's TRS transform.
  std::optional<Vec3> translation, scale;
  std::optional<std::array<double, 4>> rotation;  // x, y, z, w
  int mode = TINYGLTF_MODE_TRIANGLES;             // or TRIANGLE_STRIP of the first 2 triangles
};

inline void append_bytes(std::vector<unsigned char>& buffer, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), bytes, bytes + size);
  while (buffer.size() % 4 != 0) buffer.push_back(0);
}

inline int add_view(tinygltf::Model& model, std::vector<unsigned char>& buffer, const void* data,
                    std::size_t size) {
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = size;
  append_bytes(buffer, data, size);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

inline int add_accessor(tinygltf::Model& model, int view, int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

/// Writes `mesh` as one primitive, every corner its own vertex (as exporters split vertices at
/// UV seams), indexed with unsigned shorts. Returns whether tinygltf wrote it.
inline bool write_gltf(const std::filesystem::path& path, const SceneMesh& mesh,
                       const GltfOptions& options) {
  tinygltf::Model model;
  std::vector<unsigned char> buffer;
  std::vector<float> positions, uvs;
  std::vector<std::uint16_t> indices;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.positions[mesh.triangles[t][k]];
      positions.insert(positions.end(), {float(p.x()), float(p.y()), float(p.z())});
      if (!mesh.corner_uv.empty())
        uvs.insert(uvs.end(), {float(mesh.corner_uv[t][k].x()), float(1 - mesh.corner_uv[t][k].y())});
      indices.push_back(static_cast<std::uint16_t>(indices.size()));
    }
  tinygltf::Primitive primitive;
  primitive.mode = options.mode;
  if (options.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    // The first two triangles as a strip a b c d: triangles (a b c) and (c b d).
    const auto& t0 = mesh.triangles[0];
    const auto& t1 = mesh.triangles[1];
    positions.clear();
    for (int v : {t0[0], t0[1], t0[2], t1[2]}) {
      const Vec3& p = mesh.positions[v];
      positions.insert(positions.end(), {float(p.x()), float(p.y()), float(p.z())});
    }
    indices = {0, 1, 2, 3};
    uvs.clear();
  }
  const std::size_t vertices = positions.size() / 3;
  primitive.attributes["POSITION"] = add_accessor(
      model, add_view(model, buffer, positions.data(), positions.size() * 4), TINYGLTF_TYPE_VEC3,
      vertices);
  {
    tinygltf::Accessor& a = model.accessors.back();
    a.minValues = {-1e9, -1e9, -1e9};
    a.maxValues = {1e9, 1e9, 1e9};
  }
  if (!uvs.empty())
    primitive.attributes["TEXCOORD_0"] = add_accessor(
        model, add_view(model, buffer, uvs.data(), uvs.size() * 4), TINYGLTF_TYPE_VEC2, vertices);
  primitive.indices = add_accessor(
      model, add_view(model, buffer, indices.data(), indices.size() * 2), TINYGLTF_TYPE_SCALAR,
      indices.size());
  model.accessors.back().componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  if (!options.png.empty()) {
    tinygltf::Image image;
    image.mimeType = "image/png";
    if (options.binary) {
      image.bufferView = add_view(model, buffer, options.png.data(), options.png.size());
    } else {
      image.uri = options.image_uri;
      std::FILE* f = std::fopen((path.parent_path() / options.image_uri).c_str(), "wb");
      if (f == nullptr) return false;
      std::fwrite(options.png.data(), 1, options.png.size(), f);
      std::fclose(f);
    }
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = 0;
    model.textures.push_back(texture);
    tinygltf::Material material;
    material.name = "atlas";
    material.pbrMetallicRoughness.baseColorTexture.index = 0;
    model.materials.push_back(material);
    primitive.material = 0;
  }
  tinygltf::Buffer data;
  data.data = buffer;
  if (!options.binary) data.uri = path.stem().string() + ".bin";
  model.buffers.push_back(data);
  tinygltf::Mesh gltf_mesh;
  gltf_mesh.primitives.push_back(primitive);
  model.meshes.push_back(gltf_mesh);
  tinygltf::Node node;
  node.mesh = 0;
  if (options.translation)
    node.translation = {options.translation->x(), options.translation->y(),
                        options.translation->z()};
  if (options.scale) node.scale = {options.scale->x(), options.scale->y(), options.scale->z()};
  if (options.rotation)
    node.rotation = {(*options.rotation)[0], (*options.rotation)[1], (*options.rotation)[2],
                     (*options.rotation)[3]};
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  model.asset.version = "2.0";
  tinygltf::TinyGLTF writer;
  return writer.WriteGltfSceneToFile(&model, path.string(), false, options.binary, true,
                                     options.binary);
}

/// Writes `mesh` as one mesh object of a 3MF package, built `copies` times as components of
/// one components object, the k-th moved by (k * shift, 0, 0); per-triangle colours where
/// given. Returns whether lib3mf wrote it.
inline bool write_3mf(const std::filesystem::path& path, const SceneMesh& mesh, int copies = 1,
                      double shift = 0.0) {
  using namespace NMR;
  PLib3MFModel* model = nullptr;
  if (lib3mf_createmodel(&model) != LIB3MF_OK) return false;
  PLib3MFModelMeshObject* object = nullptr;
  lib3mf_model_addmeshobject(model, &object);
  std::vector<MODELMESHVERTEX> vertices(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    for (int k = 0; k < 3; ++k) vertices[v].m_fPosition[k] = float(mesh.positions[v][k]);
  std::vector<MODELMESHTRIANGLE> triangles(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) triangles[t].m_nIndices[k] = DWORD(mesh.triangles[t][k]);
  lib3mf_meshobject_setgeometry(object, vertices.data(), DWORD(vertices.size()), triangles.data(),
                                DWORD(triangles.size()));
  if (!mesh.triangle_colour.empty()) {
    PLib3MFPropertyHandler* handler = nullptr;
    lib3mf_meshobject_createpropertyhandler(object, &handler);
    for (std::size_t t = 0; t < mesh.triangle_colour.size(); ++t) {
      MODELMESHCOLOR_SRGB c{mesh.triangle_colour[t][0], mesh.triangle_colour[t][1],
                            mesh.triangle_colour[t][2], 255};
      lib3mf_propertyhandler_setsinglecolor(handler, DWORD(t), &c);
    }
    lib3mf_release(handler);
    // The core specification wants a default property beside per-triangle ones.
    PLib3MFDefaultPropertyHandler* defaults = nullptr;
    lib3mf_object_createdefaultpropertyhandler(object, &defaults);
    MODELMESHCOLOR_SRGB grey{128, 128, 128, 255};
    lib3mf_defaultpropertyhandler_setcolor(defaults, &grey);
    lib3mf_release(defaults);
  }
  PLib3MFModelBuildItem* item = nullptr;
  if (copies <= 1) {
    lib3mf_model_addbuilditem(model, object, nullptr, &item);
  } else {
    PLib3MFModelComponentsObject* group = nullptr;
    lib3mf_model_addcomponentsobject(model, &group);
    for (int k = 0; k < copies; ++k) {
      MODELTRANSFORM t{};
      for (int r = 0; r < 3; ++r) t.m_fFields[r][r] = 1.0f;
      t.m_fFields[0][3] = float(k * shift);
      PLib3MFModelComponent* component = nullptr;
      lib3mf_componentsobject_addcomponent(group, object, &t, &component);
      lib3mf_release(component);
    }
    lib3mf_model_addbuilditem(model, group, nullptr, &item);
    lib3mf_release(group);
  }
  lib3mf_release(item);
  lib3mf_release(object);
  PLib3MFModelWriter* writer = nullptr;
  lib3mf_model_querywriter(model, "3mf", &writer);
  const bool ok = lib3mf_writer_writetofileutf8(writer, path.c_str()) == LIB3MF_OK;
  if (!ok) {
    DWORD code = 0;
    LPCSTR message = nullptr;
    lib3mf_getlasterror(writer, &code, &message);
    std::fprintf(stderr, "lib3mf: %u %s\n", unsigned(code), message ? message : "");
  }
  lib3mf_release(writer);
  lib3mf_release(model);
  return ok;
}

}  // namespace papercraft::testing
