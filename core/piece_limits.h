#pragma once
// What a person can cut and glue, as the refinement judges the pieces its cuts make: a piece
// at least `min_width` wide over all but its tips and at least `min_area` large (both in
// model units, from min_width_mm, min_area_mm2 and the print scale).

#include <string>

#include "core/mesh.h"

namespace papercraft {

struct PieceLimits {
  double min_width = 0.0;  // 0: no bound
  double min_area = 0.0;   // 0: no bound
  /// Share of a piece's area allowed to be narrower than min_width: its tips (the apex of a
  /// cone, the corners where cuts meet) and nothing more.
  double max_narrow_share = 0.5;
  /// A tail: the share above lets a wide piece carry a long thin band (an iso-line that runs
  /// close to the boundary for a while leaves one), which the share does not see. So one
  /// connected region narrower than sliver_width (a share of min_width) may cover at most
  /// max_sliver_area times sliver_width squared: a tip is about as long as it is wide, a
  /// sliver many times. At the defaults (5 mm): no region under 3 mm of more than 72 mm^2.
  /// max_sliver_area 0: no bound.
  double sliver_width = 0.6;
  double max_sliver_area = 8.0;

  bool active() const { return min_width > 0.0 || min_area > 0.0; }
};

/// How far a piece is from what the limits ask: 0 when it meets them, else the largest of the
/// area it lacks (as a share of min_area), the narrow share it has beyond max_narrow_share
/// (as a share of what is left above it) and the part of its largest sliver beyond the bound
/// (as a share of the sliver). Ranks the cuts that cannot meet the limits.
double piece_shortfall(const Mesh& piece, const PieceLimits& limits);

/// piece_shortfall(piece, limits) == 0.
bool piece_fits(const Mesh& piece, const PieceLimits& limits);

}  // namespace papercraft
