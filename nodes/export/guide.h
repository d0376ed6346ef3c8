#pragma once
// The assembly guide: the model as the strips approximate it, seen from four sides, each
// printed piece shaded in its own colour with its number at its centre, a table of where
// every piece is printed, and the build order (core/build_order.h), one line per step in
// columns, continued on further guide pages where it does not fit. Its first page is the first
// page of pattern.pdf and guide.png. Drawn with cairo (depth-sorted, flat-shaded triangles).

#include <cairo.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/pattern.h"
#include "core/strip.h"

namespace papercraft {

/// One printed piece in 3D: its triangles (model units), its name and the pattern page.
struct GuidePiece {
  std::string name;
  int page = 0;  // 1-based pattern page
  std::vector<std::array<Vec3, 3>> triangles;
};

/// What the guide shows: the pieces in 3D and the build steps, each as its printed line
/// (build_step_text).
struct Guide {
  std::vector<GuidePiece> pieces;
  std::vector<std::string> steps;
};

/// The pieces of `layout` in 3D, from the flat strips they were cut from (strip ids match
/// PlacedPiece::strip_id; a piece's triangles are its strip's, through strip_vertex); then
/// the joining strips, named "joint <seam>", without triangles.
std::vector<GuidePiece> guide_pieces(const PatternLayout& layout,
                                     const std::vector<FlatStrip>& strips);

/// Draws the guide on pages of `page` size (mm; cairo's user space in mm, origin top left).
/// Where the build steps need another page, calls `next_page`, which shows the page drawn and
/// returns true to go on (a PDF), or returns false to end the guide there (an image); then a
/// last line says that more steps follow.
void draw_guide(cairo_t* cr, const Guide& guide, const PageSize& page, const std::string& title,
                const std::string& font, const std::function<bool()>& next_page);

/// The guide's first page as a PNG at `dpi`: the file's bytes.
std::string guide_png(const Guide& guide, const PageSize& page, const std::string& title,
                      double dpi = 100.0);

}  // namespace papercraft
