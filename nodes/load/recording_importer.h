#pragma once
// Step 2 of loading: OpenMesh's reader fills a recording importer that keeps the raw vertex
// positions, face index lists and texture coordinates, dropping nothing.

#include <filesystem>
#include <string>

#include "nodes/load/prescan.h"
#include "nodes/load/raw_mesh.h"

namespace papercraft::load_internal {

/// Reads the file with OpenMesh's reader (serialised: its readers are process-wide singletons);
/// an ascii OFF with comments or face extras goes through a cleaned temporary copy.
/// \throws IOException when the reader fails or the cleaned copy cannot be written.
RawMesh read_with_openmesh(const std::filesystem::path& path, const std::string& file,
                           const Prescan& scan);

}  // namespace papercraft::load_internal
