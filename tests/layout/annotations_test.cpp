// Seam labels and piece numbers: beside the piece, with leader lines straight and bent.
#include "nodes/layout/annotations.h"

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

// Strips too narrow for a seam label (1.5 mm at 2 mm text): the labels are printed beside
// their pieces, on no piece and over no other text, and the nesting keeps other pieces off them.
TEST(LayoutPages, LabelsWithoutRoomOnTheirPieceArePrintedBesideIt) {
  std::vector<FlatStrip> strips;
  for (int k = 0; k < 12; ++k) {
    FlatStrip s = cell_strip(k, 12, 1, 5.0, 1.5);
    std::string label = "N";
    label += std::to_string(k / 2);
    if (k % 2 == 0)
      mark_seam(s, label, k + 1, [&](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
    else
      mark_seam(s, label, k - 1, [&](const Vec2& m) { return std::abs(m.y() - 1.5) < 1e-9; });
    strips.push_back(s);
  }
  LayoutOptions options;
  options.scale = 1;
  options.tab_width_mm = 0;  // no tab to carry the label either
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  int outside = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces)
      for (const Label& label : piece.labels) outside += label.outside ? 1 : 0;
  EXPECT_EQ(outside, 12);
  EXPECT_EQ(layout.stats.overlapping_text, 0);
}

// A seam at the bottom of a slot 1.5 mm wide and 19.5 mm deep, on a comb whose teeth are
// 1.5 mm wide too: no room for its label on the piece, on a tab or beside the seam, so it is
// printed beyond the slot with a leader line from the seam's middle that touches no piece and
// no other text.
// A comb of 1.5 mm cells (nx by 14, the cells where keep(i, j)) whose seam S12 is the edge
// from (1.5, 1.5) to (3, 1.5), at the bottom of a slot in column 1; and a 20 mm block glued to
// it there (its seam edge shortened to the same 1.5 mm).
std::vector<FlatStrip> slot_and_block(int nx, const std::function<bool(int, int)>& keep) {
  FlatStrip comb = cell_strip(0, nx, 14, 1.5, 1.5, keep);
  mark_seam(comb, "S12", 1, [](const Vec2& m) {
    return std::abs(m.y() - 1.5) < 1e-9 && std::abs(m.x() - 2.25) < 1e-9;
  });
  FlatStrip block = cell_strip(1, 4, 4, 5.0, 5.0);
  mark_seam(block, "S12", 0,
            [](const Vec2& m) { return std::abs(m.y()) < 1e-9 && std::abs(m.x() - 2.5) < 1e-9; });
  for (Vec2& v : block.vertices2d)
    if (std::abs(v.y()) < 1e-9 && (std::abs(v.x() - 0.0) < 1e-9 || std::abs(v.x() - 5.0) < 1e-9))
      v.x() = v.x() < 1 ? 1.75 : 3.25;
  for (std::size_t i = 0; i < block.vertices2d.size(); ++i)
    block.vertices3d[i] = Vec3(block.vertices2d[i].x(), block.vertices2d[i].y(), 0.0);
  return {comb, block};
}

TEST(LayoutPages, LabelInANarrowSlotGetsALeaderLine) {
  const std::vector<FlatStrip> strips =
      slot_and_block(3, [](int i, int j) { return i != 1 || j == 0; });
  const FlatStrip& comb = strips[0];
  LayoutOptions options;
  options.scale = 1;
  options.tab_width_mm = 0;  // no tab to carry the label
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.overlapping_text, 0);
  int leaders = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      if (piece.strip_id != 0) continue;
      ASSERT_EQ(piece.labels.size(), 1u);
      const Label& label = piece.labels[0];
      ASSERT_EQ(label.leader.size(), 2u) << "no leader line";
      ++leaders;
      EXPECT_TRUE(label.outside);
      // It starts at the seam's middle: the comb's page vertex of (2.25, 1.5).
      Vec2 seam_middle = Vec2::Zero();
      for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
        const Vec2 strip_point = comb.vertices2d[piece.strip_vertex[v]];
        if ((strip_point - Vec2(1.5, 1.5)).norm() < 1e-9 ||
            (strip_point - Vec2(3.0, 1.5)).norm() < 1e-9)
          seam_middle += 0.5 * piece.vertices[v];
      }
      EXPECT_LT((label.leader.front() - seam_middle).norm(), 1e-6);
      // It runs out of the slot on no piece, and ends at the text, clear of it.
      for (int k = 1; k <= 20; ++k) {
        const Vec2 point =
            label.leader.front() + (k / 20.0) * (label.leader.back() - label.leader.front());
        for (const PlacedPiece& other : page.pieces)
          EXPECT_FALSE(on_piece(point, other) && k > 1)
              << "leader crosses strip " << other.strip_id;
      }
      const auto box = label_box(label);
      const double to_text = (label.leader.back() - label.position).norm();
      EXPECT_LT(to_text, (box[2] - box[0]).norm()) << "leader ends far from its text";
      EXPECT_GT((label.leader.back() - label.leader.front()).norm(), 18.0)
          << "the slot is 19.5 mm deep";
    }
  EXPECT_EQ(leaders, 1);
}

