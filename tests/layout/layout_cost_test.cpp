// LayoutCost and compare_layouts: the one judgement between two layouts of a model.
#include "nodes/layout/layout_cost.h"

#include <gtest/gtest.h>

namespace papercraft::layout_internal {
namespace {

LayoutCost cost(int pages, int overflowing, int pieces) {
  LayoutCost c;
  c.pages = pages;
  c.overflowing = overflowing;
  c.pieces = pieces;
  return c;
}

TEST(LayoutCost, FewerOverflowingPiecesWinsWhateverThePages) {
  EXPECT_EQ(compare_layouts(cost(9, 0, 50), cost(4, 1, 10), 3), Verdict::Better);
  EXPECT_EQ(compare_layouts(cost(2, 2, 10), cost(9, 1, 50), 3), Verdict::Worse);
}

TEST(LayoutCost, PagesSavedAgainstPiecesAddedAtTheThreshold) {
  // 2 pages saved: up to 2 x splits_per_page more pieces.
  EXPECT_EQ(compare_layouts(cost(8, 0, 16), cost(10, 0, 10), 3), Verdict::Better);
  EXPECT_EQ(compare_layouts(cost(8, 0, 17), cost(10, 0, 10), 3), Verdict::TooCostly);
  EXPECT_EQ(compare_layouts(cost(8, 0, 17), cost(10, 0, 10), 4), Verdict::Better);
  // Fewer pieces and fewer pages is always better.
  EXPECT_EQ(compare_layouts(cost(8, 0, 9), cost(10, 0, 10), 1), Verdict::Better);
}

TEST(LayoutCost, NoPageSavedKeepsTheIncumbent) {
  EXPECT_EQ(compare_layouts(cost(10, 0, 10), cost(10, 0, 10), 3), Verdict::Worse);
  EXPECT_EQ(compare_layouts(cost(10, 0, 5), cost(10, 0, 10), 3), Verdict::Worse);
  EXPECT_EQ(compare_layouts(cost(11, 0, 5), cost(10, 0, 10), 3), Verdict::Worse);
}

// Over a grid of costs: never both better than the other, a layout never better than itself,
// and Better is transitive (the tries keep a best so far, so the order must not cycle).
TEST(LayoutCost, TheJudgementIsAStrictOrderOnEveryGrid) {
  std::vector<LayoutCost> costs;
  for (int pages = 1; pages <= 5; ++pages)
    for (int overflowing = 0; overflowing <= 2; ++overflowing)
      for (int pieces = 1; pieces <= 12; pieces += 2)
        costs.push_back(cost(pages, overflowing, pieces));
  for (int splits_per_page : {1, 3}) {
    auto better = [&](const LayoutCost& a, const LayoutCost& b) {
      return compare_layouts(a, b, splits_per_page) == Verdict::Better;
    };
    for (const LayoutCost& a : costs) {
      EXPECT_FALSE(better(a, a));
      for (const LayoutCost& b : costs) {
        EXPECT_FALSE(better(a, b) && better(b, a));
        if (!better(a, b)) continue;
        for (const LayoutCost& c : costs)
          if (better(b, c)) {
            // Fewer overflowing pieces somewhere in the chain, or at as many a chain of kept
            // tries each saving pages at a bounded price: the sum saves pages at that bound.
            EXPECT_TRUE(better(a, c)) << a.pages << "/" << a.pieces << " > " << b.pages << "/"
                                      << b.pieces << " > " << c.pages << "/" << c.pieces;
          }
      }
    }
  }
}

TEST(LayoutCost, CountsModelPiecesAndMeanFill) {
  PatternLayout layout;
  layout.pages.resize(2);
  layout.pages[0].pieces.resize(3);
  layout.pages[0].joints.resize(2);  // joining strips are no model pieces
  layout.pages[1].pieces.resize(1);
  layout.stats.page_fill = {0.5, 0.25};
  const LayoutCost c = layout_cost(layout, 1);
  EXPECT_EQ(c.pages, 2);
  EXPECT_EQ(c.pieces, 4);
  EXPECT_EQ(c.overflowing, 1);
  EXPECT_DOUBLE_EQ(c.fill, 0.375);
}

}  // namespace
}  // namespace papercraft::layout_internal
