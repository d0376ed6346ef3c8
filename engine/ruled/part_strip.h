#pragma once
// The twist-minimising strip of a part: twist_minimizing_strip between two boundaries of the
// part (twist_dp.h), facing the way the part does.

#include <vector>

#include "core/mesh.h"
#include "core/strip.h"
#include "engine/ruled/twist_dp.h"

namespace papercraft {

/// The strip between `a` and `b`, the polylines of `part`'s vertices `first` and `second`
/// (a boundary loop, or a single vertex, each; as select_geodesic gives them), with its
/// triangles facing the way `part`'s do: on every boundary edge of `part` that the strip
/// shares, the strip's edge runs the way the part's face-side half-edge does.
///
/// twist_minimizing_strip orients a strip by A. So a strip from a loop taken the other way
/// round the part, or from a single vertex to a loop, faces the other way all over; it is
/// turned over (otherwise it unfolds into the mirror image of its piece, whose seams run the
/// same way as their partners'). And between two loops, the cheaper traversal of B can be the
/// one that turns the strip inside out between A and B (a narrow band, where either twists
/// little): its A side faces one way, its B side the other, and its piece would show its back
/// along B. The traversal that faces one way all over is taken then, whatever its twist.
RuledStrip part_strip(const Mesh& part, const std::vector<int>& first, const Polyline& a,
                      const std::vector<int>& second, const Polyline& b,
                      const TwistOptions& options = {});

}  // namespace papercraft
