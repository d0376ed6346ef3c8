#pragma once
// assembly.html: one self-contained page (no network, opens from disk) with the model in 3D
// (three.js, bundled into the page at build time: assembly_template.h) beside the pattern
// pages. A piece picked in either view is highlighted in both with its number, page and seam
// labels; hovering a seam label shows its partner; a step slider builds the model up in the
// build order (core/build_order.h).
//
// The page holds the model's data as JSON, gzip-compressed and in base64 (so that nothing in
// it can end its element, and the pattern pages take a fifth of their size), in
// <script id="papercraft-data" type="application/gzip">:
//   name, version, page {width_mm, height_mm}, page_count, parts, notes [text],
//   pages_svg [one SVG document per pattern page, or none],
//   grid {origin [x, y, z], step}: the 3D points' grid, in mm on the model at print scale,
//   pieces [{name, page, step, part, colour "#rrggbb",
//            points: base64 of little-endian uint16 x, y, z per vertex (mm = origin + value *
//            step), triangles: base64 of little-endian uint16 (uint32 where index_bytes is 4)
//            i, j, k per triangle, index_bytes,
//            outline [[x, y, ...] per boundary loop] (integers: 0.1 mm on the page),
//            number [x, y] (0.1 mm), seams [{label, partner, edges [i, j, ...] (vertex indices,
//            two per seam edge), boxes [[x, y, angle_degrees, size] per printed label]
//            (x, y, size in 0.1 mm)}]}] in page order,
//   steps [{piece, text, seams [label]}] in build order.

#include <cstddef>
#include <string>
#include <vector>

#include "core/build_order.h"
#include "core/pattern.h"
#include "core/strip.h"
#include "nodes/export/pattern_drawing.h"

namespace papercraft {

struct AssemblyHtmlOptions {
  /// The page stays under this many bytes where it can: the pieces' print images are left out
  /// of the embedded pages first, then the pages themselves (the pieces are then drawn by their
  /// outlines, with their numbers and seam labels), each with a note on the page.
  std::size_t max_bytes = 5'000'000;
  /// Digits after the point of the embedded pages' coordinates (1: a tenth of a millimetre,
  /// finer than a screen shows the page).
  int svg_decimals = 1;
};

struct AssemblyHtml {
  std::string text;
  /// What was left out to stay under max_bytes, or that the page is larger all the same.
  std::vector<std::string> notes;
};

/// The page of `layout` (its pieces' 3D points from `strips`, as PlacedPiece::strip_id names
/// them), with `order`'s steps and the pattern pages drawn with `style` (its title is the
/// model's name, shown in any bytes: those not UTF-8 as \xNN). A piece whose strip is not in
/// `strips` is left out, as in the printed guide.
/// \throws InvalidInputException if a piece's strip vertex is out of range.
AssemblyHtml assembly_html(const PatternLayout& layout, const std::vector<FlatStrip>& strips,
                           const BuildOrder& order, const StyleOptions& style,
                           const AssemblyHtmlOptions& options = {});

}  // namespace papercraft
