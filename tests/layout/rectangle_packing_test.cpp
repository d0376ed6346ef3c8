// Rectangle packing: MaxRects never needs more pages than shelves, and beats them on mixed sizes.
#include "nodes/layout/rectangle_packing.h"

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

// Rectangles' pages: MaxRects never worse than the shelf baseline; rectangles keep the
// spacing and stay in their bin.
TEST(LayoutPages, PackerNeverNeedsMorePagesThanShelf) {
  std::mt19937 random(777);
  int total_packed = 0, total_shelf = 0;
  for (int round = 0; round < 30; ++round) {
    std::uniform_real_distribution<double> side(5.0, round % 2 ? 180.0 : 90.0);
    std::vector<Vec2> sizes;
    for (int k = 0; k < 40; ++k) sizes.emplace_back(side(random), side(random));
    const double w = 190, h = 267, spacing = 2;
    const auto placed = pack_rectangles(sizes, w, h, spacing, PackingMethod::MaxRects);
    int pages = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      pages = std::max(pages, placed[i].page + 1);
      const Vec2 size_i = placed[i].rotated ? Vec2(sizes[i].y(), sizes[i].x()) : sizes[i];
      EXPECT_GE(placed[i].x, -1e-9);
      EXPECT_GE(placed[i].y, -1e-9);
      EXPECT_LE(placed[i].x + size_i.x(), w + 1e-6);
      EXPECT_LE(placed[i].y + size_i.y(), h + 1e-6);
      for (std::size_t j = 0; j < i; ++j) {
        if (placed[i].page != placed[j].page) continue;
        const Vec2 size_j = placed[j].rotated ? Vec2(sizes[j].y(), sizes[j].x()) : sizes[j];
        const bool apart = placed[i].x + size_i.x() + spacing <= placed[j].x + 1e-6 ||
                           placed[j].x + size_j.x() + spacing <= placed[i].x + 1e-6 ||
                           placed[i].y + size_i.y() + spacing <= placed[j].y + 1e-6 ||
                           placed[j].y + size_j.y() + spacing <= placed[i].y + 1e-6;
        EXPECT_TRUE(apart) << "rectangles " << i << " and " << j;
      }
    }
    const int shelf = shelf_pack_page_count(sizes, w, h, spacing);
    EXPECT_LE(pages, shelf);
    total_packed += pages;
    total_shelf += shelf;
  }
  EXPECT_LT(total_packed, total_shelf);
  std::cout << "[ pages    ] MaxRects " << total_packed << ", shelf " << total_shelf
            << " on 30 random sets of 40 rectangles\n";
}

// One tall piece and six small ones: shelves waste the height beside the tall piece
// (2 pages); MaxRects stacks the small ones beside it (1 page).
TEST(LayoutPages, PackerBeatsShelfOnTallAndSmallPieces) {
  std::vector<FlatStrip> strips = {cell_strip(0, 1, 5, 120, 50)};
  for (int k = 1; k <= 6; ++k) strips.push_back(cell_strip(k, 3, 2, 20, 20));
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.pages.size(), 1u);
  EXPECT_EQ(layout.shelf_page_count, 2);
  options.packing = PackingMethod::Shelf;
  EXPECT_EQ(layout_pages(strips, options).pages.size(), 2u);
}

}  // namespace
}  // namespace papercraft
