#pragma once

#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// How much the cut curves between parts bend: the total turning angle of the curves divided
/// by their total length (radians per model unit; 0 when there is no cut curve). A cut edge is
/// a boundary edge found in two parts (matched by bit-identical end points, as segmentations
/// and cuts produce); boundary edges found once (the input's own boundaries) are left out. The
/// turning at a vertex joining exactly two cut edges is the angle between their directions;
/// vertices where curves end or meet (three or more parts) add nothing. A straight line scores
/// 0, a circle of radius r 1/r, a staircase of triangle edges much more than the curve it follows.
/// \pre every part is a valid triangle mesh without deleted elements.
double boundary_turning_per_length(const std::vector<Mesh>& parts);

}  // namespace papercraft
