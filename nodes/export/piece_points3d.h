#pragma once
// Where each vertex of a printed piece lies on the 3D model.

#include <vector>

#include "core/pattern.h"
#include "core/strip.h"

namespace papercraft {

/// The 3D point (model units) of every vertex of `piece`, in the order of its `vertices`:
/// PlacedPiece::points3d where it holds one per vertex (a layout that divided the strip's
/// triangles added points no strip vertex has), else the strip's vertices3d through
/// strip_vertex.
/// \pre `strip` is the flat strip the piece was cut from (strip.id == piece.strip_id).
/// \throws InvalidInputException if a strip vertex index is out of range.
std::vector<Vec3> piece_points3d(const PlacedPiece& piece, const FlatStrip& strip);

}  // namespace papercraft
