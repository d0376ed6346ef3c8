// OpenMesh's reader into an importer that records everything it reports (step 2 of loading),
// with a cleaned copy of an ascii OFF that OpenMesh would misread.

#include "nodes/load/recording_importer.h"

#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <fstream>
#include <mutex>
#include <string_view>
#include <system_error>
#include <type_traits>

#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"

namespace papercraft::load_internal {
namespace {

// A colour as red, green, blue in [0, 1]: bytes are scaled, floats taken as they are.
template <class Colour>
Vec3d rgb(const Colour& c) {
  const double scale = std::is_integral_v<typename Colour::value_type> ? 1.0 / 255.0 : 1.0;
  return Vec3d(c[0], c[1], c[2]) * scale;
}

// Records what OpenMesh's reader finds: fake handles are raw indices, nothing is validated or
// dropped, header counts given to reserve() are ignored (they are not trusted).
class RecordingImporter final : public OpenMesh::IO::BaseImporter {
 public:
  explicit RecordingImporter(RawMesh& raw) : raw_(raw) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& point) override {
    return push_vertex(Vec3d(point[0], point[1], point[2]));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& point) override {
    return push_vertex(point);
  }
  OpenMesh::VertexHandle add_vertex() override { return push_vertex(Vec3d(0.0, 0.0, 0.0)); }
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();  // only the OM format builds halfedges directly
  }
  OpenMesh::FaceHandle add_face(const VHandles& indices) override {
    for (const OpenMesh::VertexHandle& vertex : indices) raw_.corners.push_back(vertex.idx());
    raw_.face_start.push_back(raw_.corners.size());
    return OpenMesh::FaceHandle(static_cast<int>(raw_.n_faces() - 1));
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
    return OpenMesh::FaceHandle();
  }
  void add_face_texcoords(OpenMesh::FaceHandle face, OpenMesh::VertexHandle first,
                          const std::vector<OpenMesh::Vec2f>& texcoords) override {
    if (face.idx() < 0 || static_cast<std::size_t>(face.idx()) >= raw_.n_faces()) return;
    const std::size_t begin = raw_.face_start[face.idx()];
    const std::size_t size = raw_.face_start[face.idx() + 1] - begin;
    if (texcoords.size() != size || size == 0) return;
    std::size_t offset = 0;
    while (offset < size && raw_.corners[begin + offset] != first.idx()) ++offset;
    if (offset == size) return;
    raw_.corner_uv.resize(raw_.corners.size());
    raw_.face_has_uv.resize(raw_.n_faces(), 0);
    for (std::size_t i = 0; i < size; ++i) {
      const OpenMesh::Vec2f& uv = texcoords[i];
      raw_.corner_uv[begin + (offset + i) % size] = Vec2d(uv[0], uv[1]);
    }
    raw_.face_has_uv[face.idx()] = 1;
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle face, int texture) override {
    if (texture > 0) ++raw_.faces_per_texture[texture];
    if (face.idx() < 0 || static_cast<std::size_t>(face.idx()) >= raw_.n_faces()) return;
    raw_.face_texture.resize(raw_.n_faces(), 0);
    raw_.face_texture[face.idx()] = texture;
  }
  void set_point(OpenMesh::VertexHandle vertex, const OpenMesh::Vec3f& point) override {
    if (vertex.idx() >= 0 && static_cast<std::size_t>(vertex.idx()) < raw_.positions.size()) {
      raw_.positions[vertex.idx()] = Vec3d(point[0], point[1], point[2]);
    }
  }
  void set_texcoord(OpenMesh::VertexHandle vertex, const OpenMesh::Vec2f& uv) override {
    if (vertex.idx() < 0 || static_cast<std::size_t>(vertex.idx()) >= raw_.positions.size()) return;
    if (raw_.vertex_uv.size() < raw_.positions.size()) {
      raw_.vertex_uv.resize(raw_.positions.size());
      raw_.vertex_has_uv.resize(raw_.positions.size(), 0);
    }
    raw_.vertex_uv[vertex.idx()] = Vec2d(uv[0], uv[1]);
    raw_.vertex_has_uv[vertex.idx()] = 1;
  }
  void add_texture_information(int id, std::string name) override {
    raw_.textures[id] = std::move(name);
  }
  size_t n_vertices() const override { return raw_.positions.size(); }
  size_t n_faces() const override { return raw_.n_faces(); }
  size_t n_edges() const override { return 0; }

  // Normals, colors, status bits, halfedge links and 3D texture coordinates are not needed.
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle v, const OpenMesh::Vec3uc& c) override { vertex_colour(v, rgb(c)); }
  void set_color(OpenMesh::VertexHandle v, const OpenMesh::Vec4uc& c) override { vertex_colour(v, rgb(c)); }
  void set_color(OpenMesh::VertexHandle v, const OpenMesh::Vec3f& c) override { vertex_colour(v, rgb(c)); }
  void set_color(OpenMesh::VertexHandle v, const OpenMesh::Vec4f& c) override { vertex_colour(v, rgb(c)); }
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle f, const OpenMesh::Vec3uc& c) override { face_colour(f, rgb(c)); }
  void set_color(OpenMesh::FaceHandle f, const OpenMesh::Vec4uc& c) override { face_colour(f, rgb(c)); }
  void set_color(OpenMesh::FaceHandle f, const OpenMesh::Vec3f& c) override { face_colour(f, rgb(c)); }
  void set_color(OpenMesh::FaceHandle f, const OpenMesh::Vec4f& c) override { face_colour(f, rgb(c)); }
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void reserve(unsigned int, unsigned int, unsigned int) override {}

 private:
  static Vec3d clamped(const Vec3d& c) {
    return Vec3d(std::clamp(c[0], 0.0, 1.0), std::clamp(c[1], 0.0, 1.0),
                 std::clamp(c[2], 0.0, 1.0));
  }
  void vertex_colour(OpenMesh::VertexHandle v, const Vec3d& c) {
    if (v.idx() < 0 || static_cast<std::size_t>(v.idx()) >= raw_.positions.size()) return;
    raw_.vertex_colour.resize(raw_.positions.size());
    raw_.vertex_has_colour.resize(raw_.positions.size(), 0);
    raw_.vertex_colour[v.idx()] = clamped(c);
    raw_.vertex_has_colour[v.idx()] = 1;
  }
  void face_colour(OpenMesh::FaceHandle f, const Vec3d& c) {
    if (f.idx() < 0 || static_cast<std::size_t>(f.idx()) >= raw_.n_faces()) return;
    raw_.face_colour.resize(raw_.n_faces());
    raw_.face_has_colour.resize(raw_.n_faces(), 0);
    raw_.face_colour[f.idx()] = clamped(c);
    raw_.face_has_colour[f.idx()] = 1;
  }

  OpenMesh::VertexHandle push_vertex(const Vec3d& point) {
    raw_.positions.push_back(point);
    return OpenMesh::VertexHandle(static_cast<int>(raw_.positions.size() - 1));
  }

  RawMesh& raw_;
};

