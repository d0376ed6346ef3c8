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
#include "nodes/load/ply_format.h"
#include "nodes/load/prescan.h"

namespace papercraft::load_internal {
namespace {

constexpr std::size_t kMaxPlyHeaderLines = 100'000;

constexpr PlyType kPlyTypes[] = {
    {"char", 1, false, true},    {"int8", 1, false, true},    {"uchar", 1, false, false},
    {"uint8", 1, false, false},  {"short", 2, false, true},   {"int16", 2, false, true},
    {"ushort", 2, false, false}, {"uint16", 2, false, false}, {"int", 4, false, true},
    {"int32", 4, false, true},   {"uint", 4, false, false},   {"uint32", 4, false, false},
    {"float", 4, true, true},    {"float32", 4, true, true},  {"double", 8, true, true},
    {"float64", 8, true, true},
};

}  // namespace

const PlyType* find_ply_type(std::string_view name) {
  for (const PlyType& type : kPlyTypes) {
    if (type.name == name) return &type;
  }
  return nullptr;
}

namespace {

// What a PLY header says, and how its records are to be read.
struct PlyHeader {
  std::vector<PlyElement> elements;
  std::string format;
  bool big_endian = false;
  bool read_here = false;  // a layout OpenMesh's reader cannot read: the pre-scan reads it
};

// The header line `property ...` (its `tokens` after the keyword) added to the last element,
// checked as OpenMesh's reader will read it. `collect_texcoords`: the pre-scan reads the
// records (MeshLab's per-face texture coordinates then make it read them itself).
void add_ply_property(PlyHeader& header, const std::vector<std::string_view>& tokens,
                      std::string_view content, const std::string& where, bool collect_texcoords,
                      const std::string& file) {
  std::vector<PlyElement>& elements = header.elements;
  const std::string& format = header.format;
  bool& read_here = header.read_here;
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
        collect_texcoords && element.name == "face" && property.name == "texcoord";
    if (face_texcoords) {
      if (!property.type->is_float) {
        throw_invalid(
            file, where + "texture coordinates must have a real type, got " + in_quotes(tokens[2]));
      }
      property.reading = PlyReading::as_float;
      read_here = true;
      element.properties.push_back(std::move(property));
      return;
    }
    if (!property.is_vertex_indices) {
      throw_invalid(file, where + "list property " + in_quotes(property.name) + " of element " +
                              in_quotes(element.name) +
                              " is not supported (OpenMesh's PLY reader can only read the "
                              "face's vertex_indices list)");
    }
    if (property.type->is_float) {
      throw_invalid(
          file, where + "vertex indices must have an integer type, got " + in_quotes(tokens[2]));
    }
    property.reading = PlyReading::as_integer;
  } else {
    if (tokens.size() != 2) {
      throw_invalid(file, where + "expected 'property <type> <name>', got " + in_quotes(content));
    }
    property.name = std::string(tokens[1]);
    property.type = find_ply_type(tokens[0]);
    if (property.type == nullptr) {
      throw_invalid(file, where + "unknown property type " + in_quotes(tokens[0]));
    }
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    property.is_coordinate = is_vertex && is_one_of(property.name, {"x", "y", "z"});
    const bool read_as_float = is_vertex && is_one_of(property.name, {"x", "y", "z", "nx", "ny",
                                                                      "nz", "u", "v", "s", "t"});
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
}

// The header up to end_header: format, elements and properties checked, the texture file of
// a TextureFile comment into scan.ply_texture.
PlyHeader read_ply_header(FileScanner& in, const std::string& file, bool collect_texcoords,
                          Prescan& scan) {
  PlyHeader header;
  std::vector<PlyElement>& elements = header.elements;
  std::string& format = header.format;
  bool& big_endian = header.big_endian;
  bool& read_here = header.read_here;
  // The header's bytes as read, to find where OpenMesh's reader will look for binary data.
  std::string header_bytes;
  std::size_t openmesh_position = 0;  // where OpenMesh's `tellg` is before it reads a keyword
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
      add_ply_property(header, tokens, content, where, collect_texcoords, file);
      continue;
    }
    throw_invalid(file, where + "unknown PLY header keyword " + in_quotes(keyword));
  }
  if (!ended) {
    throw_invalid(file, "truncated: the PLY header has no end_header");
  }
  return header;
}

}  // namespace

Prescan prescan_ply(FileScanner& in, const std::string& file, const LoadOptions& options,
                    RawMesh* raw) {
  Prescan scan;
  scan.format = Format::ply;
  const PlyHeader header = read_ply_header(in, file, raw != nullptr, scan);
  const std::vector<PlyElement>& elements = header.elements;

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

  const bool ascii = header.format == "ascii";
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

  if (!ascii && raw != nullptr && plain_binary_ply(elements, read_elements)) {
    read_plain_binary_ply(in, file, elements, header.big_endian, raw, scan);
    return scan;
  }
  // A layout OpenMesh's reader cannot read is read here, its vertex and face records value by
  // value.
  scan_ply_records(in, file, elements, ascii, header.big_endian, read_elements,
                   static_cast<std::size_t>(vertex_element - elements.data()), face_element,
                   header.read_here, raw, scan);
  return scan;
}

}  // namespace papercraft::load_internal
