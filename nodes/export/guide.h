#pragma once
// The assembly guide: the model as the strips approximate it, seen from four sides, each
// printed piece shaded in its own colour with its number at its centre, and a table of where
// every piece is printed. It is the first page of pattern.pdf and guide.png. Drawn with cairo
// (depth-sorted, flat-shaded triangles).

#include <cairo.h>

#include <filesystem>
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

/// The pieces of `layout` in 3D, from the flat strips they were cut from (strip ids match
/// PlacedPiece::strip_id; a piece's triangles are its strip's, through strip_vertex); then
/// the joining strips, named "joint <seam>", without triangles.
std::vector<GuidePiece> guide_pieces(const PatternLayout& layout,
                                     const std::vector<FlatStrip>& strips);

/// Draws the guide on a page of `page` size (mm; cairo's user space in mm, origin top left).
void draw_guide(cairo_t* cr, const std::vector<GuidePiece>& pieces, const PageSize& page,
                const std::string& title, const std::string& font);

/// The guide as a PNG of the page at `dpi`: the file's bytes.
std::string guide_png(const std::vector<GuidePiece>& pieces, const PageSize& page,
                      const std::string& title, double dpi = 100.0);

}  // namespace papercraft
