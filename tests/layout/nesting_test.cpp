// Nesting by true outlines: orders, glued pieces on one page, the gap kept, pages.
#include "nodes/layout/nesting.h"

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

// The nesting tries three orders (by area, longest side, bounding rectangle) and keeps the best
// fill: never more pages than the area order alone, and on random sets of long bars, squares
// and triangles sometimes fewer pages or an emptier last page.
TEST(LayoutNesting, ThreeOrdersNeverLoseToOne) {
  using layout_internal::NestOptions;
  using layout_internal::NestShape;
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec2 area(190, 270);
  int better = 0;
  for (int round = 0; round < 8; ++round) {
    std::vector<NestShape> shapes;
    for (int k = 0; k < 18; ++k) {
      const double a = 120 + 60 * unit(random), b = 30 + 50 * unit(random);
      NestShape shape;
      switch (k % 3) {
        case 0:  // a long bar
          shape.convex.push_back({Vec2(0, 0), Vec2(a, 0), Vec2(a, 12), Vec2(0, 12)});
          break;
        case 1:  // a square
          shape.convex.push_back({Vec2(0, 0), Vec2(b, 0), Vec2(b, b), Vec2(0, b)});
          break;
        default:  // a right triangle
          shape.convex.push_back({Vec2(0, 0), Vec2(0.5 * a, 0), Vec2(0, b)});
      }
      shapes.push_back(std::move(shape));
    }
    NestOptions one, three;
    one.rotations = three.rotations = 8;
    one.cell_mm = three.cell_mm = 1.0;
    one.orders = 1;
    three.orders = 3;
    int pages_one = 0, pages_three = 0;
    const auto by_one = layout_internal::nest_shapes(shapes, area, one, &pages_one);
    const auto by_three = layout_internal::nest_shapes(shapes, area, three, &pages_three);
    EXPECT_LE(pages_three, pages_one) << "round " << round;
    auto last_area = [&](const std::vector<layout_internal::NestPlacement>& placements, int pages) {
      double sum = 0;
      for (std::size_t i = 0; i < shapes.size(); ++i)
        if (placements[i].page == pages - 1)
          sum += std::abs(layout_internal::signed_area(shapes[i].convex[0]));
      return sum;
    };
    if (pages_three < pages_one ||
        last_area(by_three, pages_three) < last_area(by_one, pages_one) - 1e-9)
      ++better;
    for (const auto& placement : by_three) EXPECT_GE(placement.page, 0);
  }
  EXPECT_GE(better, 1) << "the other orders never helped";
  std::cout << "[ orders   ] three orders did better on " << better << " of 8 sets\n";
}

// Half rings (arcs packed by rectangles leave their insides empty): nesting keeps the
// spacing between any two pieces, measured exactly on their triangles and tab flaps, and never
// needs more pages than the rectangle packer; on arcs it needs fewer.
// Six regions of a model, each a large piece (100 x 120 mm) glued to two small ones
// (40 x 50 mm), given region by region: largest first puts the large pieces two to a page and
// the small ones after them, mostly away from their partner; the fill in the given order, in
// runs of half a page, puts every small piece on its partner's page, on as many pages. Without
// neighbours it is not tried; on random shapes it never costs a page or parts neighbours.
TEST(LayoutNesting, PiecesGluedToEachOtherStayOnOnePageWhereThatCostsNoPage) {
  using layout_internal::NestOptions;
  using layout_internal::NestShape;
  auto rectangle = [](double w, double h) {
    NestShape shape;
    shape.convex.push_back({Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)});
    return shape;
  };
  const Vec2 area(190, 277);
  std::vector<NestShape> shapes;
  NestOptions options;
  options.rotations = 4;
  options.cell_mm = 1.0;
  for (int region = 0; region < 6; ++region) {
    const int big = static_cast<int>(shapes.size());
    shapes.push_back(rectangle(100, 120));
    for (int k = 0; k < 2; ++k) {
      options.neighbours.push_back({big, static_cast<int>(shapes.size())});
      shapes.push_back(rectangle(40, 50));
    }
  }
  auto together = [&](const std::vector<layout_internal::NestPlacement>& placements) {
    int count = 0;
    for (const auto& [a, b] : options.neighbours) count += placements[a].page == placements[b].page;
    return count;
  };
  NestOptions plain = options;
  plain.grouped = false;
  int pages_plain = 0, pages_grouped = 0;
  const auto apart = layout_internal::nest_shapes(shapes, area, plain, &pages_plain);
  const auto near = layout_internal::nest_shapes(shapes, area, options, &pages_grouped);
  EXPECT_EQ(pages_grouped, pages_plain);
  EXPECT_LT(together(apart), 12);
  EXPECT_EQ(together(near), 12);
  std::cout << "[ nesting  ] glued pairs on one page: " << together(apart)
            << " of 12 largest first, " << together(near) << " in runs\n";
  // Random shapes glued in a chain: never more pages, never fewer pairs on one page.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> side(20.0, 120.0);
  for (int round = 0; round < 4; ++round) {
    std::vector<NestShape> chain;
    NestOptions glued;
    glued.rotations = 8;
    glued.cell_mm = 1.0;
    for (int k = 0; k < 16; ++k) {
      chain.push_back(rectangle(side(random), side(random)));
      if (k > 0) glued.neighbours.push_back({k - 1, k});
    }
    NestOptions loose = glued;
    loose.grouped = false;
    int p_loose = 0, p_glued = 0;
    const auto a = layout_internal::nest_shapes(chain, area, loose, &p_loose);
    const auto b = layout_internal::nest_shapes(chain, area, glued, &p_glued);
    EXPECT_LE(p_glued, p_loose) << "round " << round;
    int near_a = 0, near_b = 0;
    for (const auto& [x, y] : glued.neighbours) {
      near_a += a[x].page == a[y].page;
      near_b += b[x].page == b[y].page;
    }
    EXPECT_GE(near_b, near_a) << "round " << round;
  }
}

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t =
      d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - a - t * d).norm();
}

