#include "core/effort.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace papercraft {
namespace {

// A rectangle [0, w] x [0, h] whose top edge is a saw: from (w, h) to the left, one point per
// millimetre, every other one raised 1 mm, over `teeth_mm`; then straight on to (0, h).
std::vector<Vec2> saw_rectangle(double w, double h, int teeth_mm) {
  std::vector<Vec2> loop{{0, 0}, {w, 0}};
  for (int i = 0; i <= teeth_mm; ++i) loop.push_back({w - i, h + (i % 2)});
  loop.push_back({0, h});
  return loop;
}

TEST(SawtoothCorners, NoneOnARectangleACircleOrAStraightRunOfPoints) {
  EXPECT_EQ(count_sawtooth_corners({{0, 0}, {20, 0}, {20, 20}, {0, 20}}), 0);
  std::vector<Vec2> circle;
  for (int i = 0; i < 64; ++i) {
    const double a = 2 * std::numbers::pi * i / 64;
    circle.push_back({10 * std::cos(a), 10 * std::sin(a)});
  }
  EXPECT_EQ(count_sawtooth_corners(circle), 0);
  std::vector<Vec2> dense;
  for (int i = 0; i <= 40; ++i) dense.push_back({0.5 * i, 0});
  dense.push_back({20, 20});
  dense.push_back({0, 20});
  EXPECT_EQ(count_sawtooth_corners(dense), 0);
}

TEST(SawtoothCorners, EveryInnerCornerOfASawCounts) {
  // 19 inner points of the saw turn by 90 degrees, alternately left and right, 1.4 mm apart;
  // its two ends turn by 45 degrees and the rectangle's corners all turn the same way.
  EXPECT_EQ(count_sawtooth_corners(saw_rectangle(30, 10, 20)), 19);
  // Either way round, and with every point doubled.
  std::vector<Vec2> reversed = saw_rectangle(30, 10, 20);
  std::reverse(reversed.begin(), reversed.end());
  EXPECT_EQ(count_sawtooth_corners(reversed), 19);
  std::vector<Vec2> doubled;
  for (const Vec2& p : saw_rectangle(30, 10, 20)) doubled.insert(doubled.end(), {p, p});
  EXPECT_EQ(count_sawtooth_corners(doubled), 19);
  // Sharper than 60 degrees only: a saw of 25-degree slopes turns by 50 and is no sawtooth.
  std::vector<Vec2> flat_saw{{0, 0}, {30, 0}};
  const double rise = std::tan(25 * std::numbers::pi / 180);
  for (int i = 0; i <= 20; ++i) flat_saw.push_back({30.0 - i, 10 + rise * (i % 2)});
  flat_saw.push_back({0, 10});
  EXPECT_EQ(count_sawtooth_corners(flat_saw), 0);
  // Above 40 degrees its 19 inner corners count, and the corner where it starts (it turns by 65
  // degrees one way, the first tooth by 50 the other way); where it ends, it turns by 25.
  EXPECT_EQ(count_sawtooth_corners(flat_saw, 40.0), 20);
}

TEST(SawtoothCorners, AShallowStepCountsAndADeepOneDoesNot) {
  auto step = [](double depth) {
    return std::vector<Vec2>{{0, 0},   {30, 0},          {30, 10},
                             {15, 10}, {15, 10 + depth}, {0, 10 + depth}};
  };
  EXPECT_EQ(count_sawtooth_corners(step(2)), 2);
  EXPECT_EQ(count_sawtooth_corners(step(3.9)), 2);
  EXPECT_EQ(count_sawtooth_corners(step(5)), 0);
  EXPECT_EQ(count_sawtooth_corners(step(5), 60.0, 6.0), 2);
  // Fewer than three distinct points: no corner.
  EXPECT_EQ(count_sawtooth_corners({{0, 0}, {1, 0}, {1, 0}}), 0);
  EXPECT_EQ(count_sawtooth_corners({}), 0);
}

// A piece whose outline is `loop` (counter-clockwise), fanned from its first point, with its
// edges cut unless listed in `seams` (edge i from loop[i] to loop[i + 1] -> label).
PlacedPiece piece(const std::string& name, const std::vector<Vec2>& loop,
                  const std::map<int, std::string>& seams, std::vector<PieceSeam> listed) {
  PlacedPiece p;
  p.name = name;
  p.vertices = loop;
  for (int i = 1; i + 1 < static_cast<int>(loop.size()); ++i) p.triangles.push_back({0, i, i + 1});
  p.outline = {loop};
  for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
    PlacedEdge e;
    e.a = loop[i];
    e.b = loop[(i + 1) % loop.size()];
    if (auto it = seams.find(i); it != seams.end()) {
      e.kind = EdgeKind::Seam;
      e.label = it->second;
    }
    p.edges.push_back(e);
  }
  p.seams = std::move(listed);
  return p;
}

