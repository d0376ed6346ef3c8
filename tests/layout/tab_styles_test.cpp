// Tab styles (LayoutOptions::tab_style) and the tab's angle, on prisms whose seams are known:
// which seam sides carry a tab, where along a long seam, the trapezoid's shape, and that no
// tab covers its piece or another tab.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>

#include "core/build_order.h"
#include "core/errors.h"
#include "nodes/export/files.h"
#include "nodes/layout/pages.h"
#include "support/layout_strips.h"
#include "support/page_overlaps.h"

namespace papercraft {
namespace {

using testing::l_footprint;
using testing::prism_strips;
using testing::square_footprint;

LayoutOptions options_with(TabStyle style, double run_mm = 40.0) {
  LayoutOptions options;
  options.scale = 1.0;
  options.tab_style = style;
  options.alternate_run_mm = run_mm;
  return options;
}

const PlacedPiece& piece_of(const PatternLayout& layout, int strip_id) {
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces)
      if (piece.strip_id == strip_id) return piece;
  throw std::runtime_error("no piece of strip " + std::to_string(strip_id));
}

std::vector<const Tab*> tabs_labelled(const PlacedPiece& piece, const std::string& label) {
  std::vector<const Tab*> tabs;
  for (const Tab& tab : piece.tabs)
    if (tab.label == label) tabs.push_back(&tab);
  return tabs;
}

// Every seam side of pieces.json: "piece label" -> its `tab` flags.
std::map<std::string, std::vector<bool>> seam_sides(const PatternLayout& layout) {
  std::map<std::string, std::vector<bool>> sides;
  const auto pieces = nlohmann::json::parse(pieces_json(layout, build_order(layout)));
  for (const auto& piece : pieces.at("pieces"))
    for (const auto& seam : piece.at("seams"))
      sides[piece.at("name").get<std::string>() + " " + seam.at("label").get<std::string>()]
          .push_back(seam.at("tab").get<bool>());
  return sides;
}

void expect_no_overlaps(const PatternLayout& layout) {
  std::vector<std::string> problems;
  EXPECT_EQ(testing::layout_overlaps(layout, &problems), 0)
      << (problems.empty() ? "" : problems.front());
}

// The parameter (0..1) along the seam edge of `piece` carrying `point`, or -1.
double along_edge(const PlacedPiece& piece, const Vec2& point) {
  for (const PlacedEdge& e : piece.edges) {
    const Vec2 d = e.b - e.a;
    const double t = (point - e.a).dot(d) / d.squaredNorm();
    if (e.kind == EdgeKind::Seam && t >= -1e-9 && t <= 1 + 1e-9 &&
        (e.a + t * d - point).norm() < 1e-6)
      return t;
  }
  return -1.0;
}

TEST(TabStyles, BothGivesEverySeamSideATab) {
  const auto strips = prism_strips(square_footprint(40), 60, 0);
  const PatternLayout one = layout_pages(strips, options_with(TabStyle::One));
  const PatternLayout both = layout_pages(strips, options_with(TabStyle::Both));
  // One: the band takes all three seams; the caps none.
  EXPECT_EQ(piece_of(one, 1).tabs.size(), 0u);
  EXPECT_EQ(piece_of(one, 2).tabs.size(), 0u);
  // Both: the band's two sides of A, and its T and B; each cap its side.
  EXPECT_EQ(tabs_labelled(piece_of(both, 0), "A").size(), 2u);
  EXPECT_EQ(tabs_labelled(piece_of(both, 0), "T").size(), 1u);
  EXPECT_EQ(tabs_labelled(piece_of(both, 1), "T").size(), 1u);
  EXPECT_EQ(tabs_labelled(piece_of(both, 2), "B").size(), 1u);
  const auto sides = seam_sides(both);
  EXPECT_EQ(sides.size(), 5u);  // 1 A (twice: a seam of the band with itself), 1 T, 1 B, 2 T, 3 B
  for (const auto& [side, tabs] : sides)
    for (bool tab : tabs) EXPECT_TRUE(tab) << side;
  // Every seam edge of every piece is under a tab.
  for (const Page& page : both.pages)
    for (const PlacedPiece& piece : page.pieces)
      for (const PlacedEdge& e : piece.edges) EXPECT_EQ(e.has_tab, e.kind == EdgeKind::Seam);
  for (const Page& page : both.pages) EXPECT_TRUE(page.joints.empty());
  expect_no_overlaps(both);
}

TEST(TabStyles, NoneDrawsNoTabsButKeepsLabelsAndMarks) {
  const auto strips = prism_strips(l_footprint(20), 60, 0);
  const PatternLayout one = layout_pages(strips, options_with(TabStyle::One));
  const PatternLayout none = layout_pages(strips, options_with(TabStyle::None));
  int labels_one = 0, labels_none = 0, marks_one = 0, marks_none = 0, tabs = 0;
  for (const auto* layout : {&one, &none})
    for (const Page& page : layout->pages) {
      EXPECT_TRUE(page.joints.empty());
      for (const PlacedPiece& piece : page.pieces) {
        (layout == &one ? labels_one : labels_none) += static_cast<int>(piece.labels.size());
        (layout == &one ? marks_one : marks_none) += static_cast<int>(piece.marks.size());
        if (layout == &none) {
          tabs += static_cast<int>(piece.tabs.size());
          for (const PlacedEdge& e : piece.edges) EXPECT_FALSE(e.has_tab);
          // The cut line is the outline itself.
          ASSERT_EQ(piece.cut_outline.size(), piece.outline.size());
          for (std::size_t k = 0; k < piece.outline.size(); ++k)
            EXPECT_EQ(piece.cut_outline[k].size(), piece.outline[k].size());
        }
      }
    }
  EXPECT_EQ(tabs, 0);
  EXPECT_GT(labels_none, 0);
  EXPECT_EQ(labels_none, labels_one);
  EXPECT_GT(marks_none, 0);
  EXPECT_EQ(marks_none, marks_one);
  for (const auto& [side, flags] : seam_sides(none))
    for (bool tab : flags) EXPECT_FALSE(tab) << side;
  for (const std::string& warning : none.warnings)
    EXPECT_EQ(warning.find("no room for a glue tab"), std::string::npos) << warning;
}

TEST(TabStyles, AlternateChangesSidesEveryRunAlongALongSeam) {
  // A 200 mm tall band: its seam A (one edge each side) in five runs of 40 mm; T and B are
  // four 40 mm edges, one run each.
  const auto strips = prism_strips(square_footprint(40), 200, 0);
  const PatternLayout layout = layout_pages(strips, options_with(TabStyle::Alternate, 40));
  const PlacedPiece& band = piece_of(layout, 0);
  const auto a_tabs = tabs_labelled(band, "A");
  ASSERT_EQ(a_tabs.size(), 2u);
  std::multiset<std::size_t> flap_counts{a_tabs[0]->flaps.size(), a_tabs[1]->flaps.size()};
  EXPECT_EQ(flap_counts, (std::multiset<std::size_t>{2, 3}));
  for (const Tab* tab : a_tabs) {
    // Each flap on its own fifth of its edge: the first side's the 1st, 3rd and 5th.
    std::set<int> runs;
    for (const auto& base : tab->bases) {
      ASSERT_EQ(base.size(), 2u);
      EXPECT_LT((base[1] - base[0]).norm(), 40.0 + 1e-9);
      const double t = along_edge(band, 0.5 * (base[0] + base[1]));
      ASSERT_GE(t, 0.0);
      runs.insert(static_cast<int>(t * 5));
    }
    const std::set<int> expected =
        tab->flaps.size() == 3 ? std::set<int>{0, 2, 4} : std::set<int>{1, 3};
    EXPECT_EQ(runs, expected);
  }
  // T and B: two of the four edges on the band, two on the cap.
  for (const auto& [label, cap] : {std::pair{"T", 1}, std::pair{"B", 2}}) {
    SCOPED_TRACE(label);
    const auto on_band = tabs_labelled(band, label);
    const auto on_cap = tabs_labelled(piece_of(layout, cap), label);
    ASSERT_EQ(on_band.size(), 1u);
    ASSERT_EQ(on_cap.size(), 1u);
    EXPECT_EQ(on_band[0]->flaps.size(), 2u);
    EXPECT_EQ(on_cap[0]->flaps.size(), 2u);
  }
  for (const auto& [side, flags] : seam_sides(layout))
    for (bool tab : flags) EXPECT_TRUE(tab) << side;
  expect_no_overlaps(layout);
}

TEST(TabStyles, AlternateOnSeamsUnderARunAndAHalfIsOne) {
  const auto strips = prism_strips(l_footprint(20), 60, 0);
  const PatternLayout one = layout_pages(strips, options_with(TabStyle::One));
  const PatternLayout alternate = layout_pages(strips, options_with(TabStyle::Alternate, 500));
  EXPECT_EQ(pieces_json(alternate, build_order(alternate)), pieces_json(one, build_order(one)));
  ASSERT_EQ(alternate.pages.size(), one.pages.size());
  for (std::size_t p = 0; p < one.pages.size(); ++p) {
    ASSERT_EQ(alternate.pages[p].pieces.size(), one.pages[p].pieces.size());
    for (std::size_t i = 0; i < one.pages[p].pieces.size(); ++i)
      EXPECT_EQ(alternate.pages[p].pieces[i].cut_outline, one.pages[p].pieces[i].cut_outline);
  }
  // A shorter run splits the 160 mm seams T and B between the band and the caps.
  const PatternLayout split = layout_pages(strips, options_with(TabStyle::Alternate, 20));
  EXPECT_FALSE(tabs_labelled(piece_of(split, 1), "T").empty());
  EXPECT_FALSE(tabs_labelled(piece_of(split, 2), "B").empty());
  expect_no_overlaps(split);
}

TEST(TabStyles, TabAngleIsTheTrapezoidsSideAngle) {
  const auto strips = prism_strips(square_footprint(40), 60, 0);
  for (const double degrees : {30.0, 45.0, 60.0, 90.0}) {
    SCOPED_TRACE(degrees);
    LayoutOptions options = options_with(TabStyle::One);
    options.tab_angle_degrees = degrees;
    const PatternLayout layout = layout_pages(strips, options);
    const auto tabs = tabs_labelled(piece_of(layout, 0), "T");
    ASSERT_EQ(tabs.size(), 1u);
    ASSERT_EQ(tabs[0]->flaps.size(), 1u);
    const auto& base = tabs[0]->bases[0];
    const auto& flap = tabs[0]->flaps[0];
    ASSERT_GT(flap.size(), base.size());
    // The flap: the base reversed, then the outer chain from the base's start to its end
    // (which may repeat the base's ends).
    std::vector<Vec2> outer;
    for (std::size_t k = base.size(); k < flap.size(); ++k)
      if ((flap[k] - base.front()).norm() > 1e-9 && (flap[k] - base.back()).norm() > 1e-9)
        outer.push_back(flap[k]);
    ASSERT_GE(outer.size(), 2u);
    const Vec2 start_side = outer.front() - base.front();
    const Vec2 end_side = outer.back() - base.back();
    const Vec2 along = (base[1] - base[0]).normalized();
    const Vec2 back = (base[base.size() - 2] - base.back()).normalized();
    EXPECT_NEAR(std::acos(start_side.normalized().dot(along)) * 180 / std::numbers::pi, degrees,
                1e-6);
    EXPECT_NEAR(std::acos(end_side.normalized().dot(back)) * 180 / std::numbers::pi, degrees, 1e-6);
    // Full width away from the seam (room all along it).
    const double height = std::abs(along.x() * start_side.y() - along.y() * start_side.x());
    EXPECT_NEAR(height, options.tab_width_mm, 1e-9);
    expect_no_overlaps(layout);
  }
}

TEST(TabStyles, TabsNarrowWhereThePieceLeavesLessRoom) {
  // An L-shaped prism's band: the caps' tabs (Both) along the reflex corner narrow or
  // shorten rather than cover the cap, at any angle.
  const auto strips = prism_strips(l_footprint(20), 60, 0);
  for (const double degrees : {20.0, 45.0, 90.0}) {
    SCOPED_TRACE(degrees);
    LayoutOptions options = options_with(TabStyle::Both);
    options.tab_angle_degrees = degrees;
    options.tab_width_mm = 12.0;
    const PatternLayout layout = layout_pages(strips, options);
    expect_no_overlaps(layout);
    EXPECT_FALSE(piece_of(layout, 1).tabs.empty());
  }
}

TEST(TabStyles, BadOptionsThrow) {
  const auto strips = prism_strips(square_footprint(40), 60, 0);
  LayoutOptions options = options_with(TabStyle::Alternate, 0.0);
  EXPECT_THROW(layout_pages(strips, options), InvalidInputException);
  for (const double degrees : {0.0, -10.0, 90.5}) {
    options = options_with(TabStyle::One);
    options.tab_angle_degrees = degrees;
    EXPECT_THROW(layout_pages(strips, options), InvalidInputException) << degrees;
  }
}

}  // namespace
}  // namespace papercraft