// The same seam at the bottom of a slot that bends (up 13.5 mm, right 3 mm, up and out) in a
// piece whose arms are at most 3 mm wide: the only paper with room for the label is the block
// of 4.5 x 4.5 mm beyond the bend, and no straight line reaches it from the seam, nor free
// paper off the piece. So the leader bends (more than two points), still crossing no cut
// line and no text.
TEST(LayoutPages, LabelInABentSlotGetsALeaderThatBends) {
  auto slot = [](int i, int j) {
    return (i == 1 && j >= 1 && j <= 10) || (j == 10 && i >= 1 && i <= 3) || (i == 3 && j >= 10);
  };
  const std::vector<FlatStrip> strips =
      slot_and_block(5, [&](int i, int j) { return !slot(i, j); });
  LayoutOptions options;
  options.scale = 1;
  options.tab_width_mm = 0;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.overlapping_text, 0);
  int bent = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      if (piece.strip_id != 0) continue;
      ASSERT_EQ(piece.labels.size(), 1u);
      EXPECT_GT(piece.labels[0].leader.size(), 2u) << "the leader does not bend";
      bent += piece.labels[0].leader.size() > 2 ? 1 : 0;
    }
  EXPECT_EQ(bent, 1);
}

// The crowded texts a layout's notes name: seam labels ("label X finds no spot") and piece
// numbers ("piece N: no room for its number").
std::set<std::string> crowded_texts(const PatternLayout& layout) {
  std::set<std::string> names;
  for (const std::string& note : layout.warnings) {
    const auto label = note.find(": label ");
    if (label != std::string::npos && note.find(" finds no spot") != std::string::npos)
      names.insert(note.substr(label + 8, note.find(" finds no spot") - label - 8));
    if (note.rfind("piece ", 0) == 0 && note.find(": no room for its number") != std::string::npos)
      names.insert(note.substr(6, note.find(':') - 6));
  }
  return names;
}

// On small pieces crowded with seams (prisms and seamed grids printed small), every text the
// notes do not name as crowded is clear of every other text and crossed by no cut line of its
// page; and the small sizes drive labels off their seams (beside the piece, or along leaders).
TEST(LayoutAnnotations, LabelsClearEachOtherAndEveryCutLine) {
  std::mt19937 random(2024);
  std::uniform_int_distribution<int> cells(1, 5);
  std::uniform_real_distribution<double> size(0.5, 2.0);
  int texts = 0, away = 0;
  for (double height : {12.0, 20.0, 35.0, 60.0}) {
    std::vector<FlatStrip> strips = prism_strips(square_footprint(1.0), 1.0, 0);
    for (FlatStrip& s : prism_strips(l_footprint(1.0), 1.5, 3)) {
      for (BoundaryEdge& e : s.boundary) e.label += "L";
      strips.push_back(std::move(s));
    }
    for (int k = 0; k < 8; ++k) {
      const int nx = cells(random), ny = cells(random);
      const double w = size(random), h = size(random);
      FlatStrip s = cell_strip(10 + k, nx, ny, w, h);
      const std::string label = "R" + std::to_string(k / 2);
      if (k % 2 == 0)
        mark_seam(s, label, 11 + k, [&](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
      else
        mark_seam(s, label, 9 + k, [&](const Vec2& m) { return std::abs(m.y() - ny * h) < 1e-9; });
      strips.push_back(std::move(s));
    }
    LayoutOptions options;
    options.height_mm = height;
    options.tab_width_mm = 3.0;
    const PatternLayout layout = layout_pages(strips, options);
    SCOPED_TRACE("height " + std::to_string(height));
    const std::set<std::string> crowded = crowded_texts(layout);
    for (const Page& page : layout.pages) {
      std::vector<std::array<Vec2, 2>> cuts;
      for (const auto* pieces : {&page.pieces, &page.joints})
        for (const PlacedPiece& piece : *pieces)
          for (const auto& loop : piece.cut_outline)
            for (std::size_t i = 0; i < loop.size(); ++i)
              cuts.push_back({loop[i], loop[(i + 1) % loop.size()]});
      std::vector<const Label*> page_texts;
      for (const auto* pieces : {&page.pieces, &page.joints})
        for (const PlacedPiece& piece : *pieces) {
          page_texts.push_back(&piece.number);
          for (const Label& label : piece.labels) {
            page_texts.push_back(&label);
            away += label.outside || !label.leader.empty();
          }
        }
      for (std::size_t a = 0; a < page_texts.size(); ++a) {
        const Label& text = *page_texts[a];
        if (crowded.count(text.text)) continue;
        ++texts;
        const auto box = label_box(text);
        const std::vector<Vec2> polygon(box.begin(), box.end());
        for (const auto& cut : cuts)
          for (int i = 0; i < 4; ++i)
            EXPECT_FALSE(segments_cross(cut[0], cut[1], box[i], box[(i + 1) % 4], kEps))
                << "a cut line crosses text " << text.text;
        for (std::size_t b = a + 1; b < page_texts.size(); ++b) {
          if (crowded.count(page_texts[b]->text)) continue;
          const auto other = label_box(*page_texts[b]);
          EXPECT_FALSE(polygons_overlap(polygon, std::vector<Vec2>(other.begin(), other.end())))
              << "texts " << text.text << " and " << page_texts[b]->text << " overlap";
        }
      }
    }
  }
  EXPECT_GT(texts, 100);
  EXPECT_GT(away, 0) << "no label left its seam: the pieces are not crowded enough to test";
  std::cout << "[ labels   ] " << texts << " clear texts, " << away
            << " labels beside their piece or on a leader\n";
}

}  // namespace
}  // namespace papercraft
