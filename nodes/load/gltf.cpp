// read_gltf: a glTF 2.0 scene through tinygltf, flattened into a RawMesh.
//
// tinygltf parses the JSON and the buffers and checks the document's structure; every
// accessor and buffer view is checked here against its buffer before a byte is read, since a
// document may point anywhere. Images are not decoded here: their bytes (or the path of the
// file beside a .gltf) go to the print bake, which decodes PNG and JPEG itself.

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>

#include "nodes/load/messages.h"
#include "nodes/load/scene_formats.h"

namespace papercraft::load_internal {
namespace {

// Keeps an image's file bytes as they are (decoded later, by the print bake).
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// One accessor's elements, checked to lie inside its buffer.
struct Elements {
  const unsigned char* data = nullptr;  // null: every value is 0 (no buffer view)
  std::size_t stride = 0;
  std::size_t count = 0;
  int components = 0;
  int component_type = 0;
  bool normalized = false;

  double value(std::size_t i, int c) const {
    if (data == nullptr) return 0.0;
    const unsigned char* p = data + i * stride;
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double v = p[c];
        return normalized ? v / 255.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = static_cast<signed char>(p[c]);
        return normalized ? std::max(v / 127.0, -1.0) : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p + 2 * c, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : double(v);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p + 4 * c, 4);
        return v;
      }
      default:
        return 0.0;
    }
  }
  std::uint64_t index(std::size_t i) const {
    return data == nullptr ? 0 : static_cast<std::uint64_t>(value(i, 0));
  }
};

class SceneReader {
 public:
  SceneReader(const tinygltf::Model& model, const std::filesystem::path& path,
              const std::string& file, RawMesh& raw)
      : model_(model), path_(path), file_(file), raw_(raw) {}

  void read_scene() {
    std::vector<int> roots;
    const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (scene < static_cast<int>(model_.scenes.size())) {
      roots = model_.scenes[scene].nodes;
    } else {  // no scene: every node that is no other node's child
      std::vector<char> child(model_.nodes.size(), 0);
      for (const tinygltf::Node& node : model_.nodes)
        for (int c : node.children)
          if (c >= 0 && c < static_cast<int>(child.size())) child[c] = 1;
      for (std::size_t n = 0; n < model_.nodes.size(); ++n)
        if (!child[n]) roots.push_back(static_cast<int>(n));
    }
    for (int root : roots) read_node(root, Eigen::Matrix4d::Identity(), 0);
  }

  /// Colours and materials once every primitive is read: kept only where some primitive had
  /// them, so a plain grey model gets no appearance.
  void finish() {
    if (any_colour_) {
      raw_.vertex_colour = std::move(vertex_colour_);
      raw_.vertex_has_colour.assign(raw_.vertex_colour.size(), 1);
    }
    if (!raw_.materials.empty()) raw_.face_material = std::move(face_material_);
    if (std::count(raw_.face_has_uv.begin(), raw_.face_has_uv.end(), 1) == 0) {
      raw_.face_has_uv.clear();
      raw_.corner_uv.clear();
    }
  }

  std::uint64_t skipped_primitives = 0;

 private:
  static constexpr int kMaxDepth = 64;

  void read_node(int index, const Eigen::Matrix4d& parent, int depth) {
    if (index < 0 || index >= static_cast<int>(model_.nodes.size()))
      throw_invalid(file_, "node " + std::to_string(index) + " does not exist");
    if (depth > kMaxDepth)
      throw_invalid(file_, "the node tree is more than " + std::to_string(kMaxDepth) +
                               " levels deep (a node is its own ancestor?)");
    const tinygltf::Node& node = model_.nodes[index];
    const Eigen::Matrix4d world = parent * local_matrix(node, index);
    if (node.mesh >= 0) {
      if (node.mesh >= static_cast<int>(model_.meshes.size()))
        throw_invalid(file_, "node " + std::to_string(index) + " names mesh " +
                                 std::to_string(node.mesh) + ", which does not exist");
      for (const tinygltf::Primitive& primitive : model_.meshes[node.mesh].primitives)
        read_primitive(primitive, world);
    }
    for (int child : node.children) read_node(child, world, depth + 1);
  }

