// Triangles divided to cut strips larger than the page: the cut, and bit-identical seam points.
#include "nodes/layout/divide_triangles.h"

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

// The same square with nesting: its triangles are divided (each edge in n equal parts) and the
// strip cut across them into pieces that fit the page, along the divided cells' edges: no piece
// overflows, each is a rectangle (4 corners), and the surface is laid out whole.
TEST(LayoutPages, TriangleLargerThanThePageIsCutAcrossItsDividedTriangles) {
  const std::vector<FlatStrip> strips = {cell_strip(0, 1, 1, 400, 400)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  bool divided = false;
  for (const std::string& w : layout.warnings) {
    EXPECT_EQ(w.find("overflows"), std::string::npos) << w;
    divided = divided || w.rfind("triangles divided", 0) == 0;
  }
  EXPECT_TRUE(divided);
  expect_valid_layout(layout, strips, options);
  int pieces = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      ++pieces;
      ASSERT_EQ(piece.outline.size(), 1u);
      // Corners: outline points where the direction turns.
      const auto& loop = piece.outline[0];
      int corners = 0;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 a = loop[(i + loop.size() - 1) % loop.size()], b = loop[i],
                   c = loop[(i + 1) % loop.size()];
        corners += std::abs(cross((b - a).normalized(), (c - b).normalized())) > 1e-6;
      }
      EXPECT_EQ(corners, 4) << "piece " << piece.name;
      EXPECT_NE(piece.strip_vertex.end(),
                std::find(piece.strip_vertex.begin(), piece.strip_vertex.end(), -1));
    }
  // 400 x 400 mm on pages of 178 x 256 mm (room for tabs kept): two slabs of 200 x 400 mm,
  // each cut in three of 133 x 200 mm (10 x 10 cells of 40 mm: cut along cell edges).
  EXPECT_EQ(pieces, 6);
  EXPECT_EQ(static_cast<int>(layout.pages.size()), 6);
}

// Both sides of every seam of divided strips get the same points (bit for bit), and the surface and
// its flat image are kept: each new triangle is an isometric copy (flat edges as long as 3D ones).
TEST(LayoutDivide, BothSidesOfEverySeamGetTheSamePoints) {
  // Scaled to coordinates no binary fraction is, and every other strip's vertices numbered
  // backwards: the two sides of a seam see its ends in opposite index order.
  auto strips = prism_strips(square_footprint(40), 60, 0);
  for (std::size_t k = 0; k < strips.size(); ++k) {
    FlatStrip& s = strips[k];
    for (Vec3& v : s.vertices3d) v *= 0.37;
    for (Vec2& v : s.vertices2d) v *= 0.37;
    if (k % 2 == 1) continue;
    const int last = static_cast<int>(s.vertices3d.size()) - 1;
    std::reverse(s.vertices3d.begin(), s.vertices3d.end());
    std::reverse(s.vertices2d.begin(), s.vertices2d.end());
    for (Triangle& t : s.triangles)
      for (int& v : t) v = last - v;
    for (BoundaryEdge& e : s.boundary) e.v0 = last - e.v0, e.v1 = last - e.v1;
  }
  for (int n : {1, 2, 3, 5, 7}) {
    const auto divided = layout_internal::divide_triangles(strips, n);
    ASSERT_EQ(divided.size(), strips.size());
    std::map<int, const FlatStrip*> by_id;
    for (const FlatStrip& s : divided) by_id[s.id] = &s;
    for (std::size_t k = 0; k < strips.size(); ++k) {
      const FlatStrip &before = strips[k], &after = divided[k];
      ASSERT_EQ(after.triangles.size(), before.triangles.size() * n * n);
      ASSERT_EQ(after.boundary.size(), before.boundary.size() * n);
      double area_before = 0, area_after = 0;
      for (const Triangle& t : before.triangles)
        area_before += 0.5 * cross(before.vertices2d[t[1]] - before.vertices2d[t[0]],
                                   before.vertices2d[t[2]] - before.vertices2d[t[0]]);
      for (const Triangle& t : after.triangles) {
        const double a = 0.5 * cross(after.vertices2d[t[1]] - after.vertices2d[t[0]],
                                     after.vertices2d[t[2]] - after.vertices2d[t[0]]);
        EXPECT_GT(a, 0);  // the strip's own orientation
        area_after += a;
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR((after.vertices2d[t[i]] - after.vertices2d[t[(i + 1) % 3]]).norm(),
                      (after.vertices3d[t[i]] - after.vertices3d[t[(i + 1) % 3]]).norm(), 1e-9);
      }
      EXPECT_NEAR(area_after, area_before, 1e-9 * area_before);
      for (const BoundaryEdge& e : after.boundary) {
        if (e.kind != EdgeKind::Seam || e.partner_edge < 0) continue;
        const FlatStrip& other = *by_id.at(e.neighbour_strip);
        const BoundaryEdge& partner = other.boundary.at(e.partner_edge);
        EXPECT_EQ(partner.label, e.label);
        EXPECT_EQ(other.vertices3d[partner.v0], after.vertices3d[e.v1]);
        EXPECT_EQ(other.vertices3d[partner.v1], after.vertices3d[e.v0]);
      }
    }
    // Bit for bit: the layout pairs seam edges by their label and points. Each seam edge has
    // one edge with its label running the other way between the same points.
    using Key = std::tuple<std::string, std::array<double, 3>, std::array<double, 3>>;
    std::map<Key, int> edges;
    auto point = [](const Vec3& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
    for (const FlatStrip& s : divided)
      for (const BoundaryEdge& e : s.boundary)
        if (e.kind == EdgeKind::Seam)
          ++edges[{e.label, point(s.vertices3d[e.v0]), point(s.vertices3d[e.v1])}];
    int checked = 0;
    for (const auto& [key, count] : edges) {
      const auto& [label, a, b] = key;
      EXPECT_EQ(count, 1);
      const auto reverse = edges.find({label, b, a});
      EXPECT_TRUE(reverse != edges.end()) << "n " << n << " seam " << label;
      ++checked;
    }
    EXPECT_EQ(checked, 2 * (4 + 4 + 1) * n);  // T, B and A, each side divided in n
  }
}

}  // namespace
}  // namespace papercraft
