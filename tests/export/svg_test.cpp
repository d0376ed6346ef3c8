#include "nodes/export/svg.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "nodes/layout/pages.h"
#include "support/layout_strips.h"

namespace papercraft {
namespace {

using testing::cell_strip;
using testing::mark_seam;
using testing::prism_strips;
using testing::square_footprint;

// A box (3 pieces with seams, folds and tabs), a 600 mm strip split into pieces and a
// 180 x 200 mm sheet: more than one page.
PatternLayout sample_layout() {
  std::vector<FlatStrip> strips = prism_strips(square_footprint(40), 60, 0);
  strips.push_back(cell_strip(3, 60, 1, 10, 20));
  strips.push_back(cell_strip(4, 9, 10, 20, 20));
  LayoutOptions options;
  options.scale = 1;
  return layout_pages(strips, options);
}

// A minimal XML well-formedness check: one root, tags nest and close in order, attributes
// are quoted, no bare '<' or '&' in text.
bool well_formed(const std::string& xml, std::string* why) {
  std::vector<std::string> open;
  std::size_t i = 0;
  int roots = 0;
  auto fail = [&](const std::string& message) {
    *why = message + " at offset " + std::to_string(i);
    return false;
  };
  if (xml.rfind("<?xml", 0) == 0) i = xml.find("?>") + 2;
  while (i < xml.size()) {
    if (xml[i] != '<') {
      if (xml[i] == '&') {
        const std::size_t end = xml.find(';', i);
        if (end == std::string::npos || end - i > 6) return fail("bare &");
      }
      if (open.empty() && !std::isspace(static_cast<unsigned char>(xml[i])))
        return fail("text outside the root");
      ++i;
      continue;
    }
    const std::size_t end = xml.find('>', i);
    if (end == std::string::npos) return fail("unclosed tag");
    std::string tag = xml.substr(i + 1, end - i - 1);
    if (tag.find('<') != std::string::npos) return fail("'<' inside a tag");
    if (!tag.empty() && tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return fail("mismatched </" + tag);
      open.pop_back();
    } else {
      const bool self_closing = !tag.empty() && tag.back() == '/';
      if (self_closing) tag.pop_back();
      const std::string name = tag.substr(0, tag.find_first_of(" \t\n"));
      if (name.empty()) return fail("empty tag name");
      // Attributes: name="value" pairs.
      std::size_t a = name.size();
      while (a < tag.size()) {
        while (a < tag.size() && std::isspace(static_cast<unsigned char>(tag[a]))) ++a;
        if (a >= tag.size()) break;
        const std::size_t eq = tag.find('=', a);
        if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"')
          return fail("unquoted attribute in <" + name);
        const std::size_t close = tag.find('"', eq + 2);
        if (close == std::string::npos) return fail("unterminated attribute in <" + name);
        if (tag.substr(eq + 2, close - eq - 2).find_first_of("<") != std::string::npos)
          return fail("'<' in an attribute");
        a = close + 1;
      }
      if (open.empty()) ++roots;
      if (!self_closing) open.push_back(name);
    }
    i = end + 1;
  }
  if (!open.empty()) return fail("unclosed <" + open.back() + ">");
  if (roots != 1) return fail("not exactly one root element");
  return true;
}

// The content of the layer with this id.
std::string layer(const std::string& svg, const std::string& id) {
  const std::string head =
      "<g inkscape:groupmode=\"layer\" id=\"" + id + "\" inkscape:label=\"" + id + "\">";
  const std::size_t begin = svg.find(head);
  if (begin == std::string::npos) return "<missing>";
  const std::size_t end = svg.find("</g>", begin);
  return svg.substr(begin + head.size(), end - begin - head.size());
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ExportSvg, PagesAreWellFormedMillimetreDocumentsWithNamedLayers) {
  const PatternLayout layout = sample_layout();
  ASSERT_GE(layout.pages.size(), 2u);
  const bool have_xmllint = std::system("command -v xmllint > /dev/null 2>&1") == 0;
  for (int p = 0; p < static_cast<int>(layout.pages.size()); ++p) {
    const std::string svg = pattern_page_svg(layout, p);
    std::string why;
    EXPECT_TRUE(well_formed(svg, &why)) << why;
    EXPECT_NE(svg.find("width=\"210mm\" height=\"297mm\" viewBox=\"0 0 210 297\""),
              std::string::npos);
    for (const char* id : {"cut", "mountain", "valley", "tabs", "labels", "print"})
      EXPECT_NE(layer(svg, id), "<missing>") << id;
    // One closed cut path per piece, each label and piece number as text.
    const Page& page = layout.pages[p];
    EXPECT_EQ(count(layer(svg, "cut"), "<path"), static_cast<int>(page.pieces.size()));
    for (const PlacedPiece& piece : page.pieces) {
      EXPECT_NE(layer(svg, "labels").find(">" + piece.number.text + "</text>"), std::string::npos);
      for (const Label& label : piece.labels)
        EXPECT_NE(layer(svg, "labels").find(">" + label.text + "</text>"), std::string::npos);
    }
    EXPECT_NE(layer(svg, "print").find("<text"), std::string::npos);  // scale bar caption
    if (have_xmllint) {
      const auto file = std::filesystem::temp_directory_path() /
                        ("papercraft_svg_test_" + std::to_string(p) + ".svg");
      std::ofstream(file) << svg;
      EXPECT_EQ(std::system(("xmllint --noout " + file.string() + " 2>/dev/null").c_str()), 0);
      std::filesystem::remove(file);
    }
  }
  // The box page: three mountain folds on the band plus the bases of its three tabs.
  const std::string first = pattern_page_svg(layout, 0);
  EXPECT_NE(layer(first, "mountain").find("<path"), std::string::npos);
  EXPECT_NE(layer(first, "tabs").find("fill=\"#e6e6e6\""), std::string::npos);
}

TEST(ExportSvg, PresetsChangeColoursAndDashes) {
  const PatternLayout layout = sample_layout();
  StyleOptions laser;
  laser.preset = StylePreset::Laser;
  const std::string svg = pattern_page_svg(layout, 0, laser);
  EXPECT_NE(layer(svg, "cut").find("stroke=\"#ff0000\""), std::string::npos);
  EXPECT_NE(layer(svg, "score").find("stroke=\"#0000ff\""), std::string::npos);
  // Everything printed is engraved, in its own colour on its own layer: no black text.
  EXPECT_NE(layer(svg, "engrave").find("<text"), std::string::npos);
  EXPECT_EQ(svg.find("fill=\"#000000\""), std::string::npos);
  EXPECT_EQ(layer(svg, "labels"), "<missing>");
  EXPECT_NE(layer(svg, "cut").find("stroke-width=\"0.025\""), std::string::npos);
  EXPECT_EQ(layer(svg, "tabs").find("fill=\"#e6e6e6\""), std::string::npos);

  const std::string print = pattern_page_svg(layout, 0);
  EXPECT_NE(layer(print, "mountain").find("stroke-dasharray=\"3,1,0.6,1\""), std::string::npos);
  EXPECT_EQ(layer(print, "cut").find("stroke-dasharray"), std::string::npos);

  // Cutter: one closed path per piece running around the tabs (one subpath per loop).
  StyleOptions cutter;
  cutter.preset = StylePreset::Cutter;
  const std::string cut = layer(pattern_page_svg(layout, 0, cutter), "cut");
  int loops = 0;
  for (const PlacedPiece& piece : layout.pages[0].pieces)
    loops += static_cast<int>(piece.cut_outline.size());
  EXPECT_EQ(count(cut, "<path"), static_cast<int>(layout.pages[0].pieces.size()));
  EXPECT_EQ(count(cut, " Z"), loops);
  // Registration marks where Silhouette looks for them (A4: 210 x 297 mm).
  const std::string marks = layer(pattern_page_svg(layout, 0, cutter), "regmarks");
  EXPECT_NE(marks.find("M10,10 L15,10 L15,15 L10,15 Z"), std::string::npos) << marks;
  EXPECT_NE(marks.find("M200,10 L200,30 L199.7,30 L199.7,10.3 L180,10.3 L180,10 Z"),
            std::string::npos)
      << marks;
  EXPECT_NE(marks.find("M10,287 L30,287 L30,286.7 L10.3,286.7 L10.3,267 L10,267 Z"),
            std::string::npos)
      << marks;
  EXPECT_NE(layer(pattern_page_svg(layout, 0, cutter), "score").find("<path"), std::string::npos);

  EXPECT_EQ(style_preset_from_name("Laser"), StylePreset::Laser);
  EXPECT_EQ(style_preset_from_name("cutter"), StylePreset::Cutter);
  EXPECT_THROW(style_preset_from_name("plotter"), InvalidInputException);
}

// A gentle fold (a slight bend) is two short faint marks at the ruling's ends; a strong
// one a full dash-dot line.
TEST(ExportSvg, GentleFoldsAreShortFaintMarks) {
  PatternLayout layout;
  layout.pages.resize(1);
  PlacedPiece piece;
  piece.folds.push_back({Vec2(10, 10), Vec2(10, 50), FoldKind::Mountain, 2.0, true});
  piece.folds.push_back({Vec2(30, 10), Vec2(30, 50), FoldKind::Mountain, 20.0, false});
  layout.pages[0].pieces.push_back(piece);
  const std::string mountain = layer(pattern_page_svg(layout, 0), "mountain");
  EXPECT_NE(mountain.find("d=\"M10,10 L10,13 M10,47 L10,50\" fill=\"none\" stroke=\"#e8a0a0\""),
            std::string::npos)
      << mountain;
  EXPECT_NE(mountain.find("d=\"M30,10 L30,50\" fill=\"none\" stroke=\"#c00000\""),
            std::string::npos)
      << mountain;
}

// Lines shorter than the SVG's printed precision (3 decimals) are left out, and points of a
// cut outline that close would print as one: no path prints a segment of zero length (a fold
// line cut short at a fan's apex used to leave "M19.15,265.908 L19.15,265.908").
TEST(ExportSvg, NoSegmentPrintsWithZeroLength) {
  PatternLayout layout;
  layout.pages.resize(1);
  PlacedPiece piece;
  piece.folds.push_back(
      {Vec2(19.15, 265.908), Vec2(19.1503, 265.9081), FoldKind::Mountain, 20.0, false});
  piece.folds.push_back({Vec2(30, 10), Vec2(30, 50), FoldKind::Valley, 20.0, false});
  piece.cut_outline.push_back(
      {Vec2(0, 0), Vec2(40, 0), Vec2(40.0004, 0.0003), Vec2(40, 40), Vec2(0, 40), Vec2(0.0001, 0)});
  layout.pages[0].pieces.push_back(piece);
  const std::string svg = pattern_page_svg(layout, 0);
  EXPECT_EQ(layer(svg, "mountain").find("<path"), std::string::npos)
      << "a fold 0.3 um long is drawn";
  EXPECT_NE(layer(svg, "valley").find("M30,10 L30,50"), std::string::npos);
  EXPECT_NE(layer(svg, "cut").find("d=\"M0,0 L40,0 L40,40 L0,40 Z\""), std::string::npos)
      << layer(svg, "cut");
}

TEST(ExportSvg, TextIsEscaped) {
  std::vector<FlatStrip> strips = {cell_strip(0, 2, 1, 20, 10), cell_strip(1, 2, 1, 20, 10)};
  mark_seam(strips[0], "a<b&\"c\"", 1, [](const Vec2& m) { return m.y() == 0; });
  mark_seam(strips[1], "a<b&\"c\"", 0, [](const Vec2& m) { return m.y() == 10; });
  LayoutOptions options;
  options.scale = 1;
  StyleOptions style;
  style.title = "box <1>";
  const std::string svg = pattern_page_svg(layout_pages(strips, options), 0, style);
  std::string why;
  EXPECT_TRUE(well_formed(svg, &why)) << why;
  EXPECT_EQ(count(svg, ">a&lt;b&amp;&quot;c&quot;</text>"), 2);
  EXPECT_NE(svg.find("box &lt;1&gt;"), std::string::npos);
}

TEST(ExportSvg, BadPageThrows) {
  const PatternLayout layout = sample_layout();
  EXPECT_THROW(pattern_page_svg(layout, -1), InvalidInputException);
  EXPECT_THROW(pattern_page_svg(layout, static_cast<int>(layout.pages.size())),
               InvalidInputException);
}

}  // namespace
}  // namespace papercraft
