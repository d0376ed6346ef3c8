// The pre-scan of an STL file, binary or ascii.

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "core/errors.h"
#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"
#include "nodes/load/prescan.h"

namespace papercraft::load_internal {
namespace {

std::string degenerate_triangles_message(std::uint64_t count, std::uint64_t first) {
  return "mesh has " + counted(count, "degenerate face", "degenerate faces") +
         " (two corners of a triangle coincide), first triangle " + std::to_string(first);
}

}  // namespace

Prescan prescan_stl(FileScanner& in, const std::string& file, const LoadOptions& options) {
  Prescan scan;
  scan.format = Format::stl;
  const std::uint64_t size = in.size();
  std::uint64_t declared_triangles = 0;
  if (size >= 84) {
    unsigned char header[84] = {};
    in.read_bytes(header, sizeof header);  // size >= 84
    declared_triangles = static_cast<std::uint64_t>(decode_integer(header + 80, 4, false, false));
  }
  std::uint64_t degenerate = 0;
  std::uint64_t first_degenerate = 0;
  // OpenMesh's test: binary exactly when the size matches, whatever the header says.
  if (size >= 84 && 84 + 50 * declared_triangles == size) {
    scan.faces = declared_triangles;
    check_some_faces(file, scan);
    check_counts(file, 0, scan.faces, options);
    unsigned char record[50] = {};
    for (std::uint64_t t = 0; t < declared_triangles; ++t) {
      if (!in.read_bytes(record, sizeof record)) {
        throw_io(file, "the file shrank while being read");
      }
      std::array<std::array<float, 3>, 3> corners{};
      for (int c = 0; c < 3; ++c) {
        for (int axis = 0; axis < 3; ++axis) {
          corners[c][axis] = decode_float_little_endian(record + 12 + 12 * c + 4 * axis);
          if (!std::isfinite(corners[c][axis])) {
            throw_invalid(file, "triangle " + std::to_string(t) +
                                    " has a non-finite coordinate (NaN or infinite)");
          }
        }
      }
      if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) {
        if (degenerate++ == 0) first_degenerate = t;
      }
    }
    if (degenerate > 0 && !options.repair)
      throw_invalid(file, degenerate_triangles_message(degenerate, first_degenerate));
    scan.dropped_faces = degenerate;
    scan.dropped_corners = 3 * degenerate;
    scan.vertices = 3 * scan.faces;
    scan.corners = 3 * scan.faces;
    return scan;
  }

  in.seek(0);
  const std::string binary_hint =
      size >= 84 ? " (if this is meant as a binary STL: its header declares " +
                       counted(declared_triangles, "triangle", "triangles") + ", which need " +
                       std::to_string(84 + 50 * declared_triangles) + " bytes, but the file has " +
                       std::to_string(size) + ")"
                 : std::string();
  std::string_view line;
  while (in.next_line(line) && trim(line).empty()) {
  }
  if (!starts_with_ignoring_case(trim(line), "solid")) {
    throw_invalid(file, "not an STL file: it does not start with 'solid' and is not a binary STL" +
                            binary_hint);
  }
  try {
    bool facet_open = false;
    bool solid_ended = false;
    while (in.next_line(line)) {
      const std::string_view content = trim(line);
      // OpenMesh takes any line containing "outer" as the start of a triangle and the next three
      // lines as its corners.
      if (content.find("outer") != std::string_view::npos ||
          content.find("OUTER") != std::string_view::npos) {
        std::array<std::array<float, 3>, 3> corners{};
        for (auto& corner : corners) {
          if (!in.next_line(line)) {
            throw_invalid(file,
                          "truncated: the file ends inside triangle " + std::to_string(scan.faces));
          }
          std::string_view rest = trim(line);
          if (!equals_ignoring_case(next_token(rest), "vertex")) {
            throw_invalid(file, at_line(in.line_number()) + "expected 'vertex x y z' in triangle " +
                                    std::to_string(scan.faces) + ", got " + in_quotes(trim(line)));
          }
          for (float& value : corner) {
            const std::string_view token = next_token(rest);
            const NumberKind kind = classify_float(token, &value);
            if (kind == NumberKind::non_finite) {
              throw_invalid(file, at_line(in.line_number()) + "triangle " +
                                      std::to_string(scan.faces) + " has a non-finite coordinate " +
                                      in_quotes(token) +
                                      " (NaN, infinite or beyond single precision)");
            }
            if (kind == NumberKind::invalid) {
              throw_invalid(file, at_line(in.line_number()) +
                                      "expected 3 coordinates after 'vertex', got " +
                                      in_quotes(trim(line)));
            }
          }
        }
        if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) {
          if (degenerate++ == 0) first_degenerate = scan.faces;
        }
        if (++scan.faces > options.max_faces) check_counts(file, 0, scan.faces, options);
      } else if (starts_with_ignoring_case(content, "endsolid")) {
        solid_ended = true;
      } else if (starts_with_ignoring_case(content, "solid")) {
        solid_ended = false;
      } else if (starts_with_ignoring_case(content, "endfacet")) {
        facet_open = false;
      } else if (starts_with_ignoring_case(content, "facet")) {
        facet_open = true;
      }
    }
    if (facet_open) {
      throw_invalid(file, "truncated: the file ends inside triangle " +
                              std::to_string(scan.faces > 0 ? scan.faces - 1 : 0) +
                              " (expected 'endfacet')");
    }
    if (!solid_ended) {
      throw_invalid(file, "truncated: expected 'endsolid' after triangle " +
                              std::to_string(scan.faces > 0 ? scan.faces - 1 : 0));
    }
  } catch (const InvalidInputException& error) {
    throw InvalidInputException(error.what() + binary_hint);
  }
  check_some_faces(file, scan);
  if (degenerate > 0 && !options.repair)
    throw_invalid(file, degenerate_triangles_message(degenerate, first_degenerate));
  scan.dropped_faces = degenerate;
  scan.dropped_corners = 3 * degenerate;
  scan.vertices = 3 * scan.faces;
  scan.corners = 3 * scan.faces;
  return scan;
}

}  // namespace papercraft::load_internal
