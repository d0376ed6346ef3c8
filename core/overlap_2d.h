#pragma once
// Overlap tests between flat (2D) triangles, shared by `unfold` (a new flat strip where the
// next triangle would overlap) and `merge` (a union must not overlap itself).

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft {

using Triangle2 = std::array<Vec2, 3>;

/// Depth by which the interiors of two 2D triangles overlap: the smallest overlap of their
/// projections onto the six unit edge normals (separating axis theorem; for convex polygons
/// this is the length of the minimum translation that separates them). <= 0 when they are
/// disjoint or only touch (shared edge, shared vertex); 0 when either has no interior
/// (a zero-length edge or zero area). Either orientation is accepted.
double triangle_penetration(const Triangle2& p, const Triangle2& q);

/// A uniform grid over 2D triangles answering "does this triangle overlap a stored one by
/// more than a tolerance?" without testing all pairs. A triangle is stored in every cell
/// its bounding box touches; one whose box covers too many cells goes to a list tested
/// against every query instead.
class TriangleGrid2 {
 public:
  /// \pre cell_size > 0 and finite. \throws InvalidInputException otherwise.
  explicit TriangleGrid2(double cell_size);

  void insert(const Triangle2& triangle);

  /// True if `triangle` penetrates a stored triangle deeper than `tolerance`
  /// (triangle_penetration > tolerance).
  bool overlaps(const Triangle2& triangle, double tolerance);

  std::size_t size() const { return triangles_.size(); }

 private:
  std::array<std::int64_t, 4> cell_range(const Triangle2& triangle) const;
  static std::int64_t key(std::int64_t ix, std::int64_t iy) {
    return (ix << 32) ^ (iy & 0xffffffff);
  }

  double cell_size_;
  std::vector<Triangle2> triangles_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
  std::vector<int> oversized_;
  std::vector<std::uint32_t> stamp_;  // query stamp per triangle, avoids testing one twice
  std::uint32_t query_ = 0;
};

}  // namespace papercraft
