#pragma once
// pattern-<NN>.svg (DESIGN.md section 4): one page of a pattern layout as SVG in
// millimetres (width, height and viewBox in mm) with one Inkscape layer per operation:
// `<g inkscape:groupmode="layer" id="cut" inkscape:label="cut">`, likewise mountain,
// valley, tabs, labels and print (see pattern_drawing.h for what each holds).

#include <string>

#include "core/pattern.h"
#include "nodes/export/pattern_drawing.h"

namespace papercraft {

/// `text` for XML or HTML text and attribute values: &, <, >, " and ' as entities; control
/// characters other than tab and newline (not allowed in XML 1.0) left out.
std::string xml_escaped(const std::string& text);

/// The SVG document of page `page_index` (0-based) of `layout`.
/// \throws InvalidInputException if page_index is not a page of the layout.
std::string pattern_page_svg(const PatternLayout& layout, int page_index,
                             const StyleOptions& style = {});

}  // namespace papercraft