  Eigen::Matrix4d local_matrix(const tinygltf::Node& node, int index) const {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    if (node.matrix.size() == 16) {
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m(r, c) = node.matrix[4 * c + r];  // column-major
    } else {
      Eigen::Affine3d a = Eigen::Affine3d::Identity();
      if (node.translation.size() == 3)
        a.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
      if (node.rotation.size() == 4) {
        Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1],
                             node.rotation[2]);
        if (q.norm() > 0) a.rotate(q.normalized());
      }
      if (node.scale.size() == 3)
        a.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
      m = a.matrix();
    }
    if (!m.allFinite())
      throw_invalid(file_, "node " + std::to_string(index) + " has a transform that is not finite");
    return m;
  }

  Elements elements(int accessor_index, const std::string& what) const {
    if (accessor_index < 0 || accessor_index >= static_cast<int>(model_.accessors.size()))
      throw_invalid(file_, what + ": accessor " + std::to_string(accessor_index) +
                               " does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[accessor_index];
    const std::string name = what + " (accessor " + std::to_string(accessor_index) + ")";
    if (accessor.sparse.isSparse) throw_invalid(file_, name + ": sparse accessors are not read");
    Elements e;
    e.count = accessor.count;
    e.component_type = accessor.componentType;
    e.normalized = accessor.normalized;
    e.components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    const int component_size = tinygltf::GetComponentSizeInBytes(
        static_cast<std::uint32_t>(accessor.componentType));
    if (e.components <= 0 || component_size <= 0)
      throw_invalid(file_, name + ": unknown type or component type");
    const std::size_t element_size = std::size_t(e.components) * component_size;
    if (accessor.bufferView < 0) return e;  // all zeros
    if (accessor.bufferView >= static_cast<int>(model_.bufferViews.size()))
      throw_invalid(file_, name + ": buffer view " + std::to_string(accessor.bufferView) +
                               " does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[accessor.bufferView];
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size()))
      throw_invalid(file_, name + ": its buffer view names buffer " + std::to_string(view.buffer) +
                               ", which does not exist");
    const std::vector<unsigned char>& buffer = model_.buffers[view.buffer].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      throw_invalid(file_, name + ": its buffer view runs past the end of buffer " +
                               std::to_string(view.buffer) + " (" +
                               std::to_string(buffer.size()) + " bytes)");
    e.stride = view.byteStride > 0 ? view.byteStride : element_size;
    if (e.stride < element_size)
      throw_invalid(file_, name + ": byte stride " + std::to_string(e.stride) +
                               " is shorter than an element (" + std::to_string(element_size) +
                               " bytes)");
    if (e.count > 0) {
      const std::size_t offset = accessor.byteOffset;
      const std::size_t length = view.byteLength;
      const bool fits = offset <= length && element_size <= length - offset &&
                        (e.count - 1) <= (length - offset - element_size) / e.stride;
      if (!fits)
        throw_invalid(file_, name + ": " + counted(e.count, "element", "elements") +
                                 " run past the end of its buffer view (" +
                                 std::to_string(length) + " bytes)");
      e.data = buffer.data() + view.byteOffset + offset;
    }
    return e;
  }

  // The material's base-colour texture and factor.
  struct Look {
    int material = -1;  // index into raw_.materials, -1: no texture
    int texcoord = 0;   // which TEXCOORD_n the texture uses
    Vec3d factor{1.0, 1.0, 1.0};
  };

  Look look_of(int material) {
    Look look;
    if (material < 0 || material >= static_cast<int>(model_.materials.size())) return look;
    const tinygltf::PbrMetallicRoughness& pbr = model_.materials[material].pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3)
      look.factor = Vec3d(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]);
    if (!std::isfinite(look.factor[0] + look.factor[1] + look.factor[2]))
      look.factor = Vec3d(1.0, 1.0, 1.0);
    const int texture = pbr.baseColorTexture.index;
    look.texcoord = std::max(0, pbr.baseColorTexture.texCoord);
    if (texture < 0 || texture >= static_cast<int>(model_.textures.size())) return look;
    const int source = model_.textures[texture].source;
    if (source < 0 || source >= static_cast<int>(model_.images.size())) return look;
    const auto known = material_of_image_.find(source);
    if (known != material_of_image_.end()) {
      look.material = known->second;
      return look;
    }
    const tinygltf::Image& image = model_.images[source];
    Material m;
    m.name = !model_.materials[material].name.empty() ? model_.materials[material].name
                                                       : "image" + std::to_string(source);
    const bool external = !image.uri.empty() && image.uri.rfind("data:", 0) != 0;
    if (external) {
      m.texture = (path_.parent_path() / image.uri).lexically_normal().string();
    } else if (!image.image.empty()) {
      const std::string extension = image.mimeType == "image/jpeg" ? ".jpg" : ".png";
      m.texture = file_ + "#image" + std::to_string(source) + extension;
      m.texture_bytes = std::make_shared<const std::vector<std::uint8_t>>(image.image.begin(),
                                                                          image.image.end());
    } else {
      return look;
    }
    look.material = static_cast<int>(raw_.materials.size());
    material_of_image_[source] = look.material;
    raw_.materials.push_back(std::move(m));
    return look;
  }

  // The primitive's corners as triangles of vertex indices (local to its accessors).
  std::vector<std::array<std::uint64_t, 3>> triangles_of(const tinygltf::Primitive& primitive,
                                                         std::size_t vertices) const {
    std::vector<std::uint64_t> order;
    if (primitive.indices >= 0) {
      const Elements indices = elements(primitive.indices, "indices");
      if (indices.components != 1 ||
          (indices.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
           indices.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
           indices.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        throw_invalid(file_, "indices (accessor " + std::to_string(primitive.indices) +
                                 ") are not scalars of unsigned integers");
      order.resize(indices.count);
      for (std::size_t i = 0; i < indices.count; ++i) {
        order[i] = indices.index(i);
        if (order[i] >= vertices)
          throw_invalid(file_, "index " + std::to_string(order[i]) + " (accessor " +
                                   std::to_string(primitive.indices) + ", element " +
                                   std::to_string(i) + ") is out of range: the primitive has " +
                                   counted(vertices, "vertex", "vertices"));
      }
    } else {
      order.resize(vertices);
      for (std::size_t i = 0; i < vertices; ++i) order[i] = i;
    }
    std::vector<std::array<std::uint64_t, 3>> triangles;
    const std::size_t n = order.size();
    switch (primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode) {
      case TINYGLTF_MODE_TRIANGLES:
        for (std::size_t i = 0; i + 2 < n; i += 3)
          triangles.push_back({order[i], order[i + 1], order[i + 2]});
        break;
      case TINYGLTF_MODE_TRIANGLE_STRIP:  // every other triangle turned to keep the winding
        for (std::size_t i = 0; i + 2 < n; ++i)
          triangles.push_back(i % 2 == 0 ? std::array{order[i], order[i + 1], order[i + 2]}
                                         : std::array{order[i + 1], order[i], order[i + 2]});
        break;
      case TINYGLTF_MODE_TRIANGLE_FAN:
        for (std::size_t i = 1; i + 1 < n; ++i)
          triangles.push_back({order[0], order[i], order[i + 1]});
        break;
      default:
        break;
    }
    return triangles;
  }

  void read_primitive(const tinygltf::Primitive& primitive, const Eigen::Matrix4d& world) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end() ||
        (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
         mode != TINYGLTF_MODE_TRIANGLE_FAN)) {
      ++skipped_primitives;
      return;
    }
    const Elements positions = elements(position->second, "POSITION");
    if (positions.components != 3 ||
        positions.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
      throw_invalid(file_, "POSITION (accessor " + std::to_string(position->second) +
                               ") is not VEC3 of floats");
    const Look look = look_of(primitive.material);
    Elements uv, colour;
    const bool textured = look.material >= 0 && [&] {
      const auto it = primitive.attributes.find("TEXCOORD_" + std::to_string(look.texcoord));
      if (it == primitive.attributes.end()) return false;
      uv = elements(it->second, it->first);
      return uv.components == 2 && uv.count == positions.count;
    }();
    const auto colour_it = primitive.attributes.find("COLOR_0");
    const bool coloured = colour_it != primitive.attributes.end() && [&] {
      colour = elements(colour_it->second, "COLOR_0");
      return colour.components >= 3 && colour.count == positions.count;
    }();

    const std::size_t base = raw_.positions.size();
    const Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
    const Eigen::Vector3d shift = world.topRightCorner<3, 1>();
    for (std::size_t v = 0; v < positions.count; ++v) {
      const Eigen::Vector3d p(positions.value(v, 0), positions.value(v, 1), positions.value(v, 2));
      const Eigen::Vector3d q = linear * p + shift;
      raw_.positions.push_back(Vec3d(q.x(), q.y(), q.z()));
      Vec3d c = look.factor;
      if (coloured)
        for (int k = 0; k < 3; ++k) c[k] *= colour.value(v, k);
      vertex_colour_.push_back(c);
    }
    any_colour_ = any_colour_ || coloured || look.factor != Vec3d(1.0, 1.0, 1.0);
    const bool mirrored = linear.determinant() < 0;
    for (auto triangle : triangles_of(primitive, positions.count)) {
      if (mirrored) std::swap(triangle[1], triangle[2]);
      for (std::uint64_t corner : triangle) {
        raw_.corners.push_back(static_cast<int>(base + corner));
        raw_.corner_uv.push_back(textured ? Vec2d(uv.value(corner, 0), 1.0 - uv.value(corner, 1))
                                          : Vec2d(0.0, 0.0));
      }
      raw_.face_start.push_back(raw_.corners.size());
      raw_.face_has_uv.push_back(textured ? 1 : 0);
      face_material_.push_back(textured ? look.material : -1);
    }
  }

  const tinygltf::Model& model_;
  const std::filesystem::path& path_;
  const std::string& file_;
  RawMesh& raw_;
  std::map<int, int> material_of_image_;
  std::vector<Vec3d> vertex_colour_;
  std::vector<int> face_material_;
  bool any_colour_ = false;  // some primitive has COLOR_0 or a base-colour factor
};

}  // namespace

Prescan read_gltf(const std::filesystem::path& path, const std::string& file,
                  const LoadOptions& options, RawMesh& raw) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image_bytes, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = extension == ".glb" ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                                      : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  if (!ok) {
    std::string why = error.empty() ? warning : error;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    for (char& c : why)
      if (c == '\n') c = ';';
    throw_invalid(file, "not a readable glTF 2.0 file: " + (why.empty() ? "no reason given" : why));
  }
  for (const std::string& needed : model.extensionsRequired) {
    throw_invalid(file, "needs the glTF extension " + in_quotes(needed) +
                            ", which is not read (compressed geometry: export without it)");
  }
  SceneReader reader(model, path, file, raw);
  reader.read_scene();
  reader.finish();

  const Prescan scan = natively_read(Format::gltf, raw, file, options);
  if (scan.faces == 0) {
    throw_invalid(file, "has no triangles" +
                            (reader.skipped_primitives > 0
                                 ? " (" + counted(reader.skipped_primitives, "primitive", "primitives") +
                                       " of points or lines, or without POSITION, skipped)"
                                 : std::string(" (no mesh in its scene)")));
  }
  return scan;
}

}  // namespace papercraft::load_internal
