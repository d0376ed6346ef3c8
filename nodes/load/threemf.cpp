// read_3mf: a 3MF package through lib3mf (its C interface, version 1), flattened into a RawMesh:
// every build item's object with its transform, components objects followed recursively.

#include <Model/COM/NMR_DLLInterfaces.h>

#include <Eigen/Dense>
#include <memory>

#include "nodes/load/messages.h"
#include "nodes/load/scene_formats.h"

namespace papercraft::load_internal {
namespace {

using namespace NMR;

// Owns one lib3mf instance.
struct Released {
  void operator()(void* instance) const {
    if (instance != nullptr) lib3mf_release(static_cast<PLib3MFBase*>(instance));
  }
};
template <class T>
using Owned = std::unique_ptr<T, Released>;

constexpr int kMaxDepth = 64;

Eigen::Affine3d affine_of(const MODELTRANSFORM& t) {
  Eigen::Affine3d a = Eigen::Affine3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.matrix()(r, c) = t.m_fFields[r][c];
  return a;
}

// lib3mf's message for the last error of `instance`, or `otherwise`.
std::string last_error(void* instance, const std::string& otherwise) {
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (instance != nullptr &&
      lib3mf_getlasterror(static_cast<PLib3MFBase*>(instance), &code, &message) == LIB3MF_OK &&
      message != nullptr && *message != '\0')
    return message;
  return otherwise;
}

Vec3d rgb(BYTE r, BYTE g, BYTE b) {
  return Vec3d(r / 255.0, g / 255.0, b / 255.0);
}

class PackageReader {
 public:
  PackageReader(PLib3MFModel* model, const std::string& file, RawMesh& raw)
      : model_(model), file_(file), raw_(raw) {}

  void read_build() {
    PLib3MFModelBuildItemIterator* items_raw = nullptr;
    check(lib3mf_model_getbuilditems(model_, &items_raw), model_, "the build items");
    const Owned<void> items(items_raw);
    BOOL more = false;
    while (lib3mf_builditemiterator_movenext(items_raw, &more) == LIB3MF_OK && more) {
      PLib3MFModelBuildItem* item = nullptr;
      check(lib3mf_builditemiterator_getcurrent(items_raw, &item), items_raw, "a build item");
      const Owned<void> owned_item(item);
      PLib3MFModelObjectResource* object = nullptr;
      check(lib3mf_builditem_getobjectresource(item, &object), item, "a build item's object");
      const Owned<void> owned_object(object);
      read_object(object,
                  transform_of(item, &lib3mf_builditem_hasobjecttransform,
                               &lib3mf_builditem_getobjecttransform, "a build item's transform"),
                  0);
    }
  }

  void finish() {
    if (any_colour_) {
      raw_.face_colour = std::move(face_colour_);
      raw_.face_has_colour.assign(raw_.face_colour.size(), 1);
    }
  }

 private:
  void check(LIB3MFRESULT result, void* instance, const std::string& what) const {
    if (result == LIB3MF_OK) return;
    throw_invalid(file_, "cannot read " + what + ": " +
                             last_error(instance, "error " + std::to_string(result)));
  }

  // The transform of a build item or component where it has one, else the identity.
  template <class Instance>
  Eigen::Affine3d transform_of(Instance* instance, LIB3MFRESULT (*has)(Instance*, BOOL*),
                               LIB3MFRESULT (*get)(Instance*, MODELTRANSFORM*),
                               const std::string& what) const {
    BOOL present = false;
    if (has(instance, &present) != LIB3MF_OK || !present) return Eigen::Affine3d::Identity();
    MODELTRANSFORM t;
    check(get(instance, &t), instance, what);
    return affine_of(t);
  }

