// Glue tabs: shrunk to fit, on part of a blocked edge, steeper on a short seam.
#include "nodes/layout/tabs.h"

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

// A U-shaped piece whose slot walls are glued to each other: the tab shrinks to fit in a
// 2.4 mm slot and is dropped (with a warning) in a 0.8 mm one.
TEST(LayoutPages, TabShrinksToFitAndIsDroppedWithoutRoom) {
  auto slotted = [](int slot_cells) {
    const double cell = 0.8;
    FlatStrip s = cell_strip(0, 25, 25, cell, cell, [&](int i, int j) {
      return !(i >= 10 && i < 10 + slot_cells && j >= 5);
    });
    const double left = 10 * cell, right = (10 + slot_cells) * cell;
    mark_seam(s, "S", 0, [&](const Vec2& m) {
      return (std::abs(m.x() - left) < 1e-9 || std::abs(m.x() - right) < 1e-9) && m.y() > 5 * cell;
    });
    return std::vector<FlatStrip>{s};
  };
  LayoutOptions options;
  options.scale = 1;
  const auto wide = slotted(3);
  PatternLayout layout = layout_pages(wide, options);
  expect_valid_layout(layout, wide, options);
  const PlacedPiece& piece = layout.pages.at(0).pieces.at(0);
  ASSERT_EQ(piece.tabs.size(), 1u);
  EXPECT_TRUE(layout.warnings.empty()) << (layout.warnings.empty() ? "" : layout.warnings[0]);

  // In the 0.8 mm slot no tab fits: the seam (16 mm long) gets a joining strip instead, a
  // loose 18 x 10 mm strip named S to glue behind both walls.
  const auto narrow = slotted(1);
  layout = layout_pages(narrow, options);
  expect_valid_layout(layout, narrow, options);
  EXPECT_TRUE(layout.pages.at(0).pieces.at(0).tabs.empty());
  ASSERT_EQ(layout.warnings.size(), 2u);
  EXPECT_NE(layout.warnings[0].find("no room"), std::string::npos);
  EXPECT_NE(layout.warnings[1].find("joining strip"), std::string::npos);
  EXPECT_EQ(layout.stats.seams, 1);
  EXPECT_EQ(layout.stats.seams_without_tab, 0);
  EXPECT_EQ(layout.stats.joining_strips, 1);
  int joints = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& joint : page.joints) {
      ++joints;
      EXPECT_EQ(joint.name, "S");
      EXPECT_EQ(joint.number.text, "S");
      const double a = (joint.vertices[1] - joint.vertices[0]).norm();
      const double b = (joint.vertices[2] - joint.vertices[1]).norm();
      EXPECT_NEAR(std::max(a, b), 18.0, 1e-9);
      EXPECT_NEAR(std::min(a, b), 2 * options.tab_width_mm, 1e-9);
      ASSERT_EQ(joint.marks.size(), 2u);  // the centre line, cut around the name
    }
  EXPECT_EQ(joints, 1);

  // Without joining strips the seam is named as having none.
  options.joining_strips = false;
  layout = layout_pages(narrow, options);
  expect_valid_layout(layout, narrow, options);
  EXPECT_EQ(layout.stats.seams_without_tab, 1);
  EXPECT_EQ(layout.stats.joining_strips, 0);
  ASSERT_EQ(layout.warnings.size(), 1u);
  EXPECT_NE(layout.warnings[0].find("no room"), std::string::npos);
}

// Two pieces, each with a notch, glued along one straight wall of each: the notch's other side
// bulges to 0.6 mm from the wall near its bottom, so no flap fits along the whole wall; the
// wall that takes the tab takes it on its half at the notch's mouth, where there is room, and
// the cut line runs along the rest of it.
TEST(LayoutPages, BlockedWallTakesATabOnPartOfIt) {
  const std::vector<Vec2> outline = {Vec2(0, 0),   Vec2(40, 0),    Vec2(40, 40),
                                     Vec2(22, 40), Vec2(20.3, 14), Vec2(21, 12),
                                     Vec2(20, 10), Vec2(18, 40),   Vec2(0, 40)};
  const std::vector<Triangle> triangles = {{1, 2, 3}, {1, 3, 4}, {1, 4, 5}, {1, 5, 6},
                                           {0, 1, 6}, {0, 6, 7}, {0, 7, 8}};
  // The first piece as drawn; the second its mirror image, the same surface seen from the other
  // side in 3D, so that its mirrored wall is the first's wall reversed.
  auto notched = [&](int id) {
    FlatStrip v;
    v.id = v.source_strip = id;
    for (const Vec2& p : outline) {
      v.vertices2d.push_back(id == 0 ? p : Vec2(40 - p.x(), p.y()));
      v.vertices3d.emplace_back(p.x(), p.y(), 0.0);
    }
    for (Triangle t : triangles) {
      if (id == 1) std::swap(t[1], t[2]);
      v.triangles.push_back(t);
    }
    v.boundary = testing::open_boundary(v.triangles);
    const Vec2 wall_middle(id == 0 ? 19.0 : 21.0, 25.0);
    mark_seam(v, "V", 1 - id, [&](const Vec2& m) { return (m - wall_middle).norm() < 1e-9; });
    return v;
  };
  const std::vector<FlatStrip> strips{notched(0), notched(1)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.seams, 1);
  EXPECT_EQ(layout.stats.seams_without_tab, 0);
  EXPECT_EQ(layout.stats.joining_strips, 0) << "a tab fits on part of the wall";
  int flaps = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      if (piece.tabs.empty()) continue;
      ASSERT_EQ(piece.tabs.size(), 1u);
      ASSERT_EQ(piece.tabs[0].bases.size(), 1u);
      ++flaps;
      const auto& base = piece.tabs[0].bases[0];
      ASSERT_EQ(base.size(), 2u);
      EXPECT_NEAR((base[1] - base[0]).norm(), 0.5 * std::hypot(2.0, 30.0), 1e-9) << "half a wall";
      // The cut line passes through both ends of the flap's base.
      ASSERT_EQ(piece.cut_outline.size(), 1u);
      for (const Vec2& q : base) {
        bool on_cut = false;
        for (const Vec2& c : piece.cut_outline[0]) on_cut = on_cut || (c - q).norm() < 1e-9;
        EXPECT_TRUE(on_cut) << q.transpose();
      }
    }
  EXPECT_EQ(flaps, 1);
}

