// End to end: the build order in pieces.json and assembly.html, as the default pipeline writes
// them: every piece has one step, each step glues its piece to pieces built before it, and one
// thread or two give the very same files.

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>

#include "core/generate.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::read_text;
using testing::run_pipeline;

void expect_build_order(const nlohmann::json& pieces_file) {
  const nlohmann::json& pieces = pieces_file.at("pieces");
  std::map<std::string, int> step_of;
  std::set<int> steps;
  for (const auto& piece : pieces) {
    step_of[piece.at("name")] = piece.at("step").get<int>();
    steps.insert(piece.at("step").get<int>());
  }
  ASSERT_EQ(steps.size(), pieces.size()) << "two pieces at one step";
  EXPECT_EQ(*steps.begin(), 1);
  EXPECT_EQ(*steps.rbegin(), static_cast<int>(pieces.size()));
  std::set<int> parts;
  for (const auto& piece : pieces) {
    const std::string name = piece.at("name");
    const int step = piece.at("step");
    parts.insert(piece.at("part").get<int>());
    const std::string glue_to = piece.at("glue_to");
    if (!glue_to.empty()) EXPECT_LT(step_of.at(glue_to), step) << name;
    // Each seam glued at this step is one of the piece's, to a piece built before (or itself).
    std::set<std::string> labels;
    for (const auto& seam : piece.at("seams")) labels.insert(seam.at("label"));
    bool attaching = true;
    for (const auto& glue : piece.at("glue")) {
      EXPECT_EQ(labels.count(glue.at("label")), 1u) << name << " " << glue.at("label");
      const std::string partner = glue.at("partner");
      EXPECT_TRUE(partner == name || step_of.at(partner) < step) << name << " to " << partner;
      EXPECT_GT(glue.at("length_mm").get<double>(), 0.0);
      // The attaching seams first, those closing loops after.
      if (glue.at("closes_loop").get<bool>()) attaching = false;
      EXPECT_TRUE(glue.at("closes_loop").get<bool>() || attaching) << name;
      EXPECT_EQ(glue.at("closes_loop").get<bool>(), partner != glue_to) << name;
    }
  }
  EXPECT_EQ(static_cast<int>(parts.size()), pieces_file.at("parts").get<int>());
}

TEST(Assembly, BuildOrderAndViewerAreTheSameOnOneAndTwoThreads) {
  const TriangleMesh pawn = generate_shape("pawn", {});
  const auto one = run_pipeline(pawn, "2%", "pawn", 1);
  const auto two = run_pipeline(pawn, "2%", "pawn", 2);
  ASSERT_TRUE(one.result.ok) << one.result.error;
  ASSERT_TRUE(two.result.ok) << two.result.error;
  ASSERT_NE(one.dir, two.dir);
  const std::string pieces = read_text(one.dir / "pieces.json");
  EXPECT_EQ(pieces, read_text(two.dir / "pieces.json"));
  const std::string html = read_text(one.dir / "assembly.html");
  ASSERT_GT(html.size(), 100'000u);
  EXPECT_TRUE(html == read_text(two.dir / "assembly.html"));
  expect_build_order(nlohmann::json::parse(pieces));
}

TEST(Assembly, GuidePagesComeBeforeThePatternPages) {
  const auto out = run_pipeline(generate_shape("figure_eight", {}), "2%", "figure_eight_guide");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  const auto pieces = nlohmann::json::parse(read_text(out.dir / "pieces.json"));
  expect_build_order(pieces);
  // Every step's line is in the PDF's text, once, before the first pattern page.
  const auto text_file = out.dir / "pattern.txt";
  ASSERT_EQ(std::system(("pdftotext '" + (out.dir / "pattern.pdf").string() + "' '" +
                         text_file.string() + "'")
                            .c_str()),
            0);
  const std::string text = read_text(text_file);
  ASSERT_NE(text.find("Build order"), std::string::npos);
  const std::size_t first_page = text.find("page 1 / ");
  ASSERT_NE(first_page, std::string::npos);
  const std::regex head("(^|[^0-9])([0-9]+): (start|glue) ");
  std::multiset<int> printed;
  for (auto it = std::sregex_iterator(text.begin(), text.begin() + first_page, head);
       it != std::sregex_iterator(); ++it)
    printed.insert(std::stoi((*it)[2]));
  std::multiset<int> expected;
  for (const auto& piece : pieces.at("pieces")) expected.insert(piece.at("step").get<int>());
  EXPECT_EQ(printed, expected);
}

}  // namespace
}  // namespace papercraft
