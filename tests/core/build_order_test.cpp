#include "core/build_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/errors.h"

namespace papercraft {
namespace {

// A hand-made layout: rectangular pieces of given areas, joined by straight seams of given
// lengths (each seam one edge on each side, with its label and the piece across).
class HandLayout {
 public:
  void piece(const std::string& name, double width, double height, int page = 0) {
    PlacedPiece piece;
    piece.name = name;
    piece.vertices = {{0, 0}, {width, 0}, {width, height}, {0, height}};
    piece.triangles = {{0, 1, 2}, {0, 2, 3}};
    if (static_cast<int>(layout_.pages.size()) <= page) layout_.pages.resize(page + 1);
    layout_.pages[page].pieces.push_back(piece);
  }

  void seam(const std::string& a, const std::string& b, const std::string& label, double mm) {
    side(a, b, label, mm);
    side(b, a, label, mm);
  }

  PatternLayout& layout() { return layout_; }

 private:
  void side(const std::string& on, const std::string& across, const std::string& label, double mm) {
    PlacedPiece& piece = find(on);
    piece.edges.push_back({Vec2(0, 0), Vec2(mm, 0), EdgeKind::Seam, label, false});
    piece.seams.push_back({label, across, false});
  }

  PlacedPiece& find(const std::string& name) {
    for (Page& page : layout_.pages)
      for (PlacedPiece& piece : page.pieces)
        if (piece.name == name) return piece;
    throw std::logic_error("no piece " + name);
  }

