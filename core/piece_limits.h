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

  bool active() const { return min_width > 0.0 || min_area > 0.0; }
};

/// How far a piece is from what the limits ask: 0 when it meets them, else the larger of the
/// area it lacks (as a share of min_area) and the narrow share it has beyond
/// max_narrow_share. Ranks the cuts that cannot meet the limits.
double piece_shortfall(const Mesh& piece, const PieceLimits& limits);

/// piece_shortfall(piece, limits) == 0.
bool piece_fits(const Mesh& piece, const PieceLimits& limits);

}  // namespace papercraft
