#pragma once
// parts.ply: the parts of a segmentation in one PLY file, each face coloured by its part, to
// look at a segmentation (scripts/render_parts.py draws it to a PNG).

#include <array>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// The colour of part `index`: hues spread by the golden ratio, so neighbouring indices differ.
std::array<unsigned char, 3> part_colour(int index);

/// ASCII PLY of all parts: their vertices one after another (a shared boundary vertex appears
/// once per part), faces with the int property "part" and their part's colour.
std::string parts_ply(const std::vector<Mesh>& parts);

}  // namespace papercraft
