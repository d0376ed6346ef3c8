// Strips split for the page: at rulings to fit it, long thin strips in half pages or where
// they bend.
#include "nodes/layout/split_to_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

#include "core/edge_map.h"
#include "core/errors.h"
#include "core/flat_boundary.h"
#include "nodes/layout/divide_triangles.h"
#include "nodes/layout/nesting.h"
#include "nodes/layout/polygon_2d.h"
#include "nodes/layout/split_to_fit.h"
#include "support/layout_checks.h"
#include "support/layout_strips.h"

namespace papercraft {
namespace {

using testing::arc_strip;
using testing::cell_strip;
using testing::l_footprint;
using testing::mark_seam;
using testing::prism_strips;
using testing::square_footprint;
using namespace testing;  // layout_checks.h

// 600 mm of strip on A4: split at rulings (inner edges across the strip) into pieces that
// fit, each cut a new seam with its own label pair and tab.
TEST(LayoutPages, LongStripIsSplitAtRulingsIntoPiecesThatFit) {
  const std::vector<FlatStrip> strips = {cell_strip(7, 60, 1, 10, 20)};
  LayoutOptions options;
  options.scale = 1;
  EXPECT_EQ(strips_exceeding_page(strips, options), std::vector<int>{7});
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  const auto pieces = pieces_of(layout, 7);
  ASSERT_EQ(pieces.size(), 3u);
  std::set<std::string> numbers;
  std::map<std::string, int> seam_edges;
  for (const PlacedPiece* piece : pieces) {
    EXPECT_EQ(piece->piece_count, 3);
    numbers.insert(piece->number.text);
    for (const PlacedEdge& e : piece->edges)
      if (e.kind == EdgeKind::Seam) {
        ++seam_edges[e.label];
        EXPECT_NEAR((e.a - e.b).norm(), 20.0, 1e-9);  // one ruling
      }
  }
  EXPECT_EQ(numbers, (std::set<std::string>{"1a", "1b", "1c"}));
  // Balanced: about 200 mm each, not two full pages and a 90 mm remainder (greedy).
  for (const PlacedPiece* piece : pieces) {
    Vec2 lo = piece->vertices[0], hi = lo;
    for (const Vec2& v : piece->vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    EXPECT_GE((hi - lo).maxCoeff(), 0.5 * (297 - 2 * options.margin_mm)) << piece->number.text;
  }
  EXPECT_EQ(seam_edges.size(), 2u);
  for (const auto& [label, count] : seam_edges) EXPECT_EQ(count, 2) << label;
  ASSERT_FALSE(layout.warnings.empty());
  EXPECT_NE(layout.warnings[0].find("strip 7"), std::string::npos);
  // A short strip is left whole.
  EXPECT_TRUE(strips_exceeding_page({cell_strip(8, 20, 1, 10, 20)}, options).empty());
}

// A 300 degree annulus, 340 mm across: split along its arc into pieces that fit.
TEST(LayoutPages, CurvedStripIsSplitIntoPiecesThatFit) {
  const std::vector<FlatStrip> strips = {arc_strip(2, 150, 170, 300 * M_PI / 180, 120)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  const auto pieces = pieces_of(layout, 2);
  ASSERT_GE(pieces.size(), 2u);
  // Balanced: no piece is a sliver next to the others.
  std::vector<double> areas;
  for (const PlacedPiece* piece : pieces) {
    double area = 0;
    for (const Triangle& t : piece->triangles)
      area += 0.5 * std::abs(cross(piece->vertices[t[1]] - piece->vertices[t[0]],
                                   piece->vertices[t[2]] - piece->vertices[t[0]]));
    areas.push_back(area);
  }
  EXPECT_GE(*std::min_element(areas.begin(), areas.end()),
            0.6 * *std::max_element(areas.begin(), areas.end()));
}

// Long thin arcs (C shapes) that fit the page one at a time: laid out again with each split
// in halves that fit half a page, they need fewer pages, and the layout keeps that (every
// split strip printed as Na and Nb, a note saying so); with split_long_strips off it does not.
// Four arcs of 270 degrees between radii r and r + 10 mm, at 1:1, laid out without and with
// split_long_strips (each layout checked valid).
std::pair<PatternLayout, PatternLayout> arcs_without_and_with_split(
    double r, int segments, std::vector<FlatStrip>& strips) {
  for (int k = 0; k < 4; ++k) strips.push_back(arc_strip(k, r, r + 10, 270 * M_PI / 180, segments));
  LayoutOptions options;
  options.scale = 1;
  options.split_long_strips = false;
  PatternLayout without = layout_pages(strips, options);
  expect_valid_layout(without, strips, options);
  options.split_long_strips = true;
  PatternLayout with = layout_pages(strips, options);
  expect_valid_layout(with, strips, options);
  return {std::move(without), std::move(with)};
}

TEST(LayoutPages, LongThinStripsAreSplitWhereThatSavesPages) {
  std::vector<FlatStrip> strips;  // four C shapes 180 mm across: one per page
  const auto [whole, split] = arcs_without_and_with_split(80, 60, strips);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(pieces_of(whole, k).size(), 1u);
  EXPECT_LT(split.pages.size(), whole.pages.size());
  for (int k = 0; k < 4; ++k) {
    const auto pieces = pieces_of(split, k);
    ASSERT_EQ(pieces.size(), 2u) << "strip " << k;
    EXPECT_EQ(pieces[0]->name.back() == 'a' ? pieces[1]->name.back() : pieces[0]->name.back(), 'b');
  }
  EXPECT_TRUE(std::any_of(split.warnings.begin(), split.warnings.end(), [](const std::string& w) {
    return w.find("split in parts of half a page") != std::string::npos;
  }));
  std::cout << "[ pages    ] long arcs: " << whole.pages.size() << " pages whole, "
            << split.pages.size() << " split\n";
}

// Arcs larger than the page: split only to fit it, each part is still a wide bend that packs
// alone; in parts of half a page they pack together.
// splits_per_page bounds what a page saved may cost: the four arcs above save pages only by
// splitting all four, more than one per page saved, so with splits_per_page 1 they stay whole.
TEST(LayoutPages, SplitsPerPageBoundsTheStripsSplitForAPageSaved) {
  std::vector<FlatStrip> strips;
  const auto [whole, split] = arcs_without_and_with_split(80, 60, strips);
  const int saved = static_cast<int>(whole.pages.size() - split.pages.size());
  ASSERT_GT(saved, 0);
  ASSERT_LT(saved, 4);
  LayoutOptions options;
  options.scale = 1;
  options.splits_per_page = 1;
  const PatternLayout strict = layout_pages(strips, options);
  expect_valid_layout(strict, strips, options);
  EXPECT_EQ(strict.pages.size(), whole.pages.size());
  for (int k = 0; k < 4; ++k) EXPECT_EQ(pieces_of(strict, k).size(), 1u) << "strip " << k;
  options.splits_per_page = 0;
  EXPECT_THROW(layout_pages(strips, options), InvalidInputException);
}

TEST(LayoutPages, LongThinStripsLargerThanThePageAreSplitSmallerWhereThatSavesPages) {
  std::vector<FlatStrip> strips;  // four C shapes 320 mm across
  const auto [page_parts, half_parts] = arcs_without_and_with_split(150, 90, strips);
  EXPECT_LT(half_parts.pages.size(), page_parts.pages.size());
  // Some arcs in more pieces (in halves of a page or where they bend), none in fewer.
  std::size_t more = 0;
  for (int k = 0; k < 4; ++k) {
    EXPECT_GE(pieces_of(half_parts, k).size(), pieces_of(page_parts, k).size()) << "strip " << k;
    more += pieces_of(half_parts, k).size() - pieces_of(page_parts, k).size();
  }
  EXPECT_GT(more, 0u);
  std::cout << "[ pages    ] arcs larger than the page: " << page_parts.pages.size()
            << " pages split for the page, " << half_parts.pages.size() << " in half pages\n";
}

// A strip bent like an L (legs 220 and 100 mm, 20 mm wide), a U (legs 100, 200 and 100 mm) and
// a straight bar (300 x 20 mm) of 10 mm cells at 1:1: split where they bend, the L gives two
// straight parts, the U three, the bar stays whole; the parts cover every triangle once, each
// is connected and straight (its tightest rectangle at most 1.5 times its area), and every
// edge between two parts carries a split label.
TEST(LayoutSplit, StripsAreSplitWhereTheyBend) {
  auto parts_of = [](const FlatStrip& strip, std::size_t expected) {
    layout_internal::StripData data = layout_internal::prepare_strip(strip, 1.0);
    std::set<std::string> used;
    const auto sets = layout_internal::split_at_bends(data, used);
    ASSERT_EQ(sets.size(), expected) << "strip " << strip.id;
    std::vector<int> all;
    std::map<int, std::size_t> part_of;
    for (std::size_t k = 0; k < sets.size(); ++k) {
      double area = 0;
      for (int t : sets[k]) {
        const Triangle& tri = strip.triangles[t];
        area += 0.5 * std::abs(cross(strip.vertices2d[tri[1]] - strip.vertices2d[tri[0]],
                                     strip.vertices2d[tri[2]] - strip.vertices2d[tri[0]]));
        all.push_back(t);
        part_of[t] = k;
      }
      bool unused = false;
      const auto box = layout_internal::tightest_box(
          layout_internal::convex_hull(layout_internal::piece_points(data, sets[k])), -1, -1,
          &unused);
      EXPECT_LE(box.size.prod(), 1.5 * area) << "strip " << strip.id << " part " << k;
    }
    std::sort(all.begin(), all.end());
    std::vector<int> every(strip.triangles.size());
    std::iota(every.begin(), every.end(), 0);
    EXPECT_EQ(all, every);
    // Every inner edge between two parts is labelled as a split seam.
    std::map<std::pair<int, int>, int> owner;
    for (int t = 0; t < static_cast<int>(strip.triangles.size()); ++t)
      for (int i = 0; i < 3; ++i)
        owner[{strip.triangles[t][i], strip.triangles[t][(i + 1) % 3]}] = t;
    int cut_edges = 0;
    for (const auto& [edge, t] : owner) {
      auto twin = owner.find({edge.second, edge.first});
      if (twin == owner.end() || part_of[t] == part_of[twin->second]) continue;
      ++cut_edges;
      const auto key =
          directed_edge_key(std::min(edge.first, edge.second), std::max(edge.first, edge.second));
      EXPECT_TRUE(data.split_label.count(key)) << edge.first << "-" << edge.second;
    }
    EXPECT_EQ(cut_edges > 0, expected > 1);
  };
  parts_of(cell_strip(0, 22, 10, 10, 10, [](int i, int j) { return j < 2 || i >= 20; }), 2);
  parts_of(cell_strip(1, 20, 10, 10, 10, [](int i, int j) { return j < 2 || i < 2 || i >= 18; }),
           3);
  parts_of(cell_strip(2, 30, 2, 10, 10), 1);
}

}  // namespace
}  // namespace papercraft
