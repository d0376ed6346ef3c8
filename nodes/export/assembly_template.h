#pragma once
// The page of assembly.html before the model's data goes in: viewer/src/template.html with the
// viewer's script (viewer/src/*.js and three.js, bundled by esbuild) inlined. The build makes
// its definition (viewer/build.mjs, run by viewer/bundle.cmake).

#include <string_view>

namespace papercraft {

/// The page, UTF-8, holding `@PAPERCRAFT_TITLE@` (in <title>) and `@PAPERCRAFT_DATA@` (in a
/// <script type="application/json">) once each, where assembly_html puts the model's.
std::string_view assembly_page_template();

}  // namespace papercraft
