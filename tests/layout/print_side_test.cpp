// Printing on the back (LayoutOptions::print_side, mirror_for_back_printing): every page the
// mirror image of the front's, fold kinds swapped, texts still readable, and the drawing's
// mountain and valley layers swapped with them.

#include "nodes/layout/print_side.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/build_order.h"
#include "core/errors.h"
#include "nodes/export/files.h"
#include "nodes/export/pattern_drawing.h"
#include "nodes/layout/pages.h"
#include "support/layout_strips.h"
#include "support/page_overlaps.h"

namespace papercraft {
namespace {

using testing::l_footprint;
using testing::prism_strips;

constexpr double kEps = 1e-9;

Vec2 mirrored(const Vec2& p, double width) {
  return {width - p.x(), p.y()};
}

void expect_mirrored(const std::vector<Vec2>& back, const std::vector<Vec2>& front, double width,
                     const std::string& what) {
  ASSERT_EQ(back.size(), front.size()) << what;
  for (std::size_t i = 0; i < front.size(); ++i)
    EXPECT_LT((back[i] - mirrored(front[i], width)).norm(), kEps) << what << " point " << i;
}

LayoutOptions options_on(PrintSide side, TabStyle style = TabStyle::One) {
  LayoutOptions options;
  options.scale = 1.0;
  options.print_side = side;
  options.tab_style = style;
  return options;
}

TEST(PrintSide, BackPagesAreTheMirrorOfFrontPages) {
  const auto strips = prism_strips(l_footprint(20), 60, 0);
  for (const TabStyle style : {TabStyle::One, TabStyle::Alternate, TabStyle::Both}) {
    const PatternLayout front = layout_pages(strips, options_on(PrintSide::Front, style));
    const PatternLayout back = layout_pages(strips, options_on(PrintSide::Back, style));
    EXPECT_EQ(front.print_side, PrintSide::Front);
    EXPECT_EQ(back.print_side, PrintSide::Back);
    const double width = front.page.width_mm;
    ASSERT_EQ(back.pages.size(), front.pages.size());
    int mountains = 0, valleys = 0;
    for (std::size_t p = 0; p < front.pages.size(); ++p) {
      const Page &f = front.pages[p], &b = back.pages[p];
      // Page furniture stays readable where it was; the footer says to print on the back and
      // ends where it did.
      EXPECT_EQ(b.footer.text, f.footer.text + " - print on the back");
      EXPECT_EQ(b.footer.position.y(), f.footer.position.y());
      const auto right_end = [](const Label& l) {
        return l.position.x() + 0.3 * l.size_mm * static_cast<double>(l.text.size());
      };
      EXPECT_NEAR(right_end(b.footer), right_end(f.footer), 1e-9);
      EXPECT_EQ(b.scale_bar.start, f.scale_bar.start);
      ASSERT_EQ(b.pieces.size(), f.pieces.size());
      for (std::size_t i = 0; i < f.pieces.size(); ++i) {
        const PlacedPiece &fp = f.pieces[i], &bp = b.pieces[i];
        SCOPED_TRACE("piece " + fp.name);
        expect_mirrored(bp.vertices, fp.vertices, width, "vertices");
        for (std::size_t k = 0; k < fp.cut_outline.size(); ++k)
          expect_mirrored(bp.cut_outline[k], fp.cut_outline[k], width, "cut");
        // The transform still takes the strip to the page, now with a mirror in it.
        EXPECT_GT(bp.transform.linear.determinant(), 0.0);
        EXPECT_LT(fp.transform.linear.determinant(), 0.0);
        const FlatStrip& strip = strips[fp.strip_id];
        for (std::size_t v = 0; v < bp.vertices.size(); ++v)
          EXPECT_LT(
              (bp.transform.apply(strip.vertices2d[bp.strip_vertex[v]]) - bp.vertices[v]).norm(),
              kEps);
        ASSERT_EQ(bp.folds.size(), fp.folds.size());
        for (std::size_t k = 0; k < fp.folds.size(); ++k) {
          expect_mirrored({bp.folds[k].a, bp.folds[k].b}, {fp.folds[k].a, fp.folds[k].b}, width,
                          "fold");
          EXPECT_NE(bp.folds[k].kind, fp.folds[k].kind);
          mountains += fp.folds[k].kind == FoldKind::Mountain;
          valleys += fp.folds[k].kind == FoldKind::Valley;
        }
        ASSERT_EQ(bp.tabs.size(), fp.tabs.size());
        for (std::size_t t = 0; t < fp.tabs.size(); ++t)
          for (std::size_t k = 0; k < fp.tabs[t].flaps.size(); ++k)
            expect_mirrored(bp.tabs[t].flaps[k], fp.tabs[t].flaps[k], width, "flap");
        // Texts at the mirrored place, reading left to right along the mirrored direction.
        ASSERT_EQ(bp.labels.size(), fp.labels.size());
        std::vector<std::pair<const Label*, const Label*>> texts{{&bp.number, &fp.number}};
        for (std::size_t k = 0; k < fp.labels.size(); ++k)
          texts.push_back({&bp.labels[k], &fp.labels[k]});
        for (const auto& [bl, fl] : texts) {
          EXPECT_EQ(bl->text, fl->text);
          EXPECT_LT((bl->position - mirrored(fl->position, width)).norm(), kEps);
          EXPECT_GT(bl->angle_degrees, -90.0);
          EXPECT_LE(bl->angle_degrees, 90.0);
          const double radians = fl->angle_degrees * M_PI / 180,
                       back_radians = bl->angle_degrees * M_PI / 180;
          // Parallel to the mirrored direction (either way round; the upright one is kept).
          EXPECT_NEAR(std::abs(-std::cos(radians) * std::sin(back_radians) -
                               std::sin(radians) * std::cos(back_radians)),
                      0.0, 1e-9);
        }
      }
    }
    EXPECT_GT(mountains, 0);
    EXPECT_GT(valleys, 0);  // the L's reflex corner
    // pieces.json: the same pieces and seams, each with the same tab.
    auto seams_of = [](const PatternLayout& layout) {
      std::vector<std::string> seams;
      const auto pieces = nlohmann::json::parse(pieces_json(layout, build_order(layout)));
      for (const auto& piece : pieces.at("pieces"))
        seams.push_back(piece.at("name").dump() + piece.at("seams").dump());
      return seams;
    };
    EXPECT_EQ(seams_of(back), seams_of(front));
    EXPECT_EQ(testing::layout_overlaps(back), 0);
  }
}

// Polylines of a layer, each mirrored if asked, in a canonical order (micrometres).
std::vector<std::vector<std::pair<long, long>>> layer_lines(const std::vector<DrawLayer>& layers,
                                                            const std::string& id,
                                                            double mirror_width) {
  std::vector<std::vector<std::pair<long, long>>> lines;
  for (const DrawLayer& layer : layers) {
    if (layer.id != id) continue;
    for (const DrawPath& path : layer.paths)
      for (const auto& polyline : path.polylines) {
        std::vector<std::pair<long, long>> line;
        for (const Vec2& p : polyline) {
          const double x = mirror_width > 0 ? mirror_width - p.x() : p.x();
          line.push_back({std::lround(x * 1e3), std::lround(p.y() * 1e3)});
        }
        lines.push_back(line);
      }
  }
  std::sort(lines.begin(), lines.end());
  return lines;
}

TEST(PrintSide, BackDrawingSwapsMountainAndValleyLayers) {
  const auto strips = prism_strips(l_footprint(20), 60, 0);
  const PatternLayout front = layout_pages(strips, options_on(PrintSide::Front));
  const PatternLayout back = layout_pages(strips, options_on(PrintSide::Back));
  const double width = front.page.width_mm;
  for (int page = 0; page < static_cast<int>(front.pages.size()); ++page) {
    const auto f = pattern_page_drawing(front, page), b = pattern_page_drawing(back, page);
    const auto front_mountains = layer_lines(f, "mountain", width);
    ASSERT_FALSE(front_mountains.empty());
    // The tab bases are mountain folds on the front and valley folds on the back.
    EXPECT_EQ(layer_lines(b, "valley", 0), front_mountains);
    EXPECT_EQ(layer_lines(b, "mountain", 0), layer_lines(f, "valley", width));
    EXPECT_EQ(layer_lines(b, "cut", 0), layer_lines(f, "cut", width));
    EXPECT_EQ(layer_lines(b, "tabs", 0), layer_lines(f, "tabs", width));
    // The page number and scale bar are not mirrored.
    EXPECT_EQ(layer_lines(b, "print", 0), layer_lines(f, "print", 0));
  }
}

TEST(PrintSide, ALayoutIsMirroredOnce) {
  const auto strips = prism_strips(l_footprint(20), 60, 0);
  PatternLayout back = layout_pages(strips, options_on(PrintSide::Back));
  EXPECT_THROW(mirror_for_back_printing(back), InvalidInputException);
}

}  // namespace
}  // namespace papercraft