double polygon_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) {
      best = std::min(best, segment_distance(a[i], b[j], b[(j + 1) % b.size()]));
      best = std::min(best, segment_distance(b[j], a[i], a[(i + 1) % a.size()]));
    }
  return best;
}

FlatStrip half_ring(int id, double inner, double outer, int segments) {
  FlatStrip s;
  s.id = id;
  for (int k = 0; k <= segments; ++k) {
    const double angle = std::numbers::pi * k / segments;
    for (double r : {inner, outer}) {
      const Vec2 p(r * std::cos(angle), r * std::sin(angle));
      s.vertices2d.push_back(p);
      s.vertices3d.emplace_back(p.x(), p.y(), 0.0);
    }
  }
  for (int k = 0; k < segments; ++k) {
    const int a = 2 * k, b = 2 * k + 1, c = 2 * k + 2, d = 2 * k + 3;
    s.triangles.push_back({a, b, c});
    s.triangles.push_back({b, d, c});
  }
  s.boundary = flat_boundary(s.triangles);
  for (BoundaryEdge& e : s.boundary) e.kind = EdgeKind::Open;
  return s;
}

TEST(LayoutPages, NestingKeepsTheGapAndNeedsNoMorePagesThanRectangles) {
  std::vector<FlatStrip> strips;
  for (int k = 0; k < 30; ++k)
    strips.push_back(half_ring(k, 30 + (k % 5) * 4, 40 + (k % 5) * 4, 24));
  LayoutOptions options;
  options.scale = 1;
  options.spacing_mm = 2;
  const PatternLayout nested = layout_pages(strips, options);
  expect_valid_layout(nested, strips, options);
  options.packing = PackingMethod::MaxRects;
  const PatternLayout boxed = layout_pages(strips, options);
  EXPECT_LE(nested.pages.size(), boxed.pages.size());
  EXPECT_LT(nested.pages.size(), boxed.pages.size()) << "nested arcs must save paper";
  EXPECT_EQ(nested.rectangle_page_count, static_cast<int>(boxed.pages.size()));
  for (const Page& page : nested.pages) {
    std::vector<std::vector<std::vector<Vec2>>> shapes;  // per piece: its polygons
    for (const PlacedPiece& piece : page.pieces) {
      std::vector<std::vector<Vec2>> polygons;
      for (const Triangle& t : piece.triangles)
        polygons.push_back({piece.vertices[t[0]], piece.vertices[t[1]], piece.vertices[t[2]]});
      for (const Tab& tab : piece.tabs)
        for (const auto& flap : tab.flaps) polygons.push_back(flap);
      shapes.push_back(std::move(polygons));
    }
    for (std::size_t i = 0; i < shapes.size(); ++i)
      for (std::size_t j = i + 1; j < shapes.size(); ++j)
        for (const auto& a : shapes[i])
          for (const auto& b : shapes[j])
            ASSERT_GE(polygon_distance(a, b), options.spacing_mm - 1e-6)
                << "pieces " << page.pieces[i].name << " and " << page.pieces[j].name;
  }
  std::cout << "[ pages    ] nested " << nested.pages.size() << ", rectangles "
            << boxed.pages.size() << " for 30 half rings\n";
}

}  // namespace
}  // namespace papercraft
