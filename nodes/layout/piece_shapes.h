#pragma once
// A piece's triangles and accepted tab slices in millimetres with their boxes: what tabs
// and labels are tested against so they stay off (or on) their own piece.

#include <array>
#include <utility>
#include <vector>

#include "nodes/layout/pieces.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {

/// Triangles of a piece in mm with their boxes, for collision tests; the triangles are also
/// kept in square buckets (`bucket_mm`), so a test near a point looks at few of them.
struct PieceShapes {
  std::vector<std::array<Vec2, 3>> triangles;
  std::vector<Box2> triangle_boxes;
  std::vector<std::vector<Vec2>> slices;  // convex slices of accepted flaps
  std::vector<Box2> slice_boxes;

  double bucket_mm = 4.0;
  Box2 bounds;  // of the triangles
  int columns = 0, rows = 0;
  std::vector<std::vector<int>> buckets;  // triangle indices, row by row

  /// Calls f(t) for every triangle t whose bucket meets `box` (a triangle may come more
  /// than once, once per bucket).
  template <class F>
  void near(const Box2& box, F f) const {
    if (buckets.empty() || !(box.lo.x() <= bounds.hi.x() && bounds.lo.x() <= box.hi.x() &&
                             box.lo.y() <= bounds.hi.y() && bounds.lo.y() <= box.hi.y()))
      return;
    const auto [c0, r0] = bucket(box.lo);
    const auto [c1, r1] = bucket(box.hi);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        for (int t : buckets[static_cast<std::size_t>(r) * columns + c]) f(t);
  }

  std::pair<int, int> bucket(const Vec2& p) const {
    const int c = static_cast<int>((p.x() - bounds.lo.x()) / bucket_mm);
    const int r = static_cast<int>((p.y() - bounds.lo.y()) / bucket_mm);
    return {c < 0 ? 0 : c >= columns ? columns - 1 : c, r < 0 ? 0 : r >= rows ? rows - 1 : r};
  }
};

/// The triangles of `piece` (no slices yet).
PieceShapes piece_shapes(const StripData& data, const Piece& piece);

/// True when the convex polygon (n corners) overlaps a triangle of the piece deeper than
/// `depth` (convex_overlap), testing only the triangles near it.
bool overlaps_triangles(const Vec2* polygon, int n, const PieceShapes& shapes, double depth);

/// True when a convex slice overlaps a triangle or an accepted slice deeper than `depth`.
bool slices_collide(const std::vector<std::vector<Vec2>>& slices, const PieceShapes& shapes,
                    double depth);

/// A text box lies on the piece: its corners and edge midpoints are on triangles of it.
bool box_on_piece(const std::array<Vec2, 4>& box, const PieceShapes& shapes);

}  // namespace papercraft::layout_internal
