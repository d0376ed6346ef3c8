// End to end: the flat patterns the default pipeline writes (strips.json, report.json).

#include <gtest/gtest.h>

#include <set>

#include <cstdlib>
#include <map>

#include "core/generate.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::run_pipeline;

Vec3 v3(const nlohmann::json& j) {
  return Vec3(j[0], j[1], j[2]);
}
Vec2 v2(const nlohmann::json& j) {
  return Vec2(j[0], j[1]);
}

// Isometry and orientation of every flat triangle; every boundary edge a seam or open;
// every seam label on exactly two edge chains' worth of sides with matching 3D lengths.
void expect_valid_pattern(const nlohmann::json& flat) {
  std::map<std::string, double> seam_length_by_label;
  std::map<std::string, int> seam_edges_by_label;
  for (const auto& strip : flat.at("strips")) {
    const auto& p3 = strip.at("vertices3d");
    const auto& p2 = strip.at("vertices2d");
    ASSERT_EQ(p3.size(), p2.size());
    for (const auto& t : strip.at("triangles")) {
      const int i = t[0], j = t[1], k = t[2];
      for (auto [a, b] : {std::pair{i, j}, std::pair{j, k}, std::pair{k, i}}) {
        const double l3 = (v3(p3[a]) - v3(p3[b])).norm();
        const double l2 = (v2(p2[a]) - v2(p2[b])).norm();
        EXPECT_NEAR(l2, l3, 1e-9 * std::max(1.0, l3)) << "strip " << strip.at("id");
      }
      const Vec2 e1 = v2(p2[j]) - v2(p2[i]), e2 = v2(p2[k]) - v2(p2[i]);
      const double area3 = 0.5 * (v3(p3[j]) - v3(p3[i])).cross(v3(p3[k]) - v3(p3[i])).norm();
      if (area3 > 1e-12) {
        EXPECT_GT(e1.x() * e2.y() - e1.y() * e2.x(), 0.0) << "mirrored triangle";
      }
    }
    for (const auto& e : strip.at("boundary")) {
      const std::string kind = e.at("kind");
      EXPECT_TRUE(kind == "seam" || kind == "open") << "unexpected boundary kind " << kind;
      if (kind == "seam") {
        const std::string label = e.at("label");
        seam_edges_by_label[label]++;
        seam_length_by_label[label] +=
            (v3(p3[e.at("v0").get<int>()]) - v3(p3[e.at("v1").get<int>()])).norm();
      }
    }
  }
  for (const auto& [label, count] : seam_edges_by_label) {
    EXPECT_GE(count, 2) << "seam " << label << " has one side only";
  }
}

TEST(Pattern, CylinderWithTwoHolesIsOneFlatStrip) {
  const auto out = run_pipeline(cylinder_two_holes(), "2%", "two_holes");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  EXPECT_GE(out.report.at("result").at("flat_strips_before_merge").get<int>(), 2);
  EXPECT_EQ(out.report.at("result").at("flat_strips").get<int>(), 1);
  expect_valid_pattern(out.flat);
}

TEST(Pattern, PawnAndFigureEightPatternsAreIsometricAndSeamed) {
  for (const char* shape : {"pawn", "figure_eight"}) {
    SCOPED_TRACE(shape);
    const auto out = run_pipeline(generate_shape(shape, {}), "2%", shape);
    ASSERT_TRUE(out.result.ok) << out.result.error;
    expect_valid_pattern(out.flat);
    const auto& result = out.report.at("result");
    EXPECT_GE(result.at("pages").get<int>(), 1);
    EXPECT_LE(result.at("pages").get<int>(), result.at("shelf_pages").get<int>());
    const std::string svg = testing::read_text(out.dir / "pattern-01.svg");
    for (const char* layer : {"id=\"cut\"", "id=\"mountain\"", "id=\"valley\"", "id=\"tabs\"",
                              "id=\"labels\"", "id=\"print\""}) {
      EXPECT_NE(svg.find(layer), std::string::npos) << layer;
    }
    EXPECT_EQ(testing::read_text(out.dir / "pattern.pdf").rfind("%PDF", 0), 0u);
    // The PDF renders (poppler, as a print shop would) to the assembly guide and exactly the
    // pages the layout made.
    const auto render = out.dir / "render";
    ASSERT_EQ(std::system(("pdftoppm -r 8 -png '" + (out.dir / "pattern.pdf").string() + "' '" +
                           render.string() + "'")
                              .c_str()),
              0);
    int rendered = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out.dir)) {
      rendered += entry.path().filename().string().rfind("render", 0) == 0 ? 1 : 0;
    }
    EXPECT_EQ(rendered, 1 + result.at("pages").get<int>());
    EXPECT_TRUE(std::filesystem::exists(out.dir / "guide.png"));
    // pieces.json: numbered 1..N (letters for split strips), every piece on a real page.
    const auto pieces = nlohmann::json::parse(testing::read_text(out.dir / "pieces.json"));
    std::set<int> numbers;
    for (const auto& piece : pieces.at("pieces")) {
      const std::string name = piece.at("name").get<std::string>();
      numbers.insert(std::stoi(name));
      EXPECT_GE(piece.at("page").get<int>(), 1);
      EXPECT_LE(piece.at("page").get<int>(), result.at("pages").get<int>());
    }
    ASSERT_FALSE(numbers.empty());
    EXPECT_EQ(*numbers.begin(), 1);
    EXPECT_EQ(*numbers.rbegin(), static_cast<int>(numbers.size())) << "numbers with gaps";
    // Every seam has a tab or a joining strip; a joining strip names a seam of the pieces.
    const auto& layout = out.report.at("layout");
    EXPECT_EQ(layout.at("seams_without_tab").get<int>(), 0);
    EXPECT_EQ(pieces.at("joints").size(), layout.at("joining_strips").get<std::size_t>());
    std::set<std::string> seam_labels;
    for (const auto& piece : pieces.at("pieces"))
      for (const auto& seam : piece.at("seams")) seam_labels.insert(seam.at("label"));
    for (const auto& joint : pieces.at("joints"))
      EXPECT_EQ(seam_labels.count(joint.at("seam").get<std::string>()), 1u);
  }
}

TEST(Pattern, FeatureSegmentationOfABoxIsCertifiedWithSixSegments) {
  ASSERT_NE(default_config_text().find("segment.feature"), std::string::npos)
      << "the default config segments along sharp edges";
  const auto out = run_pipeline(box(), "2%", "box");
  ASSERT_TRUE(out.result.ok) << out.result.error;
  EXPECT_EQ(out.report.at("result").at("segments").get<int>(), 6);
  EXPECT_TRUE(out.report.at("result").at("certified").get<bool>());
  EXPECT_EQ(out.strips.size(), 6u) << "each flat face is one strip";
  expect_valid_pattern(out.flat);
}

}  // namespace
}  // namespace papercraft
