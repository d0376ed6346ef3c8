// The pre-scan of an OBJ file.

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"
#include "nodes/load/prescan.h"

namespace papercraft::load_internal {

Prescan prescan_obj(FileScanner& in, const std::string& file, const std::filesystem::path& path,
                    const LoadOptions& options) {
  Prescan scan;
  scan.format = Format::obj;
  std::uint64_t degenerate = 0;
  std::uint64_t first_degenerate_line = 0;
  std::vector<std::int64_t> face;
  std::string_view line;
  std::string joined;  // a statement continued over several lines, without the backslashes
  while (in.next_line(line)) {
    // A line ending in a backslash goes on on the next (Rhino writes long faces so): the
    // statement is read whole, and messages name the line it starts on.
    const std::uint64_t line_number = in.line_number();
    if (ends_in_backslash(line)) {
      joined.clear();
      std::string_view part = line;
      while (ends_in_backslash(part)) {
        const std::string_view body = trim(part);
        joined.append(body.substr(0, body.size() - 1)).push_back(' ');
        ++scan.obj_continuations;
        if (!in.next_line(part)) {
          part = {};
          break;
        }
      }
      joined.append(part);
      line = joined;
    }
    std::string_view rest = trim(line);
    if (rest.empty() || rest.front() == '#') continue;
    const std::string_view keyword = next_token(rest);
    if (keyword == "v") {
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view token = next_token(rest);
        const NumberKind kind = classify_float(token);
        if (kind == NumberKind::non_finite) {
          throw_invalid(file, at_line(line_number) + "vertex " + std::to_string(scan.vertices) +
                                  " has a non-finite coordinate " + in_quotes(token) +
                                  " (NaN, infinite or beyond single precision)");
        }
        if (kind == NumberKind::invalid) {
          throw_invalid(file, at_line(line_number) + "expected 3 coordinates after 'v', got " +
                                  in_quotes(trim(line)));
        }
      }
      ++scan.vertices;
    } else if (keyword == "vt") {
      for (int axis = 0; axis < 2; ++axis) {
        const std::string_view token = next_token(rest);
        const NumberKind kind = classify_float(token);
        if (kind != NumberKind::finite) {
          throw_invalid(file, at_line(line_number) +
                                  "expected 2 finite texture coordinates after 'vt', got " +
                                  in_quotes(trim(line)));
        }
      }
    } else if (keyword == "f") {
      face.clear();
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
        std::int64_t index = 0;
        if (!parse_integer(token.substr(0, token.find('/')), index) || index == 0) {
          throw_invalid(file, at_line(line_number) + "bad vertex reference " + in_quotes(token) +
                                  " in a face (expected a non-zero vertex number, optionally "
                                  "followed by /texcoord/normal)");
        }
        // Negative references count back from the vertices read so far, as in OpenMesh.
        face.push_back(index < 0 ? static_cast<std::int64_t>(scan.vertices) + index : index - 1);
      }
      std::vector<std::int64_t> sorted = face;
      std::sort(sorted.begin(), sorted.end());
      const auto distinct =
          static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
      // OpenMesh silently drops a face with fewer than 3 distinct vertices (no area: with the
      // repair, logged) and shrinks one that repeats a vertex (but not its texture coordinates).
      if (distinct < 3 && options.repair) {
        ++scan.dropped_faces;
        scan.dropped_corners += face.size();
      } else if (distinct < face.size() || face.size() < 3) {
        if (degenerate++ == 0) first_degenerate_line = line_number;
      }
      ++scan.faces;
      scan.corners += face.size();
    } else if (keyword == "mtllib" && scan.material_library.empty()) {
      const std::string_view name = trim(rest);
      if (!name.empty()) scan.material_library = path.parent_path() / std::string(name);
    }
  }
  if (degenerate > 0) {
    throw_invalid(file, "mesh has " + counted(degenerate, "degenerate face", "degenerate faces") +
                            " (a vertex repeated or fewer than 3 vertices), first at line " +
                            std::to_string(first_degenerate_line));
  }
  check_some_faces(file, scan);
  check_counts(file, scan.vertices, scan.faces, options);
  return scan;
}

}  // namespace papercraft::load_internal