  PatternLayout layout_;
};

std::vector<std::string> pieces_in_order(const BuildOrder& order) {
  std::vector<std::string> names;
  for (const BuildStep& step : order.steps) names.push_back(step.piece);
  return names;
}

std::vector<std::string> texts(const BuildOrder& order) {
  std::vector<std::string> lines;
  for (const BuildStep& step : order.steps) lines.push_back(build_step_text(step));
  return lines;
}

// Five pieces; 2 and 3 are large and equally central, 2 the larger.
HandLayout five_pieces() {
  HandLayout hand;
  hand.piece("1", 10, 10);
  hand.piece("2", 20, 20);
  hand.piece("3", 19, 20);
  hand.piece("4", 5, 10);
  hand.piece("5", 5, 10);
  hand.seam("1", "2", "A1", 10);
  hand.seam("2", "3", "A2", 30);
  hand.seam("2", "4", "A3", 5);
  hand.seam("3", "4", "A4", 20);
  hand.seam("4", "5", "A5", 8);
  hand.seam("1", "3", "A6", 4);
  return hand;
}

TEST(BuildOrder, GrowsByTheLongestSeamToWhatIsBuilt) {
  HandLayout hand = five_pieces();
  const BuildOrder order = build_order(hand.layout());
  // From 2: 3 shares 30 mm; then 4 (20 + 5) before 1 (10 + 4); then 1; then 5 (8).
  EXPECT_EQ(pieces_in_order(order), (std::vector<std::string>{"2", "3", "4", "1", "5"}));
  EXPECT_EQ(order.parts, 1);
  EXPECT_EQ(texts(order), (std::vector<std::string>{"1: start with 2", "2: glue 3 to 2 along A2",
                                                    "3: glue 4 to 3 along A4; then to 2 along A3",
                                                    "4: glue 1 to 2 along A1; then to 3 along A6",
                                                    "5: glue 5 to 4 along A5"}));
  const BuildStep& third = order.steps[2];
  EXPECT_EQ(third.step, 3);
  EXPECT_EQ(third.attach_to, "3");
  ASSERT_EQ(third.seams.size(), 2u);
  EXPECT_EQ(third.seams[0].label, "A4");
  EXPECT_FALSE(third.seams[0].closes_loop);
  EXPECT_DOUBLE_EQ(third.seams[0].length_mm, 20.0);
  EXPECT_EQ(third.seams[1].label, "A3");
  EXPECT_EQ(third.seams[1].partner, "2");
  EXPECT_TRUE(third.seams[1].closes_loop);
  EXPECT_TRUE(order.steps[0].seams.empty());
  EXPECT_EQ(order.step_of("1")->step, 4);
  EXPECT_EQ(order.step_of("9"), nullptr);
}

TEST(BuildOrder, StartsFromTheMostCentralLargePiece) {
  // A chain 1-2-3-4-5: 1 is the largest, but 3 (half its area) sits in the middle.
  HandLayout hand;
  hand.piece("1", 20, 20);
  hand.piece("2", 5, 5);
  hand.piece("3", 10, 20);
  hand.piece("4", 5, 5);
  hand.piece("5", 5, 5);
  hand.seam("1", "2", "A1", 10);
  hand.seam("2", "3", "A2", 10);
  hand.seam("3", "4", "A3", 10);
  hand.seam("4", "5", "A4", 10);
  EXPECT_EQ(build_order(hand.layout()).steps.front().piece, "3");
  // Only the largest qualifies when the share is 1.
  EXPECT_EQ(build_order(hand.layout(), {.large_share = 1.0}).steps.front().piece, "1");
}

TEST(BuildOrder, SeparatePartsEachStartTheirOwnSequenceLargerFirst) {
  HandLayout hand;
  hand.piece("1", 10, 10);  // part {1, 2}: 200 mm²
  hand.piece("2", 10, 10);
  hand.piece("3", 20, 10);  // part {3, 4, 5}: 600 mm²
  hand.piece("4", 20, 10);
  hand.piece("5", 20, 10);
  hand.piece("6", 1, 1);  // alone
  hand.seam("1", "2", "A1", 10);
  hand.seam("3", "4", "B1", 10);
  hand.seam("4", "5", "B2", 12);
  const BuildOrder order = build_order(hand.layout());
  EXPECT_EQ(order.parts, 3);
  EXPECT_EQ(pieces_in_order(order), (std::vector<std::string>{"4", "5", "3", "1", "2", "6"}));
  std::vector<int> parts;
  for (const BuildStep& step : order.steps) parts.push_back(step.part);
  EXPECT_EQ(parts, (std::vector<int>{1, 1, 1, 2, 2, 3}));
  EXPECT_EQ(build_step_text(order.steps[3]), "4: start part 2 with 1");
  EXPECT_EQ(build_step_text(order.steps[4]), "5: glue 2 to 1 along A1");
  EXPECT_EQ(build_step_text(order.steps[5]), "6: start part 3 with 6");
  EXPECT_TRUE(order.steps[5].seams.empty());
}

TEST(BuildOrder, TiesGoToTheLowerNumberWhateverThePages) {
  // A star: 1 in the middle, 2..11 round it, all alike. Number order, not text order: 9
  // before 10, and 2a, 2b after 2 and before 3.
  auto star = [](bool reversed) {
    HandLayout hand;
    std::vector<std::string> names = {"1", "2", "2a", "2b", "3", "9", "10", "11"};
    if (reversed) std::reverse(names.begin(), names.end());
    for (std::size_t k = 0; k < names.size(); ++k)
      hand.piece(names[k], names[k] == "1" ? 30 : 10, names[k] == "1" ? 30 : 10,
                 static_cast<int>(k % 3));
    for (const std::string& name : names)
      if (name != "1") hand.seam("1", name, "S" + name, 10);
    return build_order(hand.layout());
  };
  const BuildOrder forward = star(false);
  EXPECT_EQ(pieces_in_order(forward),
            (std::vector<std::string>{"1", "2", "2a", "2b", "3", "9", "10", "11"}));
  EXPECT_EQ(texts(star(true)), texts(forward));
}

TEST(BuildOrder, LengthsAndAreasAlikeToAThousandthAreTies) {
  // Rounding in the layout makes alike pieces differ in the last digits: the number decides.
  HandLayout hand;
  hand.piece("1", 30, 30);
  hand.piece("2", 10, 10);
  hand.piece("3", 10, 10 + 1e-7);
  hand.piece("4", 10, 10);
  hand.piece("5", 10 + 1e-7, 10);
  hand.seam("1", "2", "A1", 10);
  hand.seam("1", "3", "A2", 10 + 1e-6);
  hand.seam("4", "5", "B1", 7);
  const BuildOrder order = build_order(hand.layout());
  EXPECT_EQ(pieces_in_order(order), (std::vector<std::string>{"1", "2", "3", "4", "5"}));
  // ... but a real difference counts.
  HandLayout longer;
  longer.piece("1", 30, 30);
  longer.piece("2", 10, 10);
  longer.piece("3", 10, 10);
  longer.seam("1", "2", "A1", 10);
  longer.seam("1", "3", "A2", 10.01);
  EXPECT_EQ(pieces_in_order(build_order(longer.layout())),
            (std::vector<std::string>{"1", "3", "2"}));
}

TEST(BuildOrder, SeamsOfAPieceWithItselfAreGluedAtItsStepAndClosingSeamsLast) {
  HandLayout hand;
  hand.piece("1", 20, 20);
  hand.piece("2", 10, 10);
  hand.piece("3", 10, 10);
  hand.seam("1", "2", "A1", 10);
  hand.seam("1", "3", "A2", 8);
  hand.seam("2", "3", "A3", 6);
  hand.seam("3", "3", "C1", 5);  // a tube closed along a ruling: both sides on 3
  const BuildOrder order = build_order(hand.layout());
  ASSERT_EQ(order.steps.size(), 3u);
  EXPECT_EQ(build_step_text(order.steps[2]),
            "3: glue 3 to 1 along A2; then to 2 along A3; close 3 along C1");
  const GlueSeam& last = order.steps[2].seams.back();
  EXPECT_EQ(last.partner, "3");
  EXPECT_TRUE(last.closes_loop);
  EXPECT_DOUBLE_EQ(last.length_mm, 5.0);  // each side 5 mm, counted once
}

TEST(BuildOrder, OnePieceAndNoPieces) {
  HandLayout hand;
  hand.piece("1", 10, 10);
  const BuildOrder one = build_order(hand.layout());
  ASSERT_EQ(one.steps.size(), 1u);
  EXPECT_EQ(build_step_text(one.steps[0]), "1: start with 1");
  EXPECT_EQ(one.parts, 1);
  const BuildOrder none = build_order(PatternLayout{});
  EXPECT_TRUE(none.steps.empty());
  EXPECT_EQ(none.parts, 0);
}

TEST(BuildOrder, RefusesTwoPiecesOfOneName) {
  HandLayout hand;
  hand.piece("1", 10, 10, 0);
  hand.piece("1", 10, 10, 1);
  EXPECT_THROW(build_order(hand.layout()), InvalidInputException);
}

TEST(BuildOrder, PieceNamesInNumberOrder) {
  EXPECT_TRUE(piece_name_less("2", "10"));
  EXPECT_TRUE(piece_name_less("2", "2a"));
  EXPECT_TRUE(piece_name_less("2b", "3"));
  EXPECT_TRUE(piece_name_less("9b", "10a"));
  EXPECT_FALSE(piece_name_less("10", "9"));
  EXPECT_FALSE(piece_name_less("4", "4"));
}

}  // namespace
}  // namespace papercraft