  void read_object(PLib3MFModelObjectResource* object, const Eigen::Affine3d& transform,
                   int depth) {
    if (depth > kMaxDepth)
      throw_invalid(file_, "components nest more than " + std::to_string(kMaxDepth) +
                               " levels deep (an object is its own component?)");
    BOOL mesh = false, components = false;
    check(lib3mf_object_ismeshobject(object, &mesh), object, "an object's type");
    if (mesh) return read_mesh(object, transform);
    check(lib3mf_object_iscomponentsobject(object, &components), object, "an object's type");
    if (!components) return;
    DWORD count = 0;
    check(lib3mf_componentsobject_getcomponentcount(object, &count), object, "components");
    for (DWORD i = 0; i < count; ++i) {
      PLib3MFModelComponent* component = nullptr;
      check(lib3mf_componentsobject_getcomponent(object, i, &component), object, "a component");
      const Owned<void> owned_component(component);
      PLib3MFModelObjectResource* child = nullptr;
      check(lib3mf_component_getobjectresource(component, &child), component,
            "a component's object");
      const Owned<void> owned_child(child);
      read_object(child,
                  transform * transform_of(component, &lib3mf_component_hastransform,
                                           &lib3mf_component_gettransform,
                                           "a component's transform"),
                  depth + 1);
    }
  }

  // The colour of base material `index` of group `group`, if it has one.
  bool base_material_colour(DWORD group, DWORD index, Vec3d* colour) const {
    PLib3MFModelBaseMaterial* materials = nullptr;
    if (lib3mf_model_getbasematerialbyid(model_, group, &materials) != LIB3MF_OK ||
        materials == nullptr)
      return false;
    const Owned<void> owned(materials);
    BYTE r = 0, g = 0, b = 0, a = 0;
    if (lib3mf_basematerial_getdisplaycolor(materials, index, &r, &g, &b, &a) != LIB3MF_OK)
      return false;
    *colour = rgb(r, g, b);
    return true;
  }

  // The object's default colour (a colour or a base material), if it has one.
  bool default_colour(PLib3MFModelObjectResource* object, Vec3d* colour) const {
    PLib3MFDefaultPropertyHandler* handler = nullptr;
    if (lib3mf_object_createdefaultpropertyhandler(object, &handler) != LIB3MF_OK ||
        handler == nullptr)
      return false;
    const Owned<void> owned(handler);
    eModelPropertyType type = MODELPROPERTYTYPE_NONE;
    if (lib3mf_defaultpropertyhandler_getpropertytype(handler, &type) != LIB3MF_OK) return false;
    if (type == MODELPROPERTYTYPE_COLOR) {
      MODELMESHCOLOR_SRGB c;
      if (lib3mf_defaultpropertyhandler_getcolor(handler, 0, &c) != LIB3MF_OK) return false;
      *colour = rgb(c.m_Red, c.m_Green, c.m_Blue);
      return true;
    }
    if (type == MODELPROPERTYTYPE_BASEMATERIALS) {
      DWORD group = 0, index = 0;
      if (lib3mf_defaultpropertyhandler_getbasematerial(handler, &group, &index) != LIB3MF_OK)
        return false;
      return base_material_colour(group, index, colour);
    }
    return false;
  }

  void read_mesh(PLib3MFModelMeshObject* mesh, const Eigen::Affine3d& transform) {
    DWORD vertices = 0, triangles = 0;
    check(lib3mf_meshobject_getvertexcount(mesh, &vertices), mesh, "a mesh's vertex count");
    check(lib3mf_meshobject_gettrianglecount(mesh, &triangles), mesh, "a mesh's triangle count");
    std::vector<MODELMESHVERTEX> points(vertices);
    std::vector<MODELMESHTRIANGLE> corners(triangles);
    DWORD got = 0;
    if (vertices > 0)
      check(lib3mf_meshobject_getvertices(mesh, points.data(), vertices, &got), mesh,
            "a mesh's vertices");
    if (triangles > 0)
      check(lib3mf_meshobject_gettriangleindices(mesh, corners.data(), triangles, &got), mesh,
            "a mesh's triangles");

    const std::size_t base = raw_.positions.size();
    for (const MODELMESHVERTEX& p : points) {
      const Eigen::Vector3d q =
          transform * Eigen::Vector3d(p.m_fPosition[0], p.m_fPosition[1], p.m_fPosition[2]);
      raw_.positions.push_back(Vec3d(q.x(), q.y(), q.z()));
    }
    Vec3d fallback(0.5, 0.5, 0.5);
    const bool has_default = default_colour(mesh, &fallback);
    any_colour_ = any_colour_ || has_default;
    PLib3MFPropertyHandler* handler_raw = nullptr;
    if (lib3mf_meshobject_createpropertyhandler(mesh, &handler_raw) != LIB3MF_OK)
      handler_raw = nullptr;
    const Owned<void> handler(handler_raw);
    std::vector<MODELMESH_TRIANGLECOLOR_SRGB> colours;
    const bool mirrored = transform.linear().determinant() < 0;
    for (DWORD t = 0; t < triangles; ++t) {
      std::array<DWORD, 3> tri = {corners[t].m_nIndices[0], corners[t].m_nIndices[1],
                                  corners[t].m_nIndices[2]};
      for (DWORD v : tri)
        if (v >= vertices)
          throw_invalid(file_, "triangle " + std::to_string(t) + " of a mesh names vertex " +
                                   std::to_string(v) + ", but the mesh has " +
                                   counted(vertices, "vertex", "vertices"));
      if (mirrored) std::swap(tri[1], tri[2]);
      for (DWORD v : tri) raw_.corners.push_back(static_cast<int>(base + v));
      raw_.face_start.push_back(raw_.corners.size());
      face_colour_.push_back(triangle_colour(handler_raw, t, fallback, colours, triangles));
    }
  }

