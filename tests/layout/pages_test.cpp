// layout_pages as a whole: folds, scale, tabs and labels on every seam, random strips, bad input.
#include "nodes/layout/pages.h"

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

// A box: the band folds at three corners (the fourth is its seam), all convex: mountains.
// Seams A (band with itself), T and B (band with caps): two labels and one tab each, the
// tabs on the band (the lower strip id).
TEST(LayoutPages, BoxHasMountainFoldsMatchingLabelsAndOneTabPerSeam) {
  const auto strips = prism_strips(square_footprint(40), 60, 0);
  LayoutOptions options;
  options.scale = 1.0;
  const PatternLayout layout = layout_pages(strips, options);
  EXPECT_DOUBLE_EQ(layout.mm_per_unit, 1.0);
  ASSERT_EQ(layout.pages.size(), 1u);
  ASSERT_EQ(layout.pages[0].pieces.size(), 3u);
  expect_valid_layout(layout, strips, options);
  EXPECT_TRUE(layout.warnings.empty());

  const PlacedPiece& band = *pieces_of(layout, 0).at(0);
  EXPECT_EQ(band.folds.size(), 3u);
  EXPECT_EQ(count_folds(band, FoldKind::Mountain), 3);
  for (const FoldLine& f : band.folds) {
    EXPECT_NEAR(f.bend_degrees, 90.0, 1e-9);
    EXPECT_NEAR((f.a - f.b).norm(), 60.0, 1e-9);
  }
  EXPECT_EQ(band.tabs.size(), 3u);
  EXPECT_EQ(band.labels.size(), 4u);  // A twice, T, B
  EXPECT_EQ(band.number.text, "1");   // pieces are numbered 1..N
  for (int cap : {1, 2}) {
    const PlacedPiece& piece = *pieces_of(layout, cap).at(0);
    EXPECT_TRUE(piece.folds.empty());  // the diagonal is flat
    EXPECT_TRUE(piece.tabs.empty());
    ASSERT_EQ(piece.labels.size(), 1u);
    EXPECT_EQ(piece.labels[0].text, cap == 1 ? "T" : "B");
    ASSERT_EQ(piece.cut_outline.size(), 1u);
    EXPECT_EQ(piece.cut_outline[0].size(), 4u);  // no tab: the square itself
  }
  // The band's cut line goes around its three tabs: its 10 corners and the tabs' outer
  // chains (the ends and a mitre point over every seam vertex between).
  ASSERT_EQ(band.cut_outline.size(), 1u);
  EXPECT_EQ(band.cut_outline[0].size(), 10u + 5u + 5u + 2u);
  // Labels are upright and have a readable size.
  for (const Label& label : band.labels) {
    EXPECT_GT(label.angle_degrees, -90.0);
    EXPECT_LE(label.angle_degrees, 90.0);
    EXPECT_GE(label.size_mm, 2.5 - 1e-12);
  }
}

// An L-shaped prism has one reflex corner: a valley fold among four mountains.
TEST(LayoutPages, LShapedPrismHasOneValleyFold) {
  const auto strips = prism_strips(l_footprint(20), 30, 4);
  LayoutOptions options;
  options.scale = 1.5;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  const PlacedPiece& band = *pieces_of(layout, 4).at(0);
  EXPECT_EQ(count_folds(band, FoldKind::Mountain), 4);
  EXPECT_EQ(count_folds(band, FoldKind::Valley), 1);
}

// height_mm maps the largest side of the 3D bounding box (here x and y: 20, z: 15).
TEST(LayoutPages, HeightMapsLargestSideOfTheBoundingBox) {
  const auto strips = prism_strips(l_footprint(10), 15, 0);
  LayoutOptions options;
  options.height_mm = 100;
  EXPECT_DOUBLE_EQ(layout_scale(strips, options), 5.0);
  const PatternLayout layout = layout_pages(strips, options);
  EXPECT_DOUBLE_EQ(layout.mm_per_unit, 5.0);
  expect_valid_layout(layout, strips, options);
  options.scale = 2.0;  // overrides height_mm
  EXPECT_DOUBLE_EQ(layout_scale(strips, options), 2.0);
}

