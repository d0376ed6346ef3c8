#pragma once
// Dividing large flat triangles, so that a strip larger than a page can be cut across its
// triangles: a coarse mesh (a cube of 12 triangles) printed large has triangles no page holds
// two of, and a strip of them can be split only at its few inner edges.

#include <vector>

#include "core/strip.h"

namespace papercraft::layout_internal {

/// Every triangle of every strip divided into n x n similar triangles (each edge in n equal
/// parts, corners first in their own order, so the surface, its flat image and its uvs are
/// unchanged). A boundary edge becomes n edges of the same kind and label, in order, and a
/// seam's n parts are the partners of the n parts of its partner edge, last to first: both
/// sides of every seam get the same points. n <= 1 returns the strips as they are.
std::vector<FlatStrip> divide_triangles(const std::vector<FlatStrip>& strips, int n);

}  // namespace papercraft::layout_internal
