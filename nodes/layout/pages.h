#pragma once
// Page layout of flat strips: the `layout` stage's algorithm (DESIGN.md section 2 "Layout").
//
// Strips are scaled to real size, split at inner edges where one would not fit a page,
// given glue tabs (one side of every seam), matching seam labels, piece numbers and
// mountain/valley fold lines, rotated to their tightest orientation and packed onto pages.
// The result is pure geometry in page millimetres; nodes/export draws it (SVG, PDF).
//
// Conventions:
// - Page coordinates are millimetres, origin at the top-left corner of the paper, x to the
//   right, y down (as in SVG and cairo). Everything lies inside the margins.
// - The printed side of the paper is the outside of the model: a flat strip's triangles
//   are counter-clockwise in 2D and seen from outside in 3D, and the strip keeps that
//   handedness on the page (the transform flips y so the page shows the strip as the
//   strip's own y-up frame does, never mirrored).
// - Fold lines: an inner edge whose bend angle (between the normals of its two triangles,
//   computed from vertices3d) exceeds fold_angle_degrees. A convex edge (the model bulges
//   outward there) is a Mountain fold seen from the printed side; a concave one a Valley.
//   A tab folds behind the printed side, so its base is a mountain fold too. A fold bent
//   less than strong_fold_angle_degrees is `gentle`: a smooth strip bends a little at
//   every ruling, and those lines only tell a person to curve the paper there, so
//   exporters draw them faint and short (see nodes/export/pattern_drawing.h).
// - Tabs (TabStyle One, the default) go on one side of every seam: the side whose piece
//   comes first in order (strip id, piece index, position on the piece's boundary). If that
//   side has no room (the tab would cover its own piece or another tab even when shrunk),
//   the other side gets it. Alternate, Both and None place them otherwise (see TabStyle);
//   a tab narrows where the outline leaves less room and never covers its own piece or
//   another tab of it.
// - print_side Back mirrors every page at the end (print_side.h): the conventions above
//   then hold for the page seen through the sheet.
//
// Example (node config): layout: {impl: layout.pages, params: {page: A4, margin_mm: 10}}

#include <array>
#include <string>
#include <vector>

#include "core/pattern.h"
#include "core/strip.h"
#include "nodes/layout/layout_types.h"

namespace papercraft {

/// Lays out `strips` on pages (see the file comment for conventions).
///
/// \pre every strip: vertices3d and vertices2d the same size, uvs empty or that size,
///      triangle indices in range and counter-clockwise (or degenerate) in 2D, boundary
///      edges are boundary edges of its triangles with the strip on their left; strip ids
///      unique; options positive where sizes, the printable area larger than the tabs.
/// \throws InvalidInputException if a precondition fails or the scale cannot be
///         determined (height_mm with a flat-to-a-point model).
/// Strips without triangles are skipped with a warning. Seam edges pair up by label and
/// reversed 3D endpoints; a label naming more than one pair of edge chains (a seam whose
/// strip was split, or a label reused) is printed with a suffix per pair (A1.1, A1.2). The
/// seams a split creates are labelled <strip id>-<k> (7-1, 7-2).
/// Known limit: a single triangle larger than the page cannot be split and overflows its own
/// page.
PatternLayout layout_pages(const std::vector<FlatStrip>& strips, const LayoutOptions& options = {});

/// Millimetres per model unit that layout_pages uses for `strips`.
/// \throws InvalidInputException as layout_pages does for the scale.
double layout_scale(const std::vector<FlatStrip>& strips, const LayoutOptions& options);

/// Ids of the strips that fit no page in any orientation, with room for their tabs,
/// at the layout's scale: those layout_pages splits.
/// \throws InvalidInputException as layout_pages does.
std::vector<int> strips_exceeding_page(const std::vector<FlatStrip>& strips,
                                       const LayoutOptions& options);

/// The box the layout keeps clear for a label's text (corners in page mm, counter-clockwise
/// in the label's frame): 0.6 em per character plus 0.1 em each end, 1.2 em high. Labels on
/// a page do not overlap these boxes, and a seam label's box lies on its piece where the
/// piece has room (else it keeps its place at the seam's middle).
std::array<Vec2, 4> label_box(const Label& label);

/// Packs rectangles (width, height) into as few bins of bin_width x bin_height as the
/// method finds, keeping `spacing` between rectangles (none needed at the bin's edges).
/// \pre every rectangle fits the bin in one of its two orientations; sizes > 0.
/// \throws InvalidInputException if a rectangle fits in neither orientation.
std::vector<PackedRectangle> pack_rectangles(const std::vector<Vec2>& sizes, double bin_width,
                                             double bin_height, double spacing,
                                             PackingMethod method);

/// Pages the plain shelf packing (PackingMethod::Shelf) needs for these rectangles.
/// \pre as pack_rectangles.
int shelf_pack_page_count(const std::vector<Vec2>& sizes, double bin_width, double bin_height,
                          double spacing);

}  // namespace papercraft
