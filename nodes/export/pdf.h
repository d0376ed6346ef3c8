#pragma once
// pattern.pdf (DESIGN.md section 4): every page of a pattern layout, drawn with cairo as the
// SVG pages are (pattern_drawing.h), at real size.

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "core/pattern.h"
#include "nodes/export/guide.h"
#include "nodes/export/pattern_drawing.h"

namespace papercraft {

/// Writes the PDF to `out` as cairo makes it, page by page: with `guide`, the assembly guide
/// first (guide.h, one page or more), then every pattern page. A layout without pages gives one
/// blank page so the file is still a valid PDF.
/// \throws IOException if the stream fails (named `what` in the message).
/// Known limit: layers are not PDF optional content.
void write_pattern_pdf(const PatternLayout& layout, std::ostream& out,
                       const StyleOptions& style = {}, const Guide* guide = nullptr,
                       const std::string& what = "pattern.pdf");

/// The same into the file `path` (the caller writes to a temporary name and renames).
/// \throws IOException if the file cannot be written.
void write_pattern_pdf(const PatternLayout& layout, const std::filesystem::path& path,
                       const StyleOptions& style = {}, const Guide* guide = nullptr);

}  // namespace papercraft
