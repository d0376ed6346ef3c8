#pragma once
// Nesting pieces by their true outlines: a raster bottom-left fill. Each piece (its triangles
// and tab slices) is rasterised conservatively at several rotations, and placed, largest
// first, on the first page and at the rotation where it lies highest (then leftmost) without
// coming nearer than the spacing to any piece already there; so pieces go into the
// concavities of others, which packing by bounding rectangles leaves empty. "Largest" is
// tried three ways (area, longest side, bounding rectangle; side by side on the threads
// there are) and the fill with the fewest pages and the emptiest last page is kept. Then the
// pieces of its last page are moved to the front of its order and the fill made again, as long
// as that needs fewer pages or leaves less on the last page (`repacks` times at most): the
// pieces no earlier page had room for get the first choice of room. Last, a fill in the
// pieces' own order, run by run (`grouped`), is kept where it costs no page and puts more
// pieces glued to each other on one page.

#include <array>
#include <utility>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft::layout_internal {

/// A piece as the nesting sees it, in its own frame (mm, y up as the strip's frame): convex
/// polygons (its triangles and its tabs' slices) whose union is the piece.
struct NestShape {
  std::vector<std::vector<Vec2>> convex;
};

struct NestOptions {
  double cell_mm = 0.5;     // raster cell; coarsened for pages too large for it
  int rotations = 24;       // every 360 / rotations degrees; never mirrored
  double spacing_mm = 2.0;  // at least this much paper between two pieces
  /// Fills tried, largest first by area, by longest side, by bounding rectangle (1..3); the
  /// one needing the fewest pages, then leaving the least on the last page, is kept.
  int orders = 3;
  /// Fills made again with the last page's pieces first (0: none).
  int repacks = 3;
  /// Then a fill in the shapes' own order, in runs of about half a page each largest first,
  /// kept where it needs no more pages and puts more of the `neighbours` on one page: shapes
  /// given near each other stay near each other.
  bool grouped = true;
  std::vector<std::pair<int, int>> neighbours;  // shapes glued to each other (by index)
};

/// Where a piece goes: page, and the map from its frame to the printable area (mm, origin at
/// its top-left corner, y down): area = flip_y(rotate(angle) * p) + offset.
struct NestPlacement {
  int page = -1;       // -1: the piece fits the area at no rotation
  double angle = 0.0;  // radians, counter-clockwise in the piece's frame
  Vec2 offset = Vec2::Zero();
};

/// Places every shape; returns one placement per shape (input order) and sets *pages. Shapes
/// that fit at no rotation get page -1. Deterministic.
std::vector<NestPlacement> nest_shapes(const std::vector<NestShape>& shapes, const Vec2& area,
                                       const NestOptions& options, int* pages);

}  // namespace papercraft::layout_internal
