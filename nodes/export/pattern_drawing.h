#pragma once
// What a pattern page looks like, independent of the file format: the layers of DESIGN.md
// section 4 (cut, mountain, valley, tabs, labels, print) as paths and texts with the
// colours and line styles of a preset. svg.h and pdf.h render the same drawing.
//
// Layers, bottom to top:
//   print    scale bar, page number, title
//   tabs     glue tab flaps (grey fill in the print preset; unpainted otherwise)
//   labels   seam labels and piece numbers
//   valley   valley folds
//   mountain mountain folds, including the fold at the base of every tab (a valley fold on
//            a layout printed on the back, PatternLayout::print_side)
// A gentle fold (FoldLine::gentle, a slight bend at a ruling) is drawn in its layer with a
// faint thin pen, only as short marks at its two ends: the page shows the creases that
// matter and still tells where to curve the paper.
//   cut      one closed path per piece: around the piece and its tabs (each boundary loop a
//            subpath), so a cutter runs it in one go
// The laser preset draws three layers: engrave (everything printed: labels, numbers, marks,
// scale bar, in green), score (all folds, blue hairlines) and cut (red hairline). The cutter
// preset draws regmarks (Silhouette registration marks), print, labels, score (folds) and cut.
// No layer holds a zero-length segment.

#include <string>
#include <string_view>
#include <vector>

#include "core/pattern.h"
#include "nodes/export/bake.h"

namespace papercraft {

enum class StylePreset {
  Print,   // black cut lines, dash-dot mountain and dashed valley folds, grey tabs
  Laser,   // red hairline cut, blue hairline score (valley dashed)
  Cutter,  // thin black cut, dashed folds a cutter can perforate
};

/// "print", "laser" or "cutter" (case-insensitive).
/// \throws InvalidInputException for any other name.
StylePreset style_preset_from_name(std::string_view name);

struct StyleOptions {
  StylePreset preset = StylePreset::Print;
  std::string font_family = "sans-serif";
  std::string title;  // printed in the footer when not empty (the model's name)
  /// Per page, the pieces' baked print images (bake.h), drawn under everything else; the
  /// tabs then go unfilled. Null: none.
  const std::vector<std::vector<BakedImage>>* images = nullptr;
  /// Digits after the point of the SVG pages' coordinates (3: a micrometre).
  int svg_decimals = 3;
};

/// A line style; widths and dashes in mm.
struct Pen {
  std::string colour = "#000000";
  double width_mm = 0.25;
  std::vector<double> dash_mm;  // empty: solid
};

/// Polylines drawn with one pen (or none) and one fill (or none).
struct DrawPath {
  std::vector<std::vector<Vec2>> polylines;
  bool closed = false;
  bool stroked = true;
  Pen pen;
  std::string fill;  // "" : none
};

struct DrawText {
  Label label;
  std::string colour = "#000000";
};

struct DrawLayer {
  std::string id;  // cut, mountain, valley, tabs, labels, print; score, engrave, regmarks
  std::vector<DrawPath> paths;
  std::vector<DrawText> texts;
};

/// The registration marks of the cutter preset on `page` (layer "regmarks"): a filled 5 mm
/// square at the top left, filled 20 mm L-brackets 0.3 mm thick at the top right and the
/// bottom left, 10 mm from the paper's edges.
std::vector<DrawLayer> registration_marks(const PageSize& page);

/// The layers of page `page_index` of `layout`, bottom first (see the file comment).
/// \throws InvalidInputException if page_index is not a page of the layout.
std::vector<DrawLayer> pattern_page_drawing(const PatternLayout& layout, int page_index,
                                            const StyleOptions& style = {});

}  // namespace papercraft
