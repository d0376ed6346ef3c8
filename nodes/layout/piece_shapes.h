#pragma once
// A piece's triangles and accepted tab slices in millimetres with their boxes: what tabs
// and labels are tested against so they stay off (or on) their own piece.

#include <array>
#include <vector>

#include "nodes/layout/pieces.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {

/// Triangles of a piece in mm with their boxes, for collision tests.
struct PieceShapes {
  std::vector<std::array<Vec2, 3>> triangles;
  std::vector<Box2> triangle_boxes;
  std::vector<std::vector<Vec2>> slices;  // convex slices of accepted flaps
  std::vector<Box2> slice_boxes;
};

/// The triangles of `piece` (no slices yet).
PieceShapes piece_shapes(const StripData& data, const Piece& piece);

/// True when a convex slice overlaps a triangle or an accepted slice deeper than `depth`.
bool slices_collide(const std::vector<std::vector<Vec2>>& slices, const PieceShapes& shapes,
                    double depth);

/// A text box lies on the piece: its corners and edge midpoints are on triangles of it.
bool box_on_piece(const std::array<Vec2, 4>& box, const PieceShapes& shapes);

}  // namespace papercraft::layout_internal
