#pragma once
// The layout's vocabulary, shared by its passes (pages.h), tabs, annotations and packing:
// the options, the packing methods and tab styles, and where a packed rectangle went.

#include "core/pattern.h"

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
  /// saves paper at the cost of pieces (docs/layout.md, "Splits for the page", gives measured
  /// figures).
  int splits_per_page = 3;
};

/// Where pack_rectangles put one rectangle: its page and its top-left corner in the bin;
/// `rotated` when it lies with its width along y.
struct PackedRectangle {
  int page = -1;
  double x = 0.0;
  double y = 0.0;
  bool rotated = false;
};

}  // namespace papercraft
