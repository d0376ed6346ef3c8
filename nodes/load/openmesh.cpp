// load_mesh: the pre-scan, OpenMesh's reader, validation and repair, and the Mesh built from the
// result.

#include "nodes/load/openmesh.h"

#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <system_error>

#include "core/errors.h"
#include "nodes/load/file_scanner.h"
#include "nodes/load/materials.h"
#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"
#include "nodes/load/prescan.h"
#include "nodes/load/recording_importer.h"
#include "nodes/load/repair.h"
#include "nodes/load/scene_formats.h"
#include "nodes/load/soup.h"
#include "nodes/load/triangulate.h"

namespace papercraft {
namespace load_internal {
namespace {

std::string texture_of(const RawMesh& raw, const Prescan& scan, const std::filesystem::path& path) {
  if (!raw.face_material.empty()) {  // a scene format: the material of most faces
    std::map<int, std::size_t> faces;
    for (int m : raw.face_material)
      if (m >= 0) ++faces[m];
    int best = -1;
    for (const auto& [m, n] : faces)
      if (best < 0 || n > faces[best]) best = m;
    return best >= 0 ? raw.materials[best].texture : std::string();
  }
  if (scan.format == Format::ply && !scan.ply_texture.empty()) {
    return (path.parent_path() / scan.ply_texture).lexically_normal().string();
  }
  if (scan.format != Format::obj || raw.textures.empty()) return {};
  int best = raw.textures.begin()->first;
  std::size_t best_faces = 0;
  for (const auto& [texture, faces] : raw.faces_per_texture) {
    if (faces > best_faces && raw.textures.count(texture) > 0) {
      best = texture;
      best_faces = faces;
    }
  }
  const std::string name = texture_file_name(raw.textures.at(best));
  return (scan.material_library.parent_path() / name).lexically_normal().string();
}

// What the appearance needs of the file's faces and vertices, kept past the raw mesh.
struct RawAppearance {
  std::vector<Material> materials;
  std::vector<int> face_material;  // per file face
  std::vector<Vec3d> vertex_colour;
  std::vector<Vec3d> face_colour;
};

RawAppearance raw_appearance(const RawMesh& raw, const Prescan& scan,
                             const std::filesystem::path& path) {
  RawAppearance a;
  if (!raw.face_material.empty()) {  // a scene format: its materials as read
    a.materials = raw.materials;
    a.face_material = raw.face_material;
  } else if (scan.format == Format::ply && !scan.ply_texture.empty()) {
    a.materials.push_back({scan.ply_texture,
                           (path.parent_path() / scan.ply_texture).lexically_normal().string(),
                           nullptr});
    a.face_material.assign(raw.n_faces(), 0);
  } else if (scan.format == Format::obj && !raw.textures.empty()) {
    const auto names = material_names(scan.material_library);
    std::map<int, int> index;  // texture id -> material
    for (const auto& [id, map_kd] : raw.textures) {
      const std::string file = texture_file_name(map_kd);
      const auto named = names.find(file);
      index[id] = static_cast<int>(a.materials.size());
      a.materials.push_back(
          {named != names.end() ? named->second : file,
           (scan.material_library.parent_path() / file).lexically_normal().string(), nullptr});
    }
    a.face_material.assign(raw.n_faces(), -1);
    for (std::size_t f = 0; f < raw.face_texture.size() && f < raw.n_faces(); ++f) {
      const auto it = index.find(raw.face_texture[f]);
      if (it != index.end()) a.face_material[f] = it->second;
    }
  }
  // Colours count only when every vertex (face) has one.
  if (!raw.vertex_has_colour.empty() &&
      std::count(raw.vertex_has_colour.begin(), raw.vertex_has_colour.end(), 1) ==
          static_cast<std::ptrdiff_t>(raw.positions.size()))
    a.vertex_colour = raw.vertex_colour;
  else if (!raw.face_has_colour.empty() &&
           std::count(raw.face_has_colour.begin(), raw.face_has_colour.end(), 1) ==
               static_cast<std::ptrdiff_t>(raw.n_faces()))
    a.face_colour = raw.face_colour;
  return a;
}

// The appearance per face of the built mesh (face f is soup triangle f).
SurfaceAppearance mesh_appearance(RawAppearance raw, const Soup& soup, bool with_uvs) {
  SurfaceAppearance a;
  const std::size_t faces = soup.triangles.size();
  a.face_vertices.assign(soup.triangles.begin(), soup.triangles.end());
  if (!raw.face_material.empty()) {
    a.materials = std::move(raw.materials);
    a.face_material.resize(faces);
    for (std::size_t f = 0; f < faces; ++f) {
      const int source = soup.source_face[f];
      a.face_material[f] =
          source >= 0 && static_cast<std::size_t>(source) < raw.face_material.size()
              ? raw.face_material[source]
              : -1;
    }
  }
  if (with_uvs) {
    a.face_uv.resize(faces);
    for (std::size_t f = 0; f < faces; ++f)
      for (int k = 0; k < 3; ++k)
        a.face_uv[f][k] = Vec2(soup.corner_uv[f][k][0], soup.corner_uv[f][k][1]);
  }
  if (!raw.vertex_colour.empty() || !raw.face_colour.empty()) {
    a.face_colour.resize(faces);
    for (std::size_t f = 0; f < faces; ++f) {
      for (int k = 0; k < 3; ++k) {
        Vec3d c(0.5, 0.5, 0.5);
        if (!raw.vertex_colour.empty()) {
          const int source = soup.source_vertex[soup.triangles[f][k]];
          if (source >= 0 && static_cast<std::size_t>(source) < raw.vertex_colour.size())
            c = raw.vertex_colour[source];
        } else {
          const int source = soup.source_face[f];
          if (source >= 0 && static_cast<std::size_t>(source) < raw.face_colour.size())
            c = raw.face_colour[source];
        }
        a.face_colour[f][k] = Vec3(c[0], c[1], c[2]);
      }
    }
  }
  return a;
}

// The counts OpenMesh's reader (or the pre-scan) returned against the file's, and the notes
// on faces it dropped and STL corners it merged.
void check_reader_counts(const RawMesh& raw, const Prescan& scan, const std::string& file,
                         std::vector<std::string>& repairs) {
  const bool vertices_match = scan.format == Format::stl ? raw.positions.size() <= scan.vertices
                                                         : raw.positions.size() == scan.vertices;
  // OpenMesh's readers drop faces of no area: an STL triangle two of whose corners coincide, an
  // OBJ face of fewer than 3 distinct vertices.
  const std::uint64_t faces = scan.faces - scan.dropped_faces;
  const std::uint64_t corners = scan.corners - scan.dropped_corners;
  if (!vertices_match || raw.n_faces() != faces || raw.corners.size() != corners) {
    throw_io(file, "OpenMesh's reader returned " + declared(raw.positions.size(), raw.n_faces()) +
                       " (" + std::to_string(raw.corners.size()) + " corners), but the file has " +
                       declared(scan.vertices, faces) + " (" + std::to_string(corners) +
                       " corners): it misread the file");
  }
  if (scan.dropped_faces > 0) {
    repairs.push_back("removed " + (scan.format == Format::stl
                                        ? counted(scan.dropped_faces, "triangle", "triangles") +
                                              " two of whose corners coincide (no area)"
                                        : counted(scan.dropped_faces, "face", "faces") +
                                              " of fewer than 3 distinct vertices (no area)"));
  }
  if (scan.format == Format::stl && raw.positions.size() < scan.vertices) {
    repairs.push_back("merged " +
                      counted(scan.vertices - raw.positions.size(), "exactly duplicate vertex",
                              "exactly duplicate vertices") +
                      " (an STL stores every triangle corner separately)");
  }
}

// Texture coordinates: per corner (OBJ) when every face has them, else per vertex (PLY, OFF)
// when every vertex has them (copied to the corners); a note where some lack them. Whether the
// mesh keeps them.
bool choose_texture_coordinates(RawMesh& raw, const Prescan& scan,
                                std::vector<std::string>& repairs) {
  const std::size_t faces_with_uv =
      static_cast<std::size_t>(std::count(raw.face_has_uv.begin(), raw.face_has_uv.end(), 1));
  const std::size_t vertices_with_uv =
      static_cast<std::size_t>(std::count(raw.vertex_has_uv.begin(), raw.vertex_has_uv.end(), 1));
  bool with_uvs = false;
  if (scan.off_face_extras > 0) {
    repairs.push_back("ignored the values after the vertex indices of " +
                      counted(scan.off_face_extras, "face", "faces") +
                      " (face colors need a COFF header)");
  }
  if (faces_with_uv > 0) {
    with_uvs = faces_with_uv == raw.n_faces();
    if (!with_uvs) {
      repairs.push_back("ignored texture coordinates: only " + std::to_string(faces_with_uv) +
                        " of " + counted(raw.n_faces(), "face has", "faces have") + " them");
    }
  } else if (vertices_with_uv > 0) {
    with_uvs = vertices_with_uv == raw.positions.size();
    if (with_uvs) {
      raw.corner_uv.resize(raw.corners.size());
      for (std::size_t c = 0; c < raw.corners.size(); ++c) {
        raw.corner_uv[c] = raw.vertex_uv[raw.corners[c]];
      }
    } else {
      repairs.push_back("ignored texture coordinates: only " + std::to_string(vertices_with_uv) +
                        " of " + counted(raw.positions.size(), "vertex has", "vertices have") +
                        " them");
    }
  }
  return with_uvs;
}

// The safe repairs of the soup where options.repair asks for them (each noted in `repairs`),
// and the checks that refuse what is left.
void repair_and_check_soup(Soup& soup, const LoadOptions& options, const std::string& file,
                           std::vector<std::string>& repairs) {
  if (options.repair) {
    if (const std::size_t removed = remove_unreferenced_vertices(soup); removed > 0) {
      repairs.push_back("removed " +
                        counted(removed, "unreferenced vertex", "unreferenced vertices"));
    }
    const double epsilon = std::max(0.0, options.duplicate_vertex_epsilon);
    if (const std::size_t merged = merge_duplicate_vertices(soup, epsilon); merged > 0) {
      std::ostringstream what;
      what << "merged "
           << counted(merged, epsilon > 0.0 ? "duplicate vertex" : "exactly duplicate vertex",
                      epsilon > 0.0 ? "duplicate vertices" : "exactly duplicate vertices");
      if (epsilon > 0.0) what << " (within " << epsilon << ")";
      repairs.push_back(what.str());
    }
  }
  if (options.repair) {
    const DegenerateFaces degenerate =
        heal_degenerate_triangles(soup, options.degenerate_area_ratio);
    if (degenerate.collapsed > 0) {
      repairs.push_back(
          "removed " + counted(degenerate.collapsed, "face", "faces") +
          " with a corner repeated (in the file, or once duplicate vertices were merged)");
    }
    if (degenerate.flat > 0) {
      repairs.push_back(
          "removed " + counted(degenerate.flat, "zero-area face", "zero-area faces") +
          " (corners on one line), each face across its longest edge split at its middle corner");
    }
  }
  check_degenerate_triangles(soup, options, file);
  if (options.repair) {
    const DuplicateFaces duplicates = remove_duplicate_triangles(soup);
    if (duplicates.copies > 0) {
      repairs.push_back("removed " +
                        counted(duplicates.copies, "duplicate face", "duplicate faces") +
                        " (the same vertices as another face, facing the same way)");
    }
    if (duplicates.folds > 0) {
      repairs.push_back("removed " + counted(duplicates.folds, "pair", "pairs") +
                        " of faces on the same vertices facing opposite ways (a flap "
                        "folded flat onto itself)");
    }
    if (duplicates.other_sides > 0) {
      repairs.push_back(
          "kept one side of a two-sided surface (every face written once facing each way): "
          "removed " +
          counted(duplicates.other_sides, "face", "faces"));
    }
    if (soup.triangles.empty()) {
      throw_invalid(file,
                    "mesh has no faces left once its faces of no area are removed (corners "
                    "merged into one another or on one line)");
    }
    if (const std::size_t removed = remove_unreferenced_vertices(soup); removed > 0) {
      repairs.push_back("removed " + counted(removed, "vertex", "vertices") +
                        " used only by the faces removed");
    }
  }
  check_duplicate_triangles(soup, file);
  check_topology_and_orient(soup, options.repair, file, repairs);
}

// The soup's corner texture coordinates on the mesh: per vertex, and per halfedge where a
// vertex has more than one (a UV seam).
void set_texture_coordinates(const Soup& soup, const std::vector<Mesh::VertexHandle>& handles,
                             LoadedMesh& loaded) {
  Mesh& mesh = loaded.mesh;
  const std::size_t vertices = soup.positions.size();
  loaded.has_uvs = true;
  mesh.request_vertex_texcoords2D();
  std::vector<char> assigned(vertices, 0);
  std::vector<char> seam(vertices, 0);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = soup.triangles[t][k];
      const Vec2d& uv = soup.corner_uv[t][k];
      if (!assigned[v]) {
        mesh.set_texcoord2D(handles[v], uv);
        assigned[v] = 1;
      } else if (mesh.texcoord2D(handles[v]) != uv) {
        seam[v] = 1;
      }
    }
  }
  loaded.uv_seam_vertices = static_cast<std::size_t>(std::count(seam.begin(), seam.end(), 1));
  if (loaded.uv_seam_vertices > 0) {
    mesh.request_halfedge_texcoords2D();
    for (auto f : mesh.faces()) {
      const Triangle3& tri = soup.triangles[f.idx()];
      for (auto h : f.halfedges()) {
        mesh.set_texcoord2D(h, soup.corner_uv[f.idx()][corner_of(tri, h.to().idx())]);
      }
    }
  }
}

LoadedMesh validate_and_build(RawMesh& raw, const Prescan& scan, const LoadOptions& options,
                              const std::string& file, const std::filesystem::path& path) {
  LoadedMesh loaded;
  loaded.input_vertices = scan.vertices;
  loaded.input_faces = scan.faces;
  check_reader_counts(raw, scan, file, loaded.repairs);
  check_raw_faces(raw, file, options.repair);

  const bool with_uvs = choose_texture_coordinates(raw, scan, loaded.repairs);
  loaded.texture_path = texture_of(raw, scan, path);
  RawAppearance appearance = raw_appearance(raw, scan, path);

  Soup soup = triangulate(raw, with_uvs, options, file, loaded.repairs);
  raw = RawMesh();

  repair_and_check_soup(soup, options, file, loaded.repairs);
  Mesh& mesh = loaded.mesh;
  const std::size_t vertices = soup.positions.size();
  mesh.reserve(vertices, soup.triangles.size() * 3 / 2 + 3, soup.triangles.size());
  std::vector<Mesh::VertexHandle> handles(vertices);
  for (std::size_t v = 0; v < vertices; ++v) handles[v] = mesh.add_vertex(soup.positions[v]);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const Triangle3& tri = soup.triangles[t];
    if (!mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid()) {
      throw_invalid(file, "OpenMesh refused face " + std::to_string(soup.source_face[t]) +
                              " (vertices " + vertex_list(soup.source_vertex, tri) +
                              ") as non-manifold");
    }
  }
  loaded.appearance = mesh_appearance(std::move(appearance), soup, with_uvs);
  auto input_vertex =
      OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(mesh, kInputVertexProperty);
  for (auto v : mesh.vertices()) input_vertex[v] = soup.source_vertex[v.idx()];