  Vec3d triangle_colour(PLib3MFPropertyHandler* handler, DWORD t, const Vec3d& fallback,
                        std::vector<MODELMESH_TRIANGLECOLOR_SRGB>& colours, DWORD triangles) {
    if (handler == nullptr) return fallback;
    eModelPropertyType type = MODELPROPERTYTYPE_NONE;
    if (lib3mf_propertyhandler_getpropertytype(handler, t, &type) != LIB3MF_OK) return fallback;
    if (type == MODELPROPERTYTYPE_COLOR) {
      if (colours.empty()) {
        colours.resize(triangles);
        if (lib3mf_propertyhandler_getcolorarray(handler, colours.data()) != LIB3MF_OK) {
          colours.clear();
          return fallback;
        }
      }
      any_colour_ = true;
      Vec3d sum(0.0, 0.0, 0.0);
      for (const MODELMESHCOLOR_SRGB& c : colours[t].m_Colors)
        sum += rgb(c.m_Red, c.m_Green, c.m_Blue);
      return sum / 3.0;
    }
    if (type == MODELPROPERTYTYPE_BASEMATERIALS) {
      DWORD group = 0, index = 0;
      Vec3d colour;
      if (lib3mf_propertyhandler_getbasematerial(handler, t, &group, &index) == LIB3MF_OK &&
          base_material_colour(group, index, &colour)) {
        any_colour_ = true;
        return colour;
      }
    }
    return fallback;
  }

  PLib3MFModel* model_;
  const std::string& file_;
  RawMesh& raw_;
  std::vector<Vec3d> face_colour_;
  bool any_colour_ = false;  // some triangle or object has a colour
};

}  // namespace

Prescan read_3mf(const std::filesystem::path& path, const std::string& file,
                 const LoadOptions& options, RawMesh& raw) {
  PLib3MFModel* model_raw = nullptr;
  if (lib3mf_createmodel(&model_raw) != LIB3MF_OK || model_raw == nullptr)
    throw_io(file, "lib3mf could not create a model");
  const Owned<void> model(model_raw);
  PLib3MFModelReader* reader_raw = nullptr;
  if (lib3mf_model_queryreader(model_raw, "3mf", &reader_raw) != LIB3MF_OK)
    throw_io(file, "lib3mf has no 3MF reader");
  const Owned<void> reader(reader_raw);
  if (lib3mf_reader_readfromfileutf8(reader_raw, path.c_str()) != LIB3MF_OK)
    throw_invalid(file, "not a readable 3MF package: " + last_error(reader_raw, "lib3mf refused it"));
  PackageReader package(model_raw, file, raw);
  package.read_build();
  package.finish();

  const Prescan scan = natively_read(Format::threemf, raw, file, options);
  if (scan.faces == 0) throw_invalid(file, "has no triangles (no mesh object in its build)");
  return scan;
}

}  // namespace papercraft::load_internal
