// The pre-scan of a PLY file, ascii or binary of either endianness.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"
#include "nodes/load/prescan.h"

namespace papercraft::load_internal {
namespace {

constexpr std::size_t kMaxPlyHeaderLines = 100'000;

struct PlyType {
  std::string_view name;
  int bytes;
  bool is_float;
  bool is_signed;
};

constexpr PlyType kPlyTypes[] = {
    {"char", 1, false, true},    {"int8", 1, false, true},    {"uchar", 1, false, false},
    {"uint8", 1, false, false},  {"short", 2, false, true},   {"int16", 2, false, true},
    {"ushort", 2, false, false}, {"uint16", 2, false, false}, {"int", 4, false, true},
    {"int32", 4, false, true},   {"uint", 4, false, false},   {"uint32", 4, false, false},
    {"float", 4, true, true},    {"float32", 4, true, true},  {"double", 8, true, true},
    {"float64", 8, true, true},
};

const PlyType* find_ply_type(std::string_view name) {
  for (const PlyType& type : kPlyTypes) {
    if (type.name == name) return &type;
  }
  return nullptr;
}

// How OpenMesh's ascii PLY reader consumes a value: as a float, as an int, or as a string.
enum class PlyReading { as_float, as_integer, as_token };

struct PlyProperty {
  std::string name;
  const PlyType* type = nullptr;  // the list entries' type for a list
  const PlyType* count_type = nullptr;
  bool is_list = false;
  bool is_vertex_indices = false;
  bool is_coordinate = false;
  PlyReading reading = PlyReading::as_token;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

bool is_one_of(std::string_view name, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A binary vertex or face record's real number: IEEE single or double, either byte order.
double decode_real(const unsigned char* bytes, int size, bool big_endian) {
  const auto bits = static_cast<std::uint64_t>(decode_integer(bytes, size, false, big_endian));
  if (size == 4) {
    const auto narrow = static_cast<std::uint32_t>(bits);
    float value = 0.0f;
    std::memcpy(&value, &narrow, sizeof value);
    return value;
  }
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// Whether the pre-scan reads a binary PLY itself: a vertex element of scalar positions (and
// normals, which nothing uses) followed by a face element with only its vertex index list.
// Anything else (colours, texture coordinates, other elements before the faces) goes to
// OpenMesh's reader.
bool plain_binary_ply(const std::vector<PlyElement>& elements, std::size_t read_elements) {
  if (read_elements != 2 || elements[0].name != "vertex" || elements[1].name != "face")
    return false;
  for (const PlyProperty& property : elements[0].properties)
    if (property.is_list || !is_one_of(property.name, {"x", "y", "z", "nx", "ny", "nz"}))
      return false;
  return elements[1].properties.size() == 1 && elements[1].properties[0].is_vertex_indices;
}

// The vertex and face records of a PLY that the pre-scan reads itself, value by value: a
// MeshLab-style PLY, its texture coordinates a list per face ("property list uchar float
// texcoord", u v per corner), which OpenMesh's reader cannot read. Positions, per-vertex texture
// coordinates (u v, s t, texture_u texture_v, texture_s texture_t) and colours (red green blue,
// integers over 255 or reals in 0..1), the faces' vertex index lists, texture coordinate lists
// and colours are kept; any other value is read past.
class PlyRecords {
 public:
  PlyRecords(RawMesh& raw, const PlyElement& vertex, const PlyElement& face)
      : raw_(raw), vertex_roles_(roles(vertex, false)), face_roles_(roles(face, true)) {
    raw_ = RawMesh();
    raw_.positions.reserve(vertex.count);
    raw_.face_start.reserve(face.count + 1);
    raw_.corners.reserve(3 * face.count);
    vertex_uv_ = has(vertex_roles_, Role::u) && has(vertex_roles_, Role::v);
    vertex_colour_ = has(vertex_roles_, Role::red) && has(vertex_roles_, Role::green) &&
                     has(vertex_roles_, Role::blue);
    face_uv_ = has(face_roles_, Role::texcoord);
    face_colour_ = has(face_roles_, Role::red) && has(face_roles_, Role::green) &&
                   has(face_roles_, Role::blue);
  }

  /// A value of property `property` of the current vertex record.
  void vertex_value(std::size_t property, double value) {
    const Role role = vertex_roles_[property];
    const std::size_t slot = static_cast<std::size_t>(role);
    if (role == Role::x || role == Role::y || role == Role::z) {
      position_[slot - static_cast<std::size_t>(Role::x)] = value;
    } else if (role == Role::u) {
      uv_[0] = value;
    } else if (role == Role::v) {
      uv_[1] = value;
    } else if (role == Role::red || role == Role::green || role == Role::blue) {
      colour_[slot - static_cast<std::size_t>(Role::red)] = value * scale_[property];
    }
  }
  /// The current vertex record is complete.
  void end_vertex() {
    raw_.positions.emplace_back(position_[0], position_[1], position_[2]);
    if (vertex_uv_) {
      raw_.vertex_uv.emplace_back(uv_[0], uv_[1]);
      raw_.vertex_has_uv.push_back(std::isfinite(uv_[0]) && std::isfinite(uv_[1]) ? 1 : 0);
    }
    if (vertex_colour_) {
      raw_.vertex_colour.push_back(clamped());
      raw_.vertex_has_colour.push_back(1);
    }
  }
  /// A value of property `property` of the current face record (an index list's entries as
  /// `index`, any other value as `value`).
  void face_value(std::size_t property, std::int64_t index, double value) {
    const Role role = face_roles_[property];
    if (role == Role::indices) {
      raw_.corners.push_back(static_cast<int>(std::clamp<std::int64_t>(
          index, std::numeric_limits<int>::min(), std::numeric_limits<int>::max())));
    } else if (role == Role::texcoord) {
      texcoords_.push_back(value);
    } else if (role == Role::red || role == Role::green || role == Role::blue) {
      colour_[static_cast<std::size_t>(role) - static_cast<std::size_t>(Role::red)] =
          value * scale_face_[property];
    }
  }
  /// The current face record is complete.
  void end_face() {
    const std::size_t begin = raw_.face_start.back();
    const std::size_t corners = raw_.corners.size() - begin;
    raw_.face_start.push_back(raw_.corners.size());
    if (face_uv_) {
      // A list of another length than two per corner, or not finite, gives the face no texture
      // coordinates.
      const bool whole = texcoords_.size() == 2 * corners &&
                         std::all_of(texcoords_.begin(), texcoords_.end(),
                                     [](double x) { return std::isfinite(x); });
      raw_.corner_uv.resize(raw_.corners.size());
      for (std::size_t k = 0; whole && k < corners; ++k)
        raw_.corner_uv[begin + k] = Vec2d(texcoords_[2 * k], texcoords_[2 * k + 1]);
      raw_.face_has_uv.push_back(whole ? 1 : 0);
      texcoords_.clear();
    }
    if (face_colour_) {
      raw_.face_colour.push_back(clamped());
      raw_.face_has_colour.push_back(1);
    }
  }

 private:
  enum class Role { none, x, y, z, u, v, red, green, blue, indices, texcoord };

  std::vector<Role> roles(const PlyElement& element, bool face) {
    std::vector<Role> out;
    std::vector<double>& scale = face ? scale_face_ : scale_;
    for (const PlyProperty& p : element.properties) {
      Role role = Role::none;
      if (face) {
        if (p.is_vertex_indices)
          role = Role::indices;
        else if (p.is_list && p.name == "texcoord")
          role = Role::texcoord;
      } else if (!p.is_list) {
        if (p.name == "x")
          role = Role::x;
        else if (p.name == "y")
          role = Role::y;
        else if (p.name == "z")
          role = Role::z;
        else if (is_one_of(p.name, {"u", "s", "texture_u", "texture_s"}))
          role = Role::u;
        else if (is_one_of(p.name, {"v", "t", "texture_v", "texture_t"}))
          role = Role::v;
      }
      if (!p.is_list && role == Role::none) {
        if (is_one_of(p.name, {"red", "diffuse_red"}))
          role = Role::red;
        else if (is_one_of(p.name, {"green", "diffuse_green"}))
          role = Role::green;
        else if (is_one_of(p.name, {"blue", "diffuse_blue"}))
          role = Role::blue;
      }
      out.push_back(role);
      scale.push_back(p.type != nullptr && !p.type->is_float ? 1.0 / 255.0 : 1.0);
    }
    return out;
  }
  static bool has(const std::vector<Role>& roles, Role role) {
    return std::find(roles.begin(), roles.end(), role) != roles.end();
  }
  Vec3d clamped() const {
    return Vec3d(std::clamp(colour_[0], 0.0, 1.0), std::clamp(colour_[1], 0.0, 1.0),
                 std::clamp(colour_[2], 0.0, 1.0));
  }

  RawMesh& raw_;
  std::vector<double> scale_, scale_face_;
  std::vector<Role> vertex_roles_, face_roles_;
  bool vertex_uv_ = false, vertex_colour_ = false, face_uv_ = false, face_colour_ = false;
  double position_[3] = {0, 0, 0};
  double uv_[2] = {0, 0};
  double colour_[3] = {0, 0, 0};
  std::vector<double> texcoords_;
};

}  // namespace

Prescan prescan_ply(FileScanner& in, const std::string& file, const LoadOptions& options,
                    RawMesh* raw) {
  Prescan scan;
  scan.format = Format::ply;
  // The header's bytes as read, to find where OpenMesh's reader will look for binary data.
  std::string header_bytes;
  std::size_t openmesh_position = 0;  // where OpenMesh's `tellg` is before it reads a keyword
  std::vector<PlyElement> elements;
  bool read_here = false;  // a layout OpenMesh's reader cannot read: the pre-scan reads it
  std::string format;
  bool big_endian = false;
  bool ended = false;
  std::string_view line;
  while (!ended && in.next_line(line)) {
    const std::uint64_t number = in.line_number();
    if (number > kMaxPlyHeaderLines) {
      throw_invalid(file, "the PLY header has no end_header in its first " +
                              std::to_string(kMaxPlyHeaderLines) + " lines");
    }
    const std::size_t line_start = header_bytes.size();
    header_bytes.append(line);
    if (in.last_line_had_carriage_return()) header_bytes.push_back('\r');
    header_bytes.push_back('\n');
    const std::string_view content = trim(line);
    const std::size_t content_end =
        line_start + static_cast<std::size_t>(content.data() + content.size() - line.data());
    std::string_view rest = content;
    const std::string_view keyword = next_token(rest);
    std::vector<std::string_view> tokens;
    for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
      tokens.push_back(token);
    }
    const std::string where = at_line(number);

    if (number == 1) {
      if (content != "ply" && content != "PLY") {
        throw_invalid(file, "line 1: not a PLY file (the first line must be 'ply')");
      }
      continue;
    }
    if (number == 2) {
      // OpenMesh reads the second line as the format whatever it says.
      if (keyword != "format" || tokens.size() != 2) {
        throw_invalid(file, where +
                                "expected 'format <ascii|binary_little_endian|"
                                "binary_big_endian> 1.0' on the second line, got " +
                                in_quotes(content));
      }
      format = std::string(tokens[0]);
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") {
        throw_invalid(file, where + "unsupported PLY format " + in_quotes(format));
      }
      // OpenMesh reads the version as a number and never ends on one it cannot read.
      const std::string version(tokens[1]);
      if (version.find_first_not_of("0123456789.") != std::string::npos ||
          std::strtod(version.c_str(), nullptr) != 1.0) {
        throw_invalid(file,
                      where + "unsupported PLY version " + in_quotes(version) + " (expected 1.0)");
      }
      big_endian = format == "binary_big_endian";
      openmesh_position = content_end;
      continue;
    }
    if (keyword == "comment") {
      if (!tokens.empty() && equals_ignoring_case(tokens[0], "TextureFile") &&
          scan.ply_texture.empty()) {
        std::string_view name = content;
        next_token(name);
        next_token(name);
        scan.ply_texture = std::string(trim(name));
      }
      // OpenMesh skips the rest of a comment line with getline, newline included.
      openmesh_position = header_bytes.size();
      continue;
    }
    if (keyword == "end_header") {
      if (!tokens.empty()) throw_invalid(file, where + "unexpected text after end_header");
      ended = true;
      if (format != "ascii" && !read_here) {
        // OpenMesh seeks to 12 (or 14 after "\r\n") bytes past its stream position before the
        // end_header keyword, which is right only when "\nend_header\n" directly follows the
        // last token of the header.
        const bool crlf = openmesh_position + 1 < header_bytes.size() &&
                          header_bytes[openmesh_position] == '\r' &&
                          header_bytes[openmesh_position + 1] == '\n';
        const std::size_t openmesh_data = openmesh_position + (crlf ? 14 : 12);
        if (openmesh_data != header_bytes.size()) {
          throw_invalid(file, where +
                                  "OpenMesh's reader would misplace the binary data: remove the "
                                  "comment, blank line or spaces directly before end_header, and "
                                  "any spaces around it");
        }
      }
      break;
    }
    openmesh_position = content_end;
    if (keyword == "obj_info") continue;
    if (keyword == "element") {
      std::int64_t count = 0;
      if (tokens.size() != 2 || !parse_integer(tokens[1], count) || count < 0) {
        throw_invalid(file, where + "expected 'element <name> <count>', got " + in_quotes(content));
      }
      if (static_cast<std::uint64_t>(count) > UINT32_MAX) {
        throw_invalid(file, where + "element " + in_quotes(tokens[0]) + " declares " +
                                std::to_string(count) +
                                " records, more than OpenMesh's PLY reader can count");
      }
      elements.push_back({std::string(tokens[0]), static_cast<std::uint64_t>(count), {}});
      continue;
    }
    if (keyword == "property") {
      if (elements.empty()) throw_invalid(file, where + "property before any element");
      PlyElement& element = elements.back();
      PlyProperty property;
      if (!tokens.empty() && tokens[0] == "list") {
        if (tokens.size() != 4) {
          throw_invalid(file, where + "expected 'property list <count type> <entry type> <name>'");
        }
        property.is_list = true;
        property.name = std::string(tokens[3]);
        property.count_type = find_ply_type(tokens[1]);
        property.type = find_ply_type(tokens[2]);
        if (property.count_type == nullptr || property.type == nullptr) {
          throw_invalid(file, where + "unknown type in " + in_quotes(content));
        }
        if (!is_one_of(tokens[1], {"uchar", "uint8", "uint16", "int"})) {
          throw_invalid(file, where + "list count type " + in_quotes(tokens[1]) +
                                  " is not supported by OpenMesh's PLY reader (use uchar, "
                                  "uint8, uint16 or int)");
        }
        property.is_vertex_indices =
            element.name == "face" && is_one_of(property.name, {"vertex_indices", "vertex_index"});
        // MeshLab's per-face texture coordinates: read by the pre-scan itself.
        const bool face_texcoords =
            raw != nullptr && element.name == "face" && property.name == "texcoord";
        if (face_texcoords) {
          if (!property.type->is_float) {
            throw_invalid(file, where + "texture coordinates must have a real type, got " +
                                    in_quotes(tokens[2]));
          }
          property.reading = PlyReading::as_float;
          read_here = true;
          element.properties.push_back(std::move(property));
          continue;
        }
        if (!property.is_vertex_indices) {
          throw_invalid(file, where + "list property " + in_quotes(property.name) + " of element " +
                                  in_quotes(element.name) +
                                  " is not supported (OpenMesh's PLY reader can only read the "
                                  "face's vertex_indices list)");
        }
        if (property.type->is_float) {
          throw_invalid(file, where + "vertex indices must have an integer type, got " +
                                  in_quotes(tokens[2]));
        }
        property.reading = PlyReading::as_integer;
      } else {
        if (tokens.size() != 2) {
          throw_invalid(file,
                        where + "expected 'property <type> <name>', got " + in_quotes(content));
        }
        property.name = std::string(tokens[1]);
        property.type = find_ply_type(tokens[0]);
        if (property.type == nullptr) {
          throw_invalid(file, where + "unknown property type " + in_quotes(tokens[0]));
        }
        const bool is_vertex = element.name == "vertex";
        const bool is_face = element.name == "face";
        property.is_coordinate = is_vertex && is_one_of(property.name, {"x", "y", "z"});
        const bool read_as_float =
            is_vertex &&
            is_one_of(property.name, {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t"});
        const bool is_color =
            (is_vertex && is_one_of(property.name, {"red", "green", "blue", "alpha", "diffuse_red",
                                                    "diffuse_green", "diffuse_blue"})) ||
            (is_face && is_one_of(property.name, {"red", "green", "blue", "alpha"}));
        const bool single_float = property.type->is_float && property.type->bytes == 4;
        if (read_as_float) {
          property.reading = PlyReading::as_float;
          if (format != "ascii" && !property.type->is_float) {
            throw_invalid(file, where + "property " + in_quotes(property.name) + " has type " +
                                    in_quotes(tokens[0]) +
                                    "; OpenMesh's binary PLY reader needs float or double");
          }
        } else if (is_color) {
          property.reading = single_float ? PlyReading::as_float : PlyReading::as_integer;
          if (property.type->is_float && !single_float) {
            throw_invalid(file, where + "color property " + in_quotes(property.name) +
                                    " of type double is not supported by OpenMesh's PLY reader");
          }
        }
      }
      element.properties.push_back(std::move(property));
      continue;
    }
    throw_invalid(file, where + "unknown PLY header keyword " + in_quotes(keyword));
  }
  if (!ended) {
    throw_invalid(file, "truncated: the PLY header has no end_header");
  }

  // Which elements OpenMesh reads: all up to and including the face element.
  std::size_t face_element = elements.size();
  const PlyElement* vertex_element = nullptr;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (elements[i].name == "vertex" && vertex_element == nullptr) vertex_element = &elements[i];
    if (elements[i].name == "face" && face_element == elements.size()) face_element = i;
  }
  if (vertex_element == nullptr) throw_invalid(file, "the PLY header has no vertex element");
  for (std::string_view axis : {"x", "y", "z"}) {
    const auto& properties = vertex_element->properties;
    if (std::count_if(properties.begin(), properties.end(),
                      [&](const PlyProperty& p) { return p.name == axis; }) != 1) {
      throw_invalid(file, "the PLY vertex element needs exactly one property " + in_quotes(axis));
    }
  }
  scan.vertices = vertex_element->count;
  if (face_element < elements.size()) {
    const auto& properties = elements[face_element].properties;
    if (std::none_of(properties.begin(), properties.end(),
                     [](const PlyProperty& p) { return p.is_vertex_indices; })) {
      throw_invalid(file, "the PLY face element has no vertex_indices list");
    }
    scan.faces = elements[face_element].count;
  }
  check_some_faces(file, scan);

  const bool ascii = format == "ascii";
  const std::size_t read_elements = face_element + 1;
  std::uint64_t needed = 0;
  for (std::size_t i = 0; i < read_elements; ++i) {
    std::uint64_t record = 0;
    for (const PlyProperty& property : elements[i].properties) {
      // Shortest records: a one-character token and a separator per value; a face has 3 indices.
      const std::uint64_t entries = property.is_vertex_indices ? 3 : 0;
      if (ascii) {
        record += property.is_list ? 2 * (1 + entries) : 2;
      } else {
        record += property.is_list ? property.count_type->bytes + entries * property.type->bytes
                                   : property.type->bytes;
      }
    }
    needed = add_saturating(needed, multiply_saturating(record, elements[i].count));
  }
  check_room(file, declared(scan.vertices, scan.faces), needed, in.remaining());
  check_counts(file, scan.vertices, scan.faces, options);

  auto truncated = [&](const PlyElement& element, std::uint64_t record) {
    throw_invalid(file, "truncated: the header declares " + declared(scan.vertices, scan.faces) +
                            ", but the data ends in " + element.name + " " +
                            std::to_string(record) + " (of " + std::to_string(element.count) + ")");
  };

  if (!ascii && raw != nullptr && plain_binary_ply(elements, read_elements)) {
    *raw = RawMesh();
    const PlyElement& vertex = elements[0];
    const PlyElement& face = elements[1];
    std::size_t record = 0, offset[3] = {0, 0, 0};
    int size[3] = {0, 0, 0};
    for (const PlyProperty& property : vertex.properties) {
      for (int axis = 0; axis < 3; ++axis) {
        if (property.name == std::string_view("xyz" + axis, 1)) {
          offset[axis] = record;
          size[axis] = property.type->bytes;
        }
      }
      record += static_cast<std::size_t>(property.type->bytes);
    }
    raw->positions.reserve(vertex.count);
    constexpr std::uint64_t kChunk = 1 << 16;  // records read at once
    std::vector<unsigned char> bytes(record * std::min<std::uint64_t>(vertex.count, kChunk));
    for (std::uint64_t r = 0; r < vertex.count; r += kChunk) {
      const std::uint64_t n = std::min(kChunk, vertex.count - r);
      if (!in.read_bytes(bytes.data(), record * n)) truncated(vertex, r);
      for (std::uint64_t k = 0; k < n; ++k) {
        const unsigned char* at = bytes.data() + k * record;
        raw->positions.emplace_back(decode_real(at + offset[0], size[0], big_endian),
                                    decode_real(at + offset[1], size[1], big_endian),
                                    decode_real(at + offset[2], size[2], big_endian));
      }
    }
    const PlyProperty& list = face.properties[0];
    raw->face_start.reserve(face.count + 1);
    raw->corners.reserve(3 * face.count);
    std::vector<unsigned char> entries;
    for (std::uint64_t r = 0; r < face.count; ++r) {
      unsigned char count_bytes[8];
      if (!in.read_bytes(count_bytes, list.count_type->bytes)) truncated(face, r);
      const std::int64_t count = decode_integer(count_bytes, list.count_type->bytes,
                                                list.count_type->is_signed, big_endian);
      if (count < 0) {
        throw_invalid(file, face.name + " " + std::to_string(r) + " has a negative " + list.name +
                                " count (" + std::to_string(count) + ")");
      }
      if (multiply_saturating(static_cast<std::uint64_t>(count), list.type->bytes) >
          in.remaining())
        truncated(face, r);
      // In bounded runs: a face may claim millions of corners.
      constexpr std::int64_t kRun = 4096;
      for (std::int64_t k = 0; k < count; k += kRun) {
        const std::int64_t n = std::min(kRun, count - k);
        entries.resize(static_cast<std::size_t>(n) * list.type->bytes);
        if (!in.read_bytes(entries.data(), entries.size())) truncated(face, r);
        for (std::int64_t j = 0; j < n; ++j) {
          const std::int64_t index = decode_integer(entries.data() + j * list.type->bytes,
                                                    list.type->bytes, list.type->is_signed,
                                                    big_endian);
          // Kept as an int vertex handle (one beyond int is out of range anyway).
          raw->corners.push_back(static_cast<int>(std::clamp<std::int64_t>(
              index, std::numeric_limits<int>::min(), std::numeric_limits<int>::max())));
        }
      }
      raw->face_start.push_back(raw->corners.size());
      scan.corners += static_cast<std::uint64_t>(count);
    }
    scan.read_natively = true;
    return scan;
  }

  // A layout OpenMesh's reader cannot read is read here, its vertex and face records value by
  // value.
  std::optional<PlyRecords> records;
  const auto vertex_index = static_cast<std::size_t>(vertex_element - elements.data());
  if (read_here) records.emplace(*raw, *vertex_element, elements[face_element]);
  const auto collected = [&](std::size_t i) {
    return records && (i == vertex_index || i == face_element);
  };
  const auto collect = [&](std::size_t i, std::size_t property, double value, std::int64_t index) {
    if (i == vertex_index)
      records->vertex_value(property, value);
    else
      records->face_value(property, index, value);
  };
  const auto end_record = [&](std::size_t i) {
    if (i == vertex_index)
      records->end_vertex();
    else
      records->end_face();
  };
  scan.read_natively = records.has_value();

  if (!ascii) {
    // The length of a binary list, read at its start.
    const auto list_length = [&](const PlyElement& element, std::uint64_t r,
                                 const PlyProperty& property) {
      unsigned char count_bytes[8];
      if (!in.read_bytes(count_bytes, property.count_type->bytes)) truncated(element, r);
      const std::int64_t count = decode_integer(count_bytes, property.count_type->bytes,
                                                property.count_type->is_signed, big_endian);
      if (count < 0) {
        throw_invalid(file, element.name + " " + std::to_string(r) + " has a negative " +
                                property.name + " count (" + std::to_string(count) + ")");
      }
      return count;
    };
    for (std::size_t i = 0; i < read_elements; ++i) {
      const PlyElement& element = elements[i];
      const bool has_list = std::any_of(element.properties.begin(), element.properties.end(),
                                        [](const PlyProperty& p) { return p.is_list; });
      if (collected(i)) {
        unsigned char bytes[8];
        const auto value_at = [&](const PlyType& type) {
          return type.is_float ? decode_real(bytes, type.bytes, big_endian)
                               : static_cast<double>(
                                     decode_integer(bytes, type.bytes, type.is_signed, big_endian));
        };
        for (std::uint64_t r = 0; r < element.count; ++r) {
          for (std::size_t p = 0; p < element.properties.size(); ++p) {
            const PlyProperty& property = element.properties[p];
            if (!property.is_list) {
              if (!in.read_bytes(bytes, property.type->bytes)) truncated(element, r);
              collect(i, p, value_at(*property.type), 0);
              continue;
            }
            const std::int64_t count = list_length(element, r, property);
            if (multiply_saturating(static_cast<std::uint64_t>(count), property.type->bytes) >
                in.remaining())
              truncated(element, r);
            for (std::int64_t k = 0; k < count; ++k) {
              in.read_bytes(bytes, property.type->bytes);
              if (property.is_vertex_indices)
                collect(i, p, 0.0,
                        decode_integer(bytes, property.type->bytes, property.type->is_signed,
                                       big_endian));
              else
                collect(i, p, value_at(*property.type), 0);
            }
            if (property.is_vertex_indices) scan.corners += static_cast<std::uint64_t>(count);
          }
          end_record(i);
        }
        continue;
      }
      if (!has_list) {
        std::uint64_t record = 0;
        for (const PlyProperty& property : element.properties) record += property.type->bytes;
        const std::uint64_t available = in.remaining();
        if (!in.skip(multiply_saturating(record, element.count))) {
          truncated(element, record == 0 ? 0 : available / record);
        }
        continue;
      }
      for (std::uint64_t r = 0; r < element.count; ++r) {
        for (const PlyProperty& property : element.properties) {
          if (!property.is_list) {
            if (!in.skip(property.type->bytes)) truncated(element, r);
            continue;
          }
          const std::int64_t count = list_length(element, r, property);
          if (!in.skip(
                  multiply_saturating(static_cast<std::uint64_t>(count), property.type->bytes))) {
            truncated(element, r);
          }
          if (property.is_vertex_indices) scan.corners += static_cast<std::uint64_t>(count);
        }
      }
    }
    return scan;
  }

  TokenReader tokens(in);
  std::string_view token;
  auto check_value = [&](const PlyElement& element, std::uint64_t r, const PlyProperty& property,
                         std::string_view value) {
    if (property.reading == PlyReading::as_float) {
      const NumberKind kind = classify_float(value);
      if (kind == NumberKind::non_finite) {
        throw_invalid(
            file, at_line(tokens.line()) + element.name + " " + std::to_string(r) +
                      " has a non-finite " +
                      (property.is_coordinate ? "coordinate " : "value of " + property.name + " ") +
                      in_quotes(value) + " (NaN, infinite or beyond single precision)");
      }
      if (kind == NumberKind::invalid) {
        throw_invalid(file, at_line(tokens.line()) + "expected a number for " + property.name +
                                " of " + element.name + " " + std::to_string(r) + ", got " +
                                in_quotes(value));
      }
    } else if (property.reading == PlyReading::as_integer) {
      std::int64_t integer = 0;
      if (!parse_integer(value, integer)) {
        throw_invalid(file, at_line(tokens.line()) + "expected an integer for " + property.name +
                                " of " + element.name + " " + std::to_string(r) + ", got " +
                                in_quotes(value));
      }
    }
  };
  // A value checked by check_value, for the records read here.
  const auto collect_token = [&](std::size_t i, std::size_t p, std::string_view value) {
    const PlyProperty& property = elements[i].properties[p];
    std::int64_t index = 0;
    double real = 0.0;
    if (property.is_vertex_indices)
      parse_integer(value, index);
    else
      classify_float(value, nullptr, &real);
    collect(i, p, real, index);
  };
  for (std::size_t i = 0; i < read_elements; ++i) {
    const PlyElement& element = elements[i];
    const bool collecting = collected(i);
    for (std::uint64_t r = 0; r < element.count; ++r) {
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (!tokens.next(token)) truncated(element, r);
        if (!property.is_list) {
          check_value(element, r, property, token);
          if (collecting) collect_token(i, p, token);
          continue;
        }
        std::int64_t count = 0;
        if (!parse_integer(token, count) || count < 0) {
          throw_invalid(file, at_line(tokens.line()) + "expected the length of list " +
                                  property.name + " of " + element.name + " " + std::to_string(r) +
                                  ", got " + in_quotes(token));
        }
        for (std::int64_t entry = 0; entry < count; ++entry) {
          if (!tokens.next(token)) truncated(element, r);
          check_value(element, r, property, token);
          if (collecting) collect_token(i, p, token);
        }
        if (property.is_vertex_indices) scan.corners += static_cast<std::uint64_t>(count);
      }
      if (collecting) end_record(i);
    }
  }
  if (read_elements == elements.size() && tokens.next(token)) {
    throw_invalid(file, "the header declares " + declared(scan.vertices, scan.faces) +
                            ", but more data follows at line " + std::to_string(tokens.line()) +
                            " (wrong counts?)");
  }
  return scan;
}

}  // namespace papercraft::load_internal