// An ascii OFF as OpenMesh's reader can take it: no comments, no blank lines, and faces without
// values after their indices (the pre-scan has checked the rest).
std::string clean_off(const std::filesystem::path& path, const std::string& file,
                      const Prescan& scan) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_io(file, "cannot open the file");
  std::string out;
  std::string line;
  std::uint64_t content_lines = 0;
  const std::uint64_t first_face = 2 + scan.vertices;
  while (std::getline(in, line)) {
    std::string_view content = line;
    const std::size_t hash = content.find('#');
    if (hash != std::string_view::npos) content = content.substr(0, hash);
    content = trim(content);
    if (content.empty()) continue;
    if (content_lines >= first_face && scan.off_face_extras > 0) {
      std::string_view tokens = content;
      std::int64_t count = 0;
      parse_integer(next_token(tokens), count);
      for (std::int64_t corner = 0; corner < count; ++corner) next_token(tokens);
      content = content.substr(0, content.size() - tokens.size());
    }
    out.append(content);
    out.push_back('\n');
    ++content_lines;
  }
  return out;
}

// An OBJ as OpenMesh's reader can take it: each line ending in a backslash joined with the next
// (the backslash dropped), as the pre-scan read it.
std::string clean_obj(const std::filesystem::path& path, const std::string& file) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_io(file, "cannot open the file");
  std::string out;
  std::string line;
  while (std::getline(in, line)) {
    if (ends_in_backslash(line)) {
      const std::string_view content = trim(line);
      out.append(content.substr(0, content.size() - 1));
      out.push_back(' ');
    } else {
      out.append(line);
      out.push_back('\n');
    }
  }
  return out;
}

}  // namespace

RawMesh read_with_openmesh(const std::filesystem::path& path, const std::string& file,
                           const Prescan& scan) {
  RawMesh raw;
  RecordingImporter importer(raw);
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexTexCoord;
  options += OpenMesh::IO::Options::FaceTexCoord;
  options += OpenMesh::IO::Options::VertexColor;
  options += OpenMesh::IO::Options::FaceColor;
  // OpenMesh's stream reader skips the header check that sets the OFF reader's options, so a
  // cleaned OFF goes through a temporary file; so does an OBJ with lines continued by a
  // backslash, in a folder of its own with a link to its material library under the name the
  // file gives it (OpenMesh looks for it beside the OBJ), so its materials still load.
  std::filesystem::path source = path;
  struct RemoveOnExit {
    std::filesystem::path folder;
    ~RemoveOnExit() {
      std::error_code ignored;
      if (!folder.empty()) std::filesystem::remove_all(folder, ignored);
    }
  } cleaned;
  const bool clean =
      (scan.format == Format::off && (scan.off_comments || scan.off_face_extras > 0)) ||
      (scan.format == Format::obj && scan.obj_continuations > 0);
  if (clean) {
    static std::atomic<std::uint64_t> counter{0};
    std::error_code error;
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("papercraft-clean-" + std::to_string(::getpid()) +
                                                  "-" + std::to_string(counter.fetch_add(1)));
    std::filesystem::create_directory(folder, error);
    if (error) throw_io(file, "cannot make a folder for a cleaned copy: " + error.message());
    cleaned.folder = folder;
    source = folder / path.filename();
    std::ofstream out(source, std::ios::binary);
    out << (scan.format == Format::off ? clean_off(path, file, scan) : clean_obj(path, file));
    if (!out.flush()) throw_io(file, "cannot write a cleaned copy to " + source.string());
    if (scan.format == Format::obj && !scan.material_library.empty()) {
      const std::filesystem::path name =
          scan.material_library.lexically_relative(path.parent_path());
      const bool inside = !name.empty() && name.is_relative() && *name.begin() != "..";
      if (inside && std::filesystem::exists(scan.material_library, error)) {
        std::filesystem::create_directories((folder / name).parent_path(), error);
        std::filesystem::create_symlink(std::filesystem::absolute(scan.material_library, error),
                                        folder / name, error);
      }
    }
  }
  // The reader modules are process-wide singletons that keep per-file state in members.
  static std::mutex reader_mutex;
  bool ok = false;
  {
    std::lock_guard<std::mutex> lock(reader_mutex);
    ok = OpenMesh::IO::IOManager().read(source.string(), importer, options);
  }
  if (!ok) throw_io(file, "OpenMesh's reader failed on the file");
  return raw;
}

}  // namespace papercraft::load_internal
