#pragma once
// Pieces onto pages: the tightest box of a piece with everything printed round it, the piece
// turned from its strip frame into page millimetres, the page's footer, and LayoutStats.

#include <array>
#include <vector>

#include "core/pattern.h"
#include "nodes/layout/layout_types.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {

/// A piece's tightest box (its triangles, flaps and the text printed beside it) and whether
/// it fits the printable area in some orientation.
struct Orientation {
  OrientedBox box;
  bool fits = true;
};

/// The boxes of the texts printed beside the piece (PieceLabel::outside) and of leader lines.
std::vector<std::array<Vec2, 4>> outside_text(const Piece& piece);

/// The piece's Orientation in `area` (page mm).
Orientation orient_piece(const StripData& data, const Piece& piece, const Vec2& area);

/// The piece on the page: page = flip_y(rotate(theta) * p) + translation (p in the strip frame,
/// mm), with its outline, cut line, folds clear of text, tabs, marks, labels and number.
PlacedPiece place_piece_at(const StripData& data, const Piece& piece, const OrientedBox& box,
                           double theta, const Vec2& translation, const LayoutOptions& options,
                           double mm_per_unit);

/// The piece where rectangle packing put its box `at` (inside the margins).
PlacedPiece place_piece(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const PackedRectangle& at, const LayoutOptions& options,
                        double mm_per_unit);

/// The footer of page `index` of `count` ("page 2 / 5") and its scale bar.
void add_page_furniture(Page& page, int index, int count, const LayoutOptions& options,
                        double mm_per_unit);

/// Fill of each page (of `area`), seams and those without a tab, joining strips, the
/// smallest text and the texts of a page that overlap.
LayoutStats layout_stats(const PatternLayout& layout, const Vec2& area);

}  // namespace papercraft::layout_internal
