#pragma once
// pattern.pdf (DESIGN.md section 4): every page of a pattern layout, drawn with cairo as the
// SVG pages are (pattern_drawing.h), at real size.

#include <filesystem>

#include "core/pattern.h"
#include "nodes/export/guide.h"
#include "nodes/export/pattern_drawing.h"

namespace papercraft {

/// Writes the PDF to `path` (the caller writes to a temporary name and renames): with
/// `guide`, the assembly guide first (guide.h, one page or more), then every pattern page. A layout
/// without pages gives one blank page so the file is still a valid PDF. \throws IOException if the
/// file cannot be written. Known limit: layers are not PDF optional content.
void write_pattern_pdf(const PatternLayout& layout, const std::filesystem::path& path,
                       const StyleOptions& style = {}, const Guide* guide = nullptr);

}  // namespace papercraft
