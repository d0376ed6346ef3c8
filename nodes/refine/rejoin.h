#pragma once
// Two neighbouring pieces of one model refined again as one: where the refinement cut a piece
// too small to handle from its neighbour, the two glued back along their shared cut may be one
// strip within the tolerance after all (the cut was made higher up, where the whole was not).

#include <optional>

#include "core/mesh.h"
#include "core/strip.h"
#include "nodes/refine/refine.h"

namespace papercraft {

/// `a` and `b` glued into one mesh along the boundary they share: vertices of both boundaries
/// at the same 3D point (bit for bit, as a cut leaves its two sides) become one. Keeps the
/// input-vertex property and texture coordinates (when both have them). nullopt when they share
/// no boundary edge or glued they are not a manifold surface.
std::optional<Mesh> glue_pieces(const Mesh& a, const Mesh& b);

/// A piece refined as one strip, and that strip unfolded.
struct JoinedStrip {
  RefinedStrip refined;
  FlatStrip flat;  // ids 0: the caller numbers it
};

/// The strip of `piece` where it is one strip within `tolerance` (select, ruled and decide
/// accept it; certified where the decision is) that unfolds into one flat strip without
/// overlapping itself, and has no hole left over; nullopt otherwise.
std::optional<JoinedStrip> one_strip_of(const Mesh& piece, double tolerance,
                                        const RefineOptions& options);

}  // namespace papercraft
