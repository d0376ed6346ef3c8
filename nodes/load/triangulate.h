#pragma once
// Step 3 of loading, first part: the file's faces as triangles. A polygon becomes a fan from its
// first corner, or is ear-clipped where a fan would fold over.

#include <string>
#include <vector>

#include "nodes/load/openmesh.h"
#include "nodes/load/recording_importer.h"
#include "nodes/load/soup.h"

namespace papercraft::load_internal {

/// Fan triangulation with texture coordinates; polygons a fan would fold over are ear-clipped;
/// where that fails too (self-intersecting), a quad is split along the diagonal that folds
/// least, and a larger polygon refused. Moves raw.positions into the soup and
/// adds one line per change to `repairs`.
/// \pre check_raw_faces(raw) passed; with `with_uvs`, raw.corner_uv has one UV per corner.
/// \throws InvalidInputException for a self-intersecting polygon of 5 or more corners or more
///   than options.max_faces
///   triangles.
Soup triangulate(RawMesh& raw, bool with_uvs, const LoadOptions& options, const std::string& file,
                 std::vector<std::string>& repairs);

}  // namespace papercraft::load_internal
