#include "core/dual_cuts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/edge_map.h"
#include "core/errors.h"
#include "core/triangle_mesh.h"
#include "core/union_find.h"

namespace papercraft {
namespace {

// The inner edges of a triangle set (edges shared by exactly two triangles), as triangle pairs.
std::vector<std::pair<int, int>> inner_edges(const std::vector<Triangle>& triangles) {
  std::vector<std::pair<int, int>> inner;
  for (const auto& [edge, ts] : edge_triangles(triangles))
    if (ts.size() == 2) inner.emplace_back(ts[0], ts[1]);
  return inner;
}

// An n x m grid of squares, each cut into two triangles; vertex (i, j) is i * (m + 1) + j.
std::vector<Triangle> grid(int n, int m) {
  std::vector<Triangle> triangles;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = i * (m + 1) + j, b = a + 1, c = a + m + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  return triangles;
}

TEST(DualCuts, EveryEdgeOfARowOfTrianglesCutsItInTwo) {
  // 10 triangles in a zigzag row, triangle k joined to k + 1 across edge (k + 1, k + 2).
  std::vector<Triangle> row;
  for (int k = 0; k < 10; ++k) row.push_back({k, k + 1, k + 2});
  const auto inner = inner_edges(row);
  ASSERT_EQ(inner.size(), 9u);
  const DualCuts cuts(10, inner);
  EXPECT_TRUE(cuts.connected());
  for (std::size_t e = 0; e < inner.size(); ++e) {
    ASSERT_TRUE(cuts.splits(e));
    // The side of the lower triangle is 0..lower.
    const int lower = std::min(inner[e].first, inner[e].second);
    const int side = inner[e].first == lower ? lower + 1 : 10 - lower - 1;
    EXPECT_EQ(cuts.first_side_size(e), side);
    for (int t = 0; t < 10; ++t)
      EXPECT_EQ(cuts.on_first_side(e, t), (t <= lower) == (inner[e].first == lower));
  }
}

TEST(DualCuts, NoEdgeAroundAnInnerVertexCutsAFanInTwo) {
  // Six triangles around vertex 0, closed.
  std::vector<Triangle> fan;
  for (int k = 0; k < 6; ++k) fan.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const auto inner = inner_edges(fan);
  ASSERT_EQ(inner.size(), 6u);
  const DualCuts cuts(6, inner);
  EXPECT_TRUE(cuts.connected());
  for (std::size_t e = 0; e < inner.size(); ++e) EXPECT_FALSE(cuts.splits(e));
}

TEST(DualCuts, OnlyTheTailOfAFanWithATailCutsIt) {
  std::vector<Triangle> shape;
  for (int k = 0; k < 6; ++k) shape.push_back({0, 1 + k, 1 + (k + 1) % 6});
  shape.push_back({1, 7, 2});  // across the fan's rim edge 1-2
  shape.push_back({2, 7, 8});  // beyond it
  const auto inner = inner_edges(shape);
  ASSERT_EQ(inner.size(), 8u);
  const DualCuts cuts(8, inner);
  // Triangle 6 hangs from the fan's triangle 0, and 7 from 6: only those two edges cut.
  int splitting = 0;
  for (std::size_t e = 0; e < inner.size(); ++e) {
    if (!cuts.splits(e)) continue;
    ++splitting;
    const auto [first, second] = inner[e];
    const std::pair<int, int> edge{std::min(first, second), std::max(first, second)};
    if (edge == std::make_pair(6, 7)) {
      EXPECT_EQ(cuts.first_side_size(e), first == 7 ? 1 : 7);
      EXPECT_EQ(cuts.on_first_side(e, 7), first == 7);
      EXPECT_EQ(cuts.on_first_side(e, 3), first == 6);
    } else {
      ASSERT_EQ(edge, std::make_pair(0, 6)) << "an edge of the fan cuts it";
      EXPECT_EQ(cuts.first_side_size(e), first == 6 ? 2 : 6);
      EXPECT_EQ(cuts.on_first_side(e, 7), first == 6);
      EXPECT_EQ(cuts.on_first_side(e, 3), first == 0);
    }
  }
  EXPECT_EQ(splitting, 2);
}

TEST(DualCuts, TwoTrianglesJoinedTwiceAreNotCutByEitherEdge) {
  const DualCuts cuts(2, {{0, 1}, {1, 0}});
  EXPECT_FALSE(cuts.splits(0));
  EXPECT_FALSE(cuts.splits(1));
}

TEST(DualCuts, ASetInPiecesIsNotCutInTwoByAnyEdge) {
  std::vector<Triangle> two = grid(1, 2);
  for (const Triangle& t : grid(1, 2)) two.push_back({t[0] + 100, t[1] + 100, t[2] + 100});
  const auto inner = inner_edges(two);
  const DualCuts cuts(8, inner);
  EXPECT_FALSE(cuts.connected());
  for (std::size_t e = 0; e < inner.size(); ++e) EXPECT_FALSE(cuts.splits(e));
  EXPECT_TRUE(DualCuts(0, {}).connected());
  EXPECT_TRUE(DualCuts(1, {}).connected());
}

// Against the brute force: for every edge, the parts union-find leaves without it.
TEST(DualCuts, AgreesWithCuttingEachEdgeOnGridsWithHoles) {
  std::mt19937 random(12);
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<Triangle> full = grid(6, 7);
    std::vector<Triangle> kept;
    std::bernoulli_distribution keep(trial < 20 ? 0.8 : 0.6);
    for (const Triangle& t : full)
      if (keep(random)) kept.push_back(t);
    const int count = static_cast<int>(kept.size());
    const auto inner = inner_edges(kept);
    const DualCuts cuts(count, inner);
    UnionFind all(count);
    for (const auto& [a, b] : inner) all.unite(a, b);
    bool connected = true;
    for (int t = 0; t < count; ++t) connected = connected && all.find(t) == all.find(0);
    ASSERT_EQ(cuts.connected(), connected) << "trial " << trial;
    for (std::size_t e = 0; e < inner.size(); ++e) {
      UnionFind parts(count);
      for (std::size_t f = 0; f < inner.size(); ++f)
        if (f != e) parts.unite(inner[f].first, inner[f].second);
      const std::size_t first = parts.find(inner[e].first), second = parts.find(inner[e].second);
      bool two = first != second;
      int on_first = 0;
      for (int t = 0; t < count && two; ++t) {
        const std::size_t r = parts.find(t);
        two = r == first || r == second;
        on_first += r == first;
      }
      ASSERT_EQ(cuts.splits(e), two) << "trial " << trial << " edge " << e;
      if (!two) continue;
      EXPECT_EQ(cuts.first_side_size(e), on_first);
      for (int t = 0; t < count; ++t)
        ASSERT_EQ(cuts.on_first_side(e, t), parts.find(t) == first) << "trial " << trial;
    }
  }
}

TEST(DualCuts, BadInputThrows) {
  EXPECT_THROW(DualCuts(-1, {}), InvalidInputException);
  EXPECT_THROW(DualCuts(2, {{0, 2}}), InvalidInputException);
  EXPECT_THROW(DualCuts(2, {{1, 1}}), InvalidInputException);
  EXPECT_THROW(DualCuts(2, {{-1, 0}}), InvalidInputException);
}

}  // namespace
}  // namespace papercraft