  if (with_uvs) set_texture_coordinates(soup, handles, loaded);
  return loaded;
}

Format format_of(const std::filesystem::path& path, const std::string& file) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return Format::obj;
  if (extension == ".off") return Format::off;
  if (extension == ".ply") return Format::ply;
  if (extension == ".stl") return Format::stl;
  if (extension == ".gltf" || extension == ".glb") return Format::gltf;
  if (extension == ".3mf") return Format::threemf;
  throw_invalid(file, (extension.empty() ? std::string("no file extension")
                                         : "unknown extension " + in_quotes(extension)) +
                          " (supported: .obj, .off, .ply, .stl, .gltf, .glb, .3mf)");
}

}  // namespace
}  // namespace load_internal

LoadedMesh load_mesh(const std::filesystem::path& path, const LoadOptions& options) {
  using namespace load_internal;
  const std::string file = path.string();
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw_io(file, "no such file");
  if (std::filesystem::is_directory(status)) throw_io(file, "is a directory, not a mesh file");
  if (!std::filesystem::is_regular_file(status)) throw_io(file, "not a regular file");
  const Format format = format_of(path, file);
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error) throw_io(file, "cannot read the file size: " + error.message());
  if (size == 0) throw_invalid(file, "the file is empty");

  Prescan scan;
  RawMesh raw;
  if (format == Format::gltf) {
    scan = read_gltf(path, file, options, raw);
  } else if (format == Format::threemf) {
    scan = read_3mf(path, file, options, raw);
  } else {
    FileScanner in(path, file, size);
    switch (format) {
      case Format::obj:
        scan = prescan_obj(in, file, path, options);
        break;
      case Format::off:
        scan = prescan_off(in, file, options, &raw);
        break;
      case Format::ply:
        scan = prescan_ply(in, file, options, &raw);
        break;
      case Format::stl:
        scan = prescan_stl(in, file, options);
        break;
      case Format::gltf:
      case Format::threemf:
      case Format::arrays:
        break;
    }
  }
  if (!scan.read_natively) raw = read_with_openmesh(path, file, scan);
  return validate_and_build(raw, scan, options, file, path);
}

LoadedMesh load_arrays(const TriangleMesh& mesh, const std::string& name,
                       const LoadOptions& options) {
  using namespace load_internal;
  RawMesh raw;
  raw.positions.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) raw.positions.emplace_back(p.x(), p.y(), p.z());
  raw.corners.reserve(3 * mesh.triangles.size());
  raw.face_start.reserve(mesh.triangles.size() + 1);
  for (const Triangle& t : mesh.triangles) {
    raw.corners.insert(raw.corners.end(), t.begin(), t.end());
    raw.face_start.push_back(raw.corners.size());
  }
  if (raw.n_faces() == 0) throw_invalid(name, "the mesh has no faces");
  const Prescan scan = natively_read(Format::arrays, raw, name, options);
  return validate_and_build(raw, scan, options, name, std::filesystem::path());
}

}  // namespace papercraft
