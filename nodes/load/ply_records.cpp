// The records of a PLY file after its header: read at once where plain binary, else value by
// value, checked as OpenMesh's reader will read them, and collected where the pre-scan reads
// them itself.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"
#include "nodes/load/ply_format.h"

namespace papercraft::load_internal {
namespace {

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

// Throws for data that ends in record `record` of `element`.
[[noreturn]] void throw_truncated(const std::string& file, const Prescan& scan,
                                  const PlyElement& element, std::uint64_t record) {
  throw_invalid(file, "truncated: the header declares " + declared(scan.vertices, scan.faces) +
                          ", but the data ends in " + element.name + " " + std::to_string(record) +
                          " (of " + std::to_string(element.count) + ")");
}

// The records the pre-scan reads itself (PlyRecords), where it does: the vertex and the face
// element's.
struct PlyCollector {
  std::optional<PlyRecords> records;
  std::size_t vertex_index = 0, face_element = 0;
  bool collected(std::size_t i) const {
    return records && (i == vertex_index || i == face_element);
  }
  void collect(std::size_t i, std::size_t property, double value, std::int64_t index) {
    if (i == vertex_index)
      records->vertex_value(property, value);
    else
      records->face_value(property, index, value);
  }
  void end_record(std::size_t i) {
    if (i == vertex_index)
      records->end_vertex();
    else
      records->end_face();
  }
};

// The binary records of the first `read_elements` elements: skipped, or collected, corners
// counted.
void scan_binary_ply(FileScanner& in, const std::string& file,
                     const std::vector<PlyElement>& elements, bool big_endian,
                     std::size_t read_elements, PlyCollector& collector, Prescan& scan) {
  const auto truncated = [&](const PlyElement& element, std::uint64_t record) {
    throw_truncated(file, scan, element, record);
  };
  const auto collected = [&](std::size_t i) { return collector.collected(i); };
  const auto collect = [&](std::size_t i, std::size_t property, double value, std::int64_t index) {
    collector.collect(i, property, value, index);
  };
  const auto end_record = [&](std::size_t i) { collector.end_record(i); };
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
}

// The ascii records of the first `read_elements` elements: every value checked as OpenMesh's
// reader will read it, collected where the pre-scan reads them, corners counted.
void scan_ascii_ply(FileScanner& in, const std::string& file,
                    const std::vector<PlyElement>& elements, std::size_t read_elements,
                    PlyCollector& collector, Prescan& scan) {
  const auto truncated = [&](const PlyElement& element, std::uint64_t record) {
    throw_truncated(file, scan, element, record);
  };
  const auto collected = [&](std::size_t i) { return collector.collected(i); };
  const auto collect = [&](std::size_t i, std::size_t property, double value, std::int64_t index) {
    collector.collect(i, property, value, index);
  };
  const auto end_record = [&](std::size_t i) { collector.end_record(i); };
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
}

}  // namespace

bool plain_binary_ply(const std::vector<PlyElement>& elements, std::size_t read_elements) {
  if (read_elements != 2 || elements[0].name != "vertex" || elements[1].name != "face")
    return false;
  for (const PlyProperty& property : elements[0].properties)
    if (property.is_list || !is_one_of(property.name, {"x", "y", "z", "nx", "ny", "nz"}))
      return false;
  return elements[1].properties.size() == 1 && elements[1].properties[0].is_vertex_indices;
}

void read_plain_binary_ply(FileScanner& in, const std::string& file,
                           const std::vector<PlyElement>& elements, bool big_endian, RawMesh* raw,
                           Prescan& scan) {
  const auto truncated = [&](const PlyElement& element, std::uint64_t record) {
    throw_truncated(file, scan, element, record);
  };
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
    const std::int64_t count =
        decode_integer(count_bytes, list.count_type->bytes, list.count_type->is_signed, big_endian);
    if (count < 0) {
      throw_invalid(file, face.name + " " + std::to_string(r) + " has a negative " + list.name +
                              " count (" + std::to_string(count) + ")");
    }
    if (multiply_saturating(static_cast<std::uint64_t>(count), list.type->bytes) > in.remaining())
      truncated(face, r);
    // In bounded runs: a face may claim millions of corners.
    constexpr std::int64_t kRun = 4096;
    for (std::int64_t k = 0; k < count; k += kRun) {
      const std::int64_t n = std::min(kRun, count - k);
      entries.resize(static_cast<std::size_t>(n) * list.type->bytes);
      if (!in.read_bytes(entries.data(), entries.size())) truncated(face, r);
      for (std::int64_t j = 0; j < n; ++j) {
        const std::int64_t index =
            decode_integer(entries.data() + j * list.type->bytes, list.type->bytes,
                           list.type->is_signed, big_endian);
        // Kept as an int vertex handle (one beyond int is out of range anyway).
        raw->corners.push_back(static_cast<int>(std::clamp<std::int64_t>(
            index, std::numeric_limits<int>::min(), std::numeric_limits<int>::max())));
      }
    }
    raw->face_start.push_back(raw->corners.size());
    scan.corners += static_cast<std::uint64_t>(count);
  }
  scan.read_natively = true;
}

void scan_ply_records(FileScanner& in, const std::string& file,
                      const std::vector<PlyElement>& elements, bool ascii, bool big_endian,
                      std::size_t read_elements, std::size_t vertex_index, std::size_t face_element,
                      bool read_here, RawMesh* raw, Prescan& scan) {
  PlyCollector collector;
  collector.vertex_index = vertex_index;
  collector.face_element = face_element;
  if (read_here) collector.records.emplace(*raw, elements[vertex_index], elements[face_element]);
  scan.read_natively = collector.records.has_value();
  if (!ascii)
    scan_binary_ply(in, file, elements, big_endian, read_elements, collector, scan);
  else
    scan_ascii_ply(in, file, elements, read_elements, collector, scan);
}

}  // namespace papercraft::load_internal
