#pragma once
// Parts of a flat strip's triangles: a subset as a strip of its own, a triangle's key by its
// 3D corners, and whether the triangles round a vertex form one fan.

#include <array>
#include <vector>

#include "core/strip.h"

namespace papercraft::merge_detail {

/// The triangles `chosen` of `strip` as a strip of their own, laid out as they lie, their
/// vertices renumbered (unused ones dropped); its boundary left empty without `with_boundary`.
FlatStrip sub_strip(const FlatStrip& strip, const std::vector<Triangle>& chosen,
                    bool with_boundary = true);

/// Triangle `t` of `strip` by its 3D corners, sorted: the same key wherever a triangle on those
/// points is printed.
std::array<double, 9> corners_key(const FlatStrip& strip, const Triangle& t);

/// Whether the triangles around `vertex` form one fan (each joined to the next across an
/// edge), not two fans meeting at a point.
bool one_fan(const std::vector<Triangle>& triangles, int vertex);

}  // namespace papercraft::merge_detail