// Two pages: a 20 mm square (1) with a seam A to a 20 x 4 mm band (2) and a seam B with
// itself (its left and right sides); a 30 x 10 mm piece with a 2 mm step (3) and a seam C
// without a partner, glued with a joining strip.
PatternLayout two_pages() {
  PatternLayout layout;
  layout.pages.resize(2);
  layout.pages[0].pieces.push_back(piece("1", {{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                                         {{0, "A"}, {1, "B"}, {3, "B"}},
                                         {{"A", "2", true}, {"B", "1", true}, {"B", "1", false}}));
  layout.pages[0].pieces.push_back(
      piece("2", {{30, 0}, {50, 0}, {50, 4}, {30, 4}}, {{2, "A"}}, {{"A", "1", false}}));
  layout.pages[1].pieces.push_back(
      piece("3", {{0, 0}, {30, 0}, {30, 10}, {15, 10}, {15, 12}, {0, 12}, {0, 10}}, {{1, "C"}},
            {{"C", "", false}}));
  PlacedPiece joint;
  joint.name = "C";
  layout.pages[1].joints.push_back(joint);
  return layout;
}

TEST(AssemblyEffort, EveryTermCountedOnTwoPages) {
  const AssemblyEffort effort = assembly_effort(two_pages(), {});
  const EffortTerms& t = effort.terms;
  EXPECT_EQ(t.printed_pieces, 3);
  EXPECT_EQ(t.joining_strips, 1);
  EXPECT_EQ(t.things_to_cut, 4);
  EXPECT_EQ(t.seam_chains, 3);  // A, B and C
  EXPECT_EQ(t.self_seams, 1);   // B
  // A: 20 mm on each side, B: 20 on each side (one piece), C: 10 on its only side.
  EXPECT_NEAR(t.glue_length_mm, 50.0, 1e-9);
  EXPECT_EQ(t.sawtooth_corners, 2);  // the step of piece 3
  EXPECT_EQ(t.small_pieces, 1);      // piece 2: 80 mm^2
  EXPECT_EQ(t.narrow_pieces, 1);     // piece 2: 4 mm wide everywhere
  const EffortWeights w;
  EXPECT_NEAR(effort.total,
              4 * w.piece + 3 * w.seam + 0.05 * w.glue_per_metre + 2 * w.sawtooth + w.small_piece +
                  w.narrow_piece,
              1e-9);
}

TEST(AssemblyEffort, LimitsAndWeightsChangeOnlyTheirTerms) {
  // No limits: nothing is small or narrow.
  const AssemblyEffort free = assembly_effort(two_pages(), {.min_width_mm = 0, .min_area_mm2 = 0});
  EXPECT_EQ(free.terms.small_pieces, 0);
  EXPECT_EQ(free.terms.narrow_pieces, 0);
  // Stricter limits: piece 3 (330 mm^2, at most 12 mm wide) is small and narrow too.
  const AssemblyEffort strict =
      assembly_effort(two_pages(), {.min_width_mm = 13, .min_area_mm2 = 400});
  EXPECT_EQ(strict.terms.small_pieces, 2);
  EXPECT_EQ(strict.terms.narrow_pieces, 2);
  EffortWeights only_seams{};
  only_seams.piece = only_seams.glue_per_metre = only_seams.sawtooth = 0;
  only_seams.small_piece = only_seams.narrow_piece = 0;
  only_seams.seam = 2;
  EXPECT_DOUBLE_EQ(assembly_effort(two_pages(), {}, only_seams).total, 6.0);
  EXPECT_DOUBLE_EQ(assembly_effort(PatternLayout{}, {}).total, 0.0);
}

TEST(AssemblyEffort, WeightsThatAreNegativeOrNotNumbersAreNamed) {
  EXPECT_EQ(EffortWeights{}.invalid(), "");
  EffortWeights w;
  w.sawtooth = -1;
  EXPECT_EQ(w.invalid(), "sawtooth");
  w = {};
  w.glue_per_metre = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(w.invalid(), "glue_per_metre");
  w = {};
  w.narrow_piece = std::numeric_limits<double>::infinity();
  EXPECT_EQ(w.invalid(), "narrow_piece");
}

}  // namespace
}  // namespace papercraft
