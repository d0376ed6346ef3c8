// End to end: tab styles and printing on the back on a generated box and sphere. The runs are
// certified; the styles are laid out again from each run's strips.json and checked through
// pieces.json and the SVG pages; a run configured to print on the back writes SVG pages that
// are the mirror of the front run's, mountain and valley swapped.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "core/build_order.h"
#include "core/generate.h"
#include "nodes/export/files.h"
#include "nodes/export/svg.h"
#include "nodes/layout/pages.h"
#include "support/flat_strips_json.h"
#include "support/page_overlaps.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::read_text;
using testing::run_pipeline;

struct Shape {
  std::string name;
  TriangleMesh mesh;
};

std::vector<Shape> shapes() {
  return {{"box", box()}, {"sphere", sphere()}};
}

// The default config with the layout's params extended by `params` ("tab_style: both").
std::string config_with(const std::string& params) {
  std::string text = default_config_text();
  const std::string from = "params: {page: A4, margin_mm: 10}";
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos)
    text.replace(at, from.size(), "params: {page: A4, margin_mm: 10, " + params + "}");
  return text;
}

// The paths of one SVG layer as polylines ("M x,y L x,y ... [Z]" split at each M).
std::vector<std::vector<Vec2>> svg_layer(const std::string& svg, const std::string& id) {
  std::vector<std::vector<Vec2>> lines;
  const auto start = svg.find("id=\"" + id + "\"");
  if (start == std::string::npos) return lines;
  const std::string layer = svg.substr(start, svg.find("</g>", start) - start);
  static const std::regex path(R"re(<path d="([^"]*)")re");
  static const std::regex command(R"re(([ML])(-?[0-9.]+),(-?[0-9.]+))re");
  for (auto p = std::sregex_iterator(layer.begin(), layer.end(), path); p != std::sregex_iterator();
       ++p) {
    const std::string d = (*p)[1];
    for (auto c = std::sregex_iterator(d.begin(), d.end(), command); c != std::sregex_iterator();
         ++c) {
      if ((*c)[1] == "M") lines.emplace_back();
      lines.back().emplace_back(std::stod((*c)[2]), std::stod((*c)[3]));
    }
  }
  return lines;
}

// Each polyline of `a` matches one of `b` (same points, mirrored at `mirror_width` when > 0,
// to the SVG's micrometre), one to one.
bool same_polylines(std::vector<std::vector<Vec2>> a, std::vector<std::vector<Vec2>> b,
                    double mirror_width) {
  if (a.size() != b.size()) return false;
  if (mirror_width > 0)
    for (auto& line : a)
      for (Vec2& p : line) p.x() = mirror_width - p.x();
  std::vector<char> used(b.size(), 0);
  for (const auto& line : a) {
    bool found = false;
    for (std::size_t j = 0; j < b.size() && !found; ++j) {
      if (used[j] || b[j].size() != line.size()) continue;
      bool equal = true;
      for (std::size_t k = 0; k < line.size() && equal; ++k)
        equal = (line[k] - b[j][k]).cwiseAbs().maxCoeff() <= 2.1e-3;
      if (equal) {
        used[j] = 1;
        found = true;
      }
    }
    if (!found) return false;
  }
  return true;
}

// pieces.json's seams: label -> the `tab` flags of its sides.
std::map<std::string, std::vector<bool>> tab_flags(const std::string& pieces_text) {
  std::map<std::string, std::vector<bool>> flags;
  const auto pieces = nlohmann::json::parse(pieces_text);
  for (const auto& piece : pieces.at("pieces"))
    for (const auto& seam : piece.at("seams"))
      flags[seam.at("label").get<std::string>()].push_back(seam.at("tab").get<bool>());
  return flags;
}

// Length (mm) of the seam `label` on `piece`.
double seam_length(const PlacedPiece& piece, const std::string& label) {
  double length = 0;
  for (const PlacedEdge& e : piece.edges)
    if (e.kind == EdgeKind::Seam && e.label == label) length += (e.b - e.a).norm();
  return length;
}

TEST(TabStylesEndToEnd, EveryStyleOnABoxAndASphere) {
  for (const Shape& shape : shapes()) {
    SCOPED_TRACE(shape.name);
    const auto out = run_pipeline(shape.mesh, "2%", shape.name);
    ASSERT_TRUE(out.result.ok) << out.result.error;
    EXPECT_TRUE(out.report.at("result").at("certified").get<bool>());
    const auto strips = testing::read_flat_strips(out.flat.at("strips"));
    LayoutOptions options;
    options.scale =
        nlohmann::json::parse(read_text(out.dir / "pieces.json")).at("mm_per_unit").get<double>();
    // The default layout is the run's own.
    const PatternLayout own = layout_pages(strips, options);
    EXPECT_EQ(pieces_json(own, build_order(own)), read_text(out.dir / "pieces.json"));
    int long_seams = 0;
    for (const TabStyle style :
         {TabStyle::One, TabStyle::Alternate, TabStyle::Both, TabStyle::None}) {
      SCOPED_TRACE(static_cast<int>(style));
      options.tab_style = style;
      const PatternLayout layout = layout_pages(strips, options);
      std::vector<std::string> problems;
      EXPECT_EQ(testing::layout_overlaps(layout, &problems), 0)
          << (problems.empty() ? "" : problems.front());
      int tab_paths = 0;
      for (int page = 0; page < static_cast<int>(layout.pages.size()); ++page)
        tab_paths += static_cast<int>(svg_layer(pattern_page_svg(layout, page), "tabs").size());
      const auto flags = tab_flags(pieces_json(layout, build_order(layout)));
      ASSERT_FALSE(flags.empty());
      for (const auto& [label, sides] : flags) {
        const int tabbed = static_cast<int>(std::count(sides.begin(), sides.end(), true));
        if (style == TabStyle::Both) {
          EXPECT_EQ(tabbed, static_cast<int>(sides.size())) << label;
        }
        if (style == TabStyle::None) {
          EXPECT_EQ(tabbed, 0) << label;
        }
        if (style == TabStyle::One) {
          EXPECT_GE(tabbed, 1) << label;
        }
      }
      if (style == TabStyle::None) {
        EXPECT_EQ(tab_paths, 0);
      }
      if (style != TabStyle::None) {
        EXPECT_GT(tab_paths, 0);
      }
      if (style != TabStyle::Alternate) continue;
      // A seam at least 2.5 runs long has a tab on each side.
      std::map<std::string, std::vector<std::pair<double, bool>>> sides;
      for (const Page& page : layout.pages)
        for (const PlacedPiece& piece : page.pieces)
          for (const PieceSeam& seam : piece.seams)
            sides[seam.label].push_back({seam_length(piece, seam.label), seam.tab});
      for (const auto& [label, each] : sides) {
        if (each.size() != 2 || each[0].first < 2.5 * options.alternate_run_mm) continue;
        ++long_seams;
        EXPECT_TRUE(each[0].second && each[1].second) << "long seam " << label;
      }
    }
    EXPECT_GT(long_seams, 0) << "no seam long enough to alternate";
  }
}

TEST(TabStylesEndToEnd, BackPagesAreTheMirrorOfFrontPages) {
  for (const Shape& shape : shapes()) {
    SCOPED_TRACE(shape.name);
    const auto front = run_pipeline(shape.mesh, "2%", shape.name + "-front", 0,
                                    config_with("tab_style: alternate"));
    const auto back = run_pipeline(shape.mesh, "2%", shape.name + "-back", 0,
                                   config_with("tab_style: alternate, print_side: back"));
    ASSERT_TRUE(front.result.ok) << front.result.error;
    ASSERT_TRUE(back.result.ok) << back.result.error;
    EXPECT_TRUE(back.report.at("result").at("certified").get<bool>());
    const int pages = front.report.at("result").at("pages").get<int>();
    ASSERT_EQ(back.report.at("result").at("pages").get<int>(), pages);
    EXPECT_EQ(tab_flags(read_text(back.dir / "pieces.json")),
              tab_flags(read_text(front.dir / "pieces.json")));
    for (int page = 1; page <= pages; ++page) {
      char name[32];
      std::snprintf(name, sizeof name, "pattern-%02d.svg", page);
      SCOPED_TRACE(name);
      const std::string f = read_text(front.dir / name), b = read_text(back.dir / name);
      const double width = 210.0;
      EXPECT_TRUE(same_polylines(svg_layer(f, "cut"), svg_layer(b, "cut"), width));
      EXPECT_TRUE(same_polylines(svg_layer(f, "tabs"), svg_layer(b, "tabs"), width));
      EXPECT_FALSE(svg_layer(f, "mountain").empty());
      EXPECT_TRUE(same_polylines(svg_layer(f, "mountain"), svg_layer(b, "valley"), width));
      EXPECT_TRUE(same_polylines(svg_layer(f, "valley"), svg_layer(b, "mountain"), width));
      EXPECT_TRUE(same_polylines(svg_layer(f, "print"), svg_layer(b, "print"), 0));
      // The pieces' texts at mirrored places, the same texts (the footer and the scale bar's
      // caption stay where they are).
      static const std::regex text(R"re(<text x="([-0-9.]+)" y="([-0-9.]+)"[^>]*>([^<]*)<)re");
      std::vector<std::pair<std::string, Vec2>> front_texts, back_texts;
      for (const auto* svg : {&f, &b})
        for (auto t = std::sregex_iterator(svg->begin(), svg->end(), text);
             t != std::sregex_iterator(); ++t) {
          const std::string words = (*t)[3];
          if (words.find("page ") != std::string::npos || words.find(" mm (") != std::string::npos)
            continue;
          const Vec2 at(std::stod((*t)[1]), std::stod((*t)[2]));
          (svg == &f ? front_texts : back_texts).push_back({words, at});
        }
      ASSERT_EQ(back_texts.size(), front_texts.size());
      std::vector<char> used(back_texts.size(), 0);
      for (const auto& [words, at] : front_texts) {
        bool found = false;
        for (std::size_t k = 0; k < back_texts.size() && !found; ++k) {
          if (!used[k] && back_texts[k].first == words &&
              (back_texts[k].second - Vec2(width - at.x(), at.y())).cwiseAbs().maxCoeff() <=
                  2.1e-3) {
            used[k] = 1;
            found = true;
          }
        }
        EXPECT_TRUE(found) << "text " << words << " not mirrored";
      }
      EXPECT_EQ(b.find("scale(-1"), std::string::npos) << "no mirrored text";
    }
  }
}

}  // namespace
}  // namespace papercraft
