#pragma once
// The PLY header's elements and properties as the pre-scan (prescan_ply.cpp) reads them, and the
// reading of their records (ply_records.cpp).

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "nodes/load/prescan.h"

namespace papercraft::load_internal {

struct PlyType {
  std::string_view name;
  int bytes;
  bool is_float;
  bool is_signed;
};

/// The type named `name` (char, uchar, int8, ..., float64); null for none.
const PlyType* find_ply_type(std::string_view name);

/// How OpenMesh's ascii PLY reader consumes a value: as a float, as an int, or as a string.
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

inline bool is_one_of(std::string_view name, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// Whether the pre-scan reads a binary PLY itself at once (read_plain_binary_ply): a vertex
/// element of scalar positions (and normals, which nothing uses) followed by a face element with
/// only its vertex index list. Anything else (colours, texture coordinates, other elements
/// before the faces) goes to OpenMesh's reader.
bool plain_binary_ply(const std::vector<PlyElement>& elements, std::size_t read_elements);

/// A plain binary PLY read into `raw` at once: positions, faces, scan.corners.
/// \throws InvalidInputException where the data ends early or a list count is negative.
void read_plain_binary_ply(FileScanner& in, const std::string& file,
                           const std::vector<PlyElement>& elements, bool big_endian, RawMesh* raw,
                           Prescan& scan);

/// The records of the first `read_elements` elements, binary (of `big_endian`) or ascii, checked
/// as OpenMesh's reader will read them and their corners counted. With `read_here` (a layout
/// OpenMesh's reader cannot read), the vertex and face records go into `raw` (PlyRecords).
/// \throws InvalidInputException where the data ends early, a value does not read as its
///         property's type says, or (ascii) more data follows the last element.
void scan_ply_records(FileScanner& in, const std::string& file,
                      const std::vector<PlyElement>& elements, bool ascii, bool big_endian,
                      std::size_t read_elements, std::size_t vertex_index, std::size_t face_element,
                      bool read_here, RawMesh* raw, Prescan& scan);

}  // namespace papercraft::load_internal
