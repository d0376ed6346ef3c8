// The layout's tab style, tab angle and print side as a person writes them in a config: listed
// by `papercraft nodes`, refused by `validate` (exit 2, file:line:column) when out of range or
// not one of the choices, and taken by `run`.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/command.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::run_command;

const std::string kSource = PAPERCRAFT_SOURCE_DIR;

// The default config with the layout's params extended by `extra`, written into `dir`.
std::filesystem::path config_with(const std::filesystem::path& dir, const std::string& extra) {
  std::string text = testing::read_text(kSource + "/configs/default.yaml");
  const std::string from = "params: {page: A4, margin_mm: 10}";
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos)
    text.replace(at, from.size(), "params: {page: A4, margin_mm: 10, " + extra + "}");
  const auto path = dir / "config.yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(TabStyleParams, NodesListsThemWithTheirDefaults) {
  const auto r = run_command("nodes");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* text : {"tab_style", "[one|alternate|both|none]", "tab_angle_degrees",
                           "alternate_run_mm", "print_side", "[front|back]"})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
}

TEST(TabStyleParams, ValidateRefusesUnknownChoicesAndAnglesOutOfRange) {
  const auto dir = testing::fresh_temp_dir("tab-style-params");
  for (const auto& [extra, message] : std::vector<std::pair<std::string, std::string>>{
           {"tab_style: zigzag",
            "config.yaml:15:85: parameter 'tab_style' of node 'layout': expected one of one, "
            "alternate, both, none, got 'zigzag'"},
           {"print_side: inside",
            "config.yaml:15:86: parameter 'print_side' of node 'layout': expected one of front, "
            "back, got 'inside'"},
           {"tab_angle_degrees: -10",
            "config.yaml:15:93: parameter 'tab_angle_degrees' of node 'layout': must be greater "
            "than 0 and at most 90, got -10"},
           {"tab_angle_degrees: 95",
            "config.yaml:15:93: parameter 'tab_angle_degrees' of node 'layout': must be greater "
            "than 0 and at most 90, got 95"},
           {"tab_angle_degrees: 0", "config.yaml:15:93: parameter 'tab_angle_degrees'"},
           {"alternate_run_mm: 0",
            "parameter 'alternate_run_mm' of node 'layout': must be "
            "greater than 0, got 0"}}) {
    const auto config = config_with(dir, extra);
    const auto r = run_command("validate " + config.string());
    EXPECT_EQ(r.exit_code, 2) << extra << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << extra << "\n" << r.output;
  }
  for (const std::string good :
       {"tab_style: both, tab_angle_degrees: 90", "tab_style: alternate, alternate_run_mm: 25",
        "tab_style: none, print_side: back"}) {
    const auto r = run_command("validate " + config_with(dir, good).string());
    EXPECT_EQ(r.exit_code, 0) << good << "\n" << r.output;
  }
}

TEST(TabStyleParams, RunTakesThem) {
  const auto dir = testing::fresh_temp_dir("tab-style-run");
  const auto mesh = dir / "box.obj";
  ASSERT_EQ(run_command("generate box " + mesh.string()).exit_code, 0);
  const auto config = config_with(dir, "tab_style: none, print_side: back");
  const auto r = run_command("run -q --config " + config.string() + " --out " +
                             (dir / "out").string() + " " + mesh.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto pieces =
      nlohmann::json::parse(testing::read_text(dir / "out" / "box" / "pieces.json"));
  int seams = 0;
  for (const auto& piece : pieces.at("pieces")) {
    // Mirrored: the transform keeps the strip's handedness on the page.
    const auto& m = piece.at("transform").at("linear");
    EXPECT_GT(m[0].get<double>() * m[3].get<double>() - m[1].get<double>() * m[2].get<double>(),
              0.0);
    for (const auto& seam : piece.at("seams")) {
      ++seams;
      EXPECT_FALSE(seam.at("tab").get<bool>());
    }
  }
  EXPECT_GT(seams, 0);
  EXPECT_TRUE(pieces.at("joints").empty());
}

}  // namespace
}  // namespace papercraft