// Two cells bent along their shared edge: a fold only above the threshold; bent away from
// the printed (outer, +z) side it is a mountain, towards it a valley.
TEST(LayoutPages, FoldThresholdAndDirection) {
  auto bent = [](double degrees) {
    FlatStrip s = cell_strip(0, 2, 1, 10, 10);
    const double a = degrees * M_PI / 180.0;
    for (std::size_t v = 0; v < s.vertices2d.size(); ++v)
      if (s.vertices2d[v].x() > 15)
        s.vertices3d[v] = Vec3(10 + 10 * std::cos(a), s.vertices2d[v].y(), 10 * std::sin(a));
    return std::vector<FlatStrip>{s};
  };
  LayoutOptions options;
  options.scale = 1;
  options.fold_angle_degrees = 0.5;
  EXPECT_TRUE(layout_pages(bent(0.3), options).pages[0].pieces[0].folds.empty());
  options.fold_angle_degrees = 0.1;
  auto folds = layout_pages(bent(0.3), options).pages[0].pieces[0].folds;
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].kind, FoldKind::Valley);
  EXPECT_NEAR(folds[0].bend_degrees, 0.3, 1e-6);
  EXPECT_TRUE(folds[0].gentle);
  folds = layout_pages(bent(-30), options).pages[0].pieces[0].folds;
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].kind, FoldKind::Mountain);
  EXPECT_NEAR(folds[0].bend_degrees, 30, 1e-6);
  EXPECT_FALSE(folds[0].gentle);
  options.strong_fold_angle_degrees = 45;
  EXPECT_TRUE(layout_pages(bent(-30), options).pages[0].pieces[0].folds.at(0).gentle);
}

// Two flat strips glued along y = 0 in 3D, each with its own uv offset (as across a uv
// seam of an atlas): a tab shows the partner's texture where the partner would lie.
TEST(LayoutPages, TabTextureContinuesThePartnerStrip) {
  std::vector<FlatStrip> strips = {cell_strip(0, 2, 1, 20, 10), cell_strip(1, 2, 1, 20, 10)};
  mark_seam(strips[0], "s", 1, [](const Vec2& m) { return m.y() == 0; });
  mark_seam(strips[1], "s", 0, [](const Vec2& m) { return m.y() == 10; });
  auto uv_of = [](int strip, const Vec2& p3d) {
    return Vec2(p3d.x() / 40 + 0.5 * strip, (p3d.y() + 10) / 20);
  };
  for (int k = 0; k < 2; ++k)
    for (std::size_t v = 0; v < strips[k].vertices3d.size(); ++v) {
      strips[k].vertices3d[v].y() -= 10 * k;
      strips[k].uvs.push_back(uv_of(k, strips[k].vertices3d[v].head<2>()));
    }
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  int patches = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces)
      for (const Tab& tab : piece.tabs)
        for (const TexturePatch& patch : tab.texture) {
          ++patches;
          Eigen::Matrix3d from, to;
          for (int k = 0; k < 3; ++k) {
            from.col(k) << patch.uvs[k], 1.0;
            to.col(k) << patch.corners[k], 1.0;
          }
          const Eigen::Matrix3d page_to_uv = from * to.inverse();
          Vec2 centre = Vec2::Zero();
          for (const Vec2& c : patch.clip) centre += c / static_cast<double>(patch.clip.size());
          const Vec2 uv = (page_to_uv * Eigen::Vector3d(centre.x(), centre.y(), 1)).head<2>();
          // The flat continuation of the piece's own strip frame, in 3D.
          const Vec2 frame =
              piece.transform.linear.inverse() * (centre - piece.transform.translation);
          const Vec2 p3d = frame - Vec2(0, 10 * piece.strip_id);
          const Vec2 expected = uv_of(1 - piece.strip_id, p3d);
          EXPECT_NEAR((uv - expected).norm(), 0, 1e-9) << uv.transpose();
        }
  EXPECT_GE(patches, 2);  // one per seam edge under the tab
}