// A seam 1.5 mm long takes no flap of the smallest height (1 mm) at 45 degrees; steeper
// ends give it one.
TEST(LayoutPages, ShortSeamGetsASteeperTab) {
  FlatStrip a = cell_strip(0, 1, 4, 1.5, 5.0), b = cell_strip(1, 1, 4, 1.5, 5.0);
  mark_seam(a, "S", 1, [](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
  mark_seam(b, "S", 0, [](const Vec2& m) { return std::abs(m.y() - 20.0) < 1e-9; });
  const std::vector<FlatStrip> strips{a, b};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.seams, 1);
  EXPECT_EQ(layout.stats.seams_without_tab, 0);
}

// Distance from p to the polyline `base`.
double distance_to_polyline(const Vec2& p, const std::vector<Vec2>& base) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < base.size(); ++i)
    nearest = std::min(nearest, distance_to_segment(p, base[i], base[i + 1]));
  return nearest;
}

// In every tab style, on notched grids and prisms whose seams crowd each other: no flap covers
// its own piece or another flap of the piece, every flap lies within the room the splitter keeps
// for it (1.15 tab widths of its base), and every seam side a tab names is a seam of the piece.
TEST(LayoutTabs, TabsNeverCoverTheirPieceOrEachOther) {
  std::vector<FlatStrip> strips = prism_strips(l_footprint(20.0), 15.0, 0);
  // A comb: teeth one cell wide with one-cell slots between them, seamed all along its bottom.
  FlatStrip comb = cell_strip(3, 7, 4, 6.0, 6.0, [](int i, int j) { return j == 0 || i % 2 == 0; });
  mark_seam(comb, "C", 4, [](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
  FlatStrip bar = cell_strip(4, 7, 1, 6.0, 6.0);
  for (Vec2& v : bar.vertices2d) v.y() = -v.y();
  for (std::size_t i = 0; i < bar.vertices2d.size(); ++i)
    bar.vertices3d[i] = Vec3(bar.vertices2d[i].x(), bar.vertices2d[i].y(), 0.0);
  for (Triangle& t : bar.triangles) std::swap(t[1], t[2]);
  bar.boundary = testing::open_boundary(bar.triangles);
  mark_seam(bar, "C", 3, [](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
  for (std::size_t i = 0; i < comb.vertices2d.size(); ++i)
    comb.vertices3d[i] = Vec3(comb.vertices2d[i].x(), comb.vertices2d[i].y(), 0.0);
  strips.push_back(comb);
  strips.push_back(bar);
  int flaps = 0;
  for (TabStyle style : {TabStyle::One, TabStyle::Alternate, TabStyle::Both}) {
    LayoutOptions options;
    options.scale = 1.0;
    options.tab_width_mm = 5.0;
    options.tab_style = style;
    options.alternate_run_mm = 10.0;
    const PatternLayout layout = layout_pages(strips, options);
    SCOPED_TRACE("tab style " + std::to_string(static_cast<int>(style)));
    for (const Page& page : layout.pages)
      for (const PlacedPiece& piece : page.pieces) {
        std::set<std::string> seams;
        for (const PlacedEdge& e : piece.edges)
          if (e.kind == EdgeKind::Seam) seams.insert(e.label);
        for (const Tab& tab : piece.tabs) {
          EXPECT_TRUE(seams.count(tab.label)) << "tab " << tab.label << " names no seam";
          for (std::size_t f = 0; f < tab.flaps.size(); ++f) {
            ++flaps;
            for (const Vec2& q : tab.flaps[f])
              EXPECT_LE(distance_to_polyline(q, tab.bases[f]), 1.15 * options.tab_width_mm + kEps)
                  << "a flap of tab " << tab.label << " reaches past its room";
          }
        }
        const std::vector<Shape> shapes = shapes_of(piece);
        for (std::size_t i = 0; i < shapes.size(); ++i)
          for (std::size_t j = i + 1; j < shapes.size(); ++j) {
            if (shapes[i].tab < 0 && shapes[j].tab < 0) continue;
            if (!boxes_overlap(shapes[i], shapes[j])) continue;
            EXPECT_FALSE(polygons_overlap(shapes[i].polygon, shapes[j].polygon))
                << "piece " << piece.name << ": shapes " << i << " and " << j << " overlap";
          }
      }
  }
  EXPECT_GT(flaps, 20);
}

}  // namespace
}  // namespace papercraft
