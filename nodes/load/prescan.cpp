// The checks every pre-scan shares: declared counts against the limits, against the file size,
// and a file without faces.

#include "nodes/load/prescan.h"

#include <climits>

#include "nodes/load/messages.h"

namespace papercraft::load_internal {

Prescan natively_read(Format format, const RawMesh& raw, const std::string& file,
                      const LoadOptions& options) {
  Prescan scan;
  scan.format = format;
  scan.read_natively = true;
  scan.vertices = raw.positions.size();
  scan.faces = raw.n_faces();
  scan.corners = raw.corners.size();
  check_counts(file, scan.vertices, scan.faces, options);
  return scan;
}

void check_counts(const std::string& file, std::uint64_t vertices, std::uint64_t faces,
                  const LoadOptions& options) {
  if (faces > options.max_faces) {
    throw_invalid(file, "declares " + counted(faces, "face", "faces") +
                            ", more than the limit of " + std::to_string(options.max_faces) +
                            " (LoadOptions::max_faces)");
  }
  if (vertices > static_cast<std::uint64_t>(INT_MAX) - 1) {
    throw_invalid(file, "declares " + counted(vertices, "vertex", "vertices") +
                            ", more than OpenMesh can index");
  }
}

void check_room(const std::string& file, const std::string& what, std::uint64_t needed,
                std::uint64_t available) {
  if (needed > available) {
    throw_invalid(file, "truncated or corrupt header: it declares " + what +
                            ", which need at least " + std::to_string(needed) +
                            " bytes, but only " + std::to_string(available) +
                            " bytes follow the header");
  }
}

void check_some_faces(const std::string& file, const Prescan& scan) {
  if (scan.faces > 0) return;
  throw_invalid(
      file, "mesh has no faces" + (scan.vertices > 0
                                       ? " (only " + counted(scan.vertices, "vertex", "vertices") +
                                             ": a point cloud?)"
                                       : std::string()));
}

}  // namespace papercraft::load_internal