TEST(LayoutPages, OpenEdgesGetNoTabsOrLabels) {
  const std::vector<FlatStrip> strips = {cell_strip(3, 4, 2, 10, 10)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  const PlacedPiece& piece = layout.pages.at(0).pieces.at(0);
  EXPECT_TRUE(piece.tabs.empty());
  EXPECT_TRUE(piece.labels.empty());
  EXPECT_EQ(piece.number.text, "1");  // the only piece, whatever its strip id
  for (const PlacedEdge& e : piece.edges) EXPECT_EQ(e.kind, EdgeKind::Open);
  expect_valid_layout(layout, strips, options);
}

// Random rectangles seamed in pairs along their long sides, random scale: valid layouts.
TEST(LayoutPages, RandomStripsWithSeamsKeepEveryInvariant) {
  std::mt19937 random(12345);
  std::uniform_int_distribution<int> cells(1, 8);
  std::uniform_real_distribution<double> size(3.0, 25.0);
  int pages = 0, shelf_pages = 0;
  for (int round = 0; round < 4; ++round) {
    std::vector<FlatStrip> strips;
    for (int k = 0; k < 24; ++k) {
      const int nx = cells(random), ny = cells(random);
      const double w = size(random), h = size(random);
      FlatStrip s = cell_strip(k, nx, ny, w, h);
      std::string label = "P";
      label += std::to_string(k / 2);
      if (k % 2 == 0)
        mark_seam(s, label, k + 1, [&](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
      else
        mark_seam(s, label, k - 1, [&](const Vec2& m) { return std::abs(m.y() - ny * h) < 1e-9; });
      strips.push_back(s);
    }
    LayoutOptions options;
    options.scale = 0.5 + 0.25 * round;
    const PatternLayout layout = layout_pages(strips, options);
    expect_valid_layout(layout, strips, options);
    EXPECT_LE(static_cast<int>(layout.pages.size()), layout.shelf_page_count);
    pages += static_cast<int>(layout.pages.size());
    shelf_pages += layout.shelf_page_count;
  }
  std::cout << "[ pages    ] layout " << pages << ", shelf " << shelf_pages
            << " on 4 sets of 24 seamed strips\n";
}

TEST(LayoutPages, OversizedTriangleOverflowsWithWarning) {
  const std::vector<FlatStrip> strips = {cell_strip(0, 1, 1, 400, 400)};
  LayoutOptions options;
  options.scale = 1;
  options.packing = PackingMethod::MaxRects;  // nesting divides the triangles (below)
  const PatternLayout layout = layout_pages(strips, options);
  EXPECT_EQ(layout.pages.size(), 2u);  // split into its two triangles, each alone
  bool overflow = false;
  for (const std::string& w : layout.warnings) overflow |= w.find("overflows") != std::string::npos;
  EXPECT_TRUE(overflow);
}

// Cuts that meet near a vertex can leave a triangle many orders of magnitude below the
// strip's size; rounding decides its orientation, and it must not fail the model.
TEST(LayoutPages, VanishingSliverDoesNotFailTheLayout) {
  LayoutOptions options;
  options.scale = 1;
  FlatStrip strip;
  strip.id = 0;
  strip.source_strip = 0;
  // A (pushed past the segment E-F by 1e-11 mm, so A-E-F turns clockwise), E, B, C, D, F.
  const std::vector<Vec2> points = {{2e-11, 2e-11}, {1e-11, 0}, {10, 0},
                                    {10, 10},       {0, 10},    {0, 1e-11}};
  for (const Vec2& p : points) {
    strip.vertices2d.push_back(p);
    strip.vertices3d.emplace_back(p.x(), p.y(), 0.0);
  }
  strip.triangles = {{0, 1, 5}, {1, 2, 3}, {1, 3, 5}, {5, 3, 4}};
  strip.boundary = testing::open_boundary(strip.triangles);
  const Vec2 e1 = points[1] - points[0], e2 = points[5] - points[0];
  ASSERT_LT(e1.x() * e2.y() - e1.y() * e2.x(), 0.0);  // the sliver really is clockwise
  EXPECT_NO_THROW(layout_pages({strip}, options));

  // The same reversal at a visible size is still refused.
  FlatStrip visible = strip;
  visible.vertices2d[0] = {2, 2};
  visible.vertices2d[1] = {1, 0};
  visible.vertices2d[5] = {0, 1};
  EXPECT_THROW(layout_pages({visible}, options), InvalidInputException);
}

TEST(LayoutPages, BadInputThrows) {
  LayoutOptions options;
  options.scale = 1;
  const FlatStrip good = cell_strip(0, 2, 1, 10, 10);
  EXPECT_NO_THROW(layout_pages({good}, options));
  EXPECT_TRUE(layout_pages({}, options).pages.empty());

  FlatStrip clockwise = good;
  std::swap(clockwise.triangles[0][1], clockwise.triangles[0][2]);
  EXPECT_THROW(layout_pages({clockwise}, options), InvalidInputException);
  FlatStrip sizes = good;
  sizes.vertices3d.pop_back();
  EXPECT_THROW(layout_pages({sizes}, options), InvalidInputException);
  FlatStrip index = good;
  index.triangles[1][2] = 99;
  EXPECT_THROW(layout_pages({index}, options), InvalidInputException);
  FlatStrip inner = good;
  inner.boundary.push_back({0, 4, EdgeKind::Open, -1, ""});  // the first cell's diagonal
  EXPECT_THROW(layout_pages({inner}, options), InvalidInputException);
  EXPECT_THROW(layout_pages({good, good}, options), InvalidInputException);  // same id

  LayoutOptions bad = options;
  bad.margin_mm = -1;
  EXPECT_THROW(layout_pages({good}, bad), InvalidInputException);
  bad = options;
  bad.page = {40, 40};
  bad.margin_mm = 15;
  EXPECT_THROW(layout_pages({good}, bad), InvalidInputException);
  bad = LayoutOptions{};
  FlatStrip point = good;
  for (Vec3& v : point.vertices3d) v = Vec3::Zero();
  EXPECT_THROW(layout_scale({point}, bad), InvalidInputException);
  EXPECT_THROW(pack_rectangles({Vec2(300, 300)}, 190, 267, 2, PackingMethod::MaxRects),
               InvalidInputException);
}

}  // namespace
}  // namespace papercraft
