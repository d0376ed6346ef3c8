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

namespace papercraft {

enum class PackingMethod {
  Nest,      // true outlines at every nest_rotations step (nesting.h); MaxRects where that is fewer
             // pages
  MaxRects,  // maximal rectangles with 90 degree rotation, several orders; never worse than Shelf
  Shelf,     // next-fit decreasing height shelves (the plain baseline)
};

/// Where a seam's glue tabs go.
enum class TabStyle {
  One,        // one side of every seam (the other side takes what the first has no room for)
  Alternate,  // along a seam, runs of about alternate_run_mm alternate between the two sides
  Both,       // a tab on each side of every seam; the partner is glued over it
  None,       // no tabs (and no joining strips); seams are still labelled and marked
};

struct LayoutOptions {
  PageSize page;
  double margin_mm = 10.0;
  /// Real-world size: the largest side of the 3D bounding box of all strips (vertices3d)
  /// becomes height_mm millimetres. The largest side, not z, because meshes come with any
  /// up axis. Ignored when scale > 0.
  double height_mm = 200.0;
  /// Millimetres per model unit; when > 0 it overrides height_mm.
  double scale = 0.0;
  double tab_width_mm = 5.0;        // 0: no tabs
  double tab_angle_degrees = 45.0;  // angle between a tab's ends and its seam edge, (0, 90]
  TabStyle tab_style = TabStyle::One;
  /// Alternate: the length (mm) of the runs whose tabs change sides along a seam; a seam
  /// shorter than 1.5 runs is one run (as TabStyle::One).
  double alternate_run_mm = 40.0;
  /// Back: every page mirrored, to be printed on the back of the sheet (PrintSide).
  PrintSide print_side = PrintSide::Front;
  /// A seam with room for a tab on neither side (a narrow slit, a tiny seam in a notch) gets
  /// a joining strip instead: a loose strip 2 x tab_width_mm wide, named by the seam's label,
  /// glued behind both sides (Page::joints).
  bool joining_strips = true;
  double fold_angle_degrees = 0.5;  // bend angle above which an inner edge is a fold line
  /// Bend angle from which a fold line is a real crease (drawn in full mountain/valley
  /// style); folds between fold_angle_degrees and this are gentle bends.
  double strong_fold_angle_degrees = 10.0;
  double spacing_mm = 2.0;         // gap between the bounding boxes of pieces
  double label_size_mm = 2.5;      // seam label text height
  double min_text_mm = 2.0;        // no label or number is printed smaller
  double alignment_mark_mm = 3.0;  // tick across the cut line where two seams meet (0: none)
  double number_size_mm = 3.0;     // piece number text height (down to min_text_mm on thin pieces)
  double footer_mm = 8.0;          // band at the bottom of the printable area: scale bar
  PackingMethod packing = PackingMethod::Nest;
  int nest_rotations = 24;    // Nest: rotations tried (every 360 / n degrees; never mirrored)
  double nest_cell_mm = 0.5;  // Nest: raster cell
  int nest_repacks = 3;       // Nest: fills made again with the last page's pieces first
  /// Nest: lay out again with long thin strips (longer than half the page) split in parts of
  /// half a page, or where they bend, and keep that where it saves pages, at least one per
  /// `splits_per_page` more pieces.
  bool split_long_strips = true;
  /// Nest: how many more pieces (long thin strips split) one page saved is worth (>= 1). More
  /// saves paper at the cost of pieces (the README's layout row gives measured figures).
  int splits_per_page = 3;
};

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

/// Where pack_rectangles put one rectangle: its page and its top-left corner in the bin;
/// `rotated` when it lies with its width along y.
struct PackedRectangle {
  int page = -1;
  double x = 0.0;
  double y = 0.0;
  bool rotated = false;
};

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
