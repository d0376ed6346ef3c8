#pragma once
// Two neighbouring pieces of one model refined again as one: where the refinement cut a piece
// too small to handle from its neighbour, the two glued back along their shared cut may be one
// strip within the tolerance after all (the cut was made higher up, where the whole was not):
// glue_pieces here, then one_strip_of (refine.h) on the union.

#include <optional>

#include "core/mesh.h"

namespace papercraft {

/// `a` and `b` glued into one mesh along the boundary they share: vertices of both boundaries
/// at the same 3D point (bit for bit, as a cut leaves its two sides) become one. Keeps the
/// input-vertex property and texture coordinates (when both have them). nullopt when they share
/// no boundary edge or glued they are not a manifold surface.
std::optional<Mesh> glue_pieces(const Mesh& a, const Mesh& b);

}  // namespace papercraft
