// The papercraft command: subcommands, exit codes, batch behaviour with bad inputs.

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

TEST(Cli, NodesListsEveryStage) {
  const auto r = run_command("nodes");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const char* name :
       {"load.openmesh", "segment.none", "select.geodesic", "select.exhaustive", "ruled.twist_dp",
        "hausdorff.bounded", "hausdorff.sampled", "cut.harmonic", "unfold.sequential",
        "merge.congruent", "layout.pages", "export.files"}) {
    EXPECT_NE(r.output.find(name), std::string::npos) << name;
  }
  EXPECT_NE(r.output.find("param precision (number, default 0.05)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("output: reject -> RejectedStrip"), std::string::npos);
}

TEST(Cli, ValidateEveryShippedConfig) {
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/configs")) {
    const auto r = run_command("validate " + entry.path().string());
    EXPECT_EQ(r.exit_code, 0) << entry.path() << "\n" << r.output;
    EXPECT_NE(r.output.find(": ok ("), std::string::npos) << r.output;
  }
}

TEST(Cli, ValidateReportsPositionAndExitCode2) {
  const auto dir = testing::fresh_temp_dir("validate");
  std::ofstream(dir / "bad.yaml") << "nodes:\n  load: {impl: load.openmesh, to: [nowhere]}\n";
  const auto r = run_command("validate " + (dir / "bad.yaml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("bad.yaml:2:36: edge to unknown node 'nowhere'"), std::string::npos)
      << r.output;
}

TEST(Cli, ValidateChecksWhatOnlyTheNodeKnows) {
  const auto dir = testing::fresh_temp_dir("validate-node");
  std::ofstream(dir / "bad.yaml")
      << "nodes:\n  load: {impl: load.openmesh, to: [segment]}\n"
         "  segment: {impl: segment.fuzzy, params: {alternatives: [depth=4]}, to: [select]}\n"
         "  select: {impl: select.geodesic, to: [ruled]}\n"
         "  ruled: {impl: ruled.twist_dp, to: [hausdorff]}\n"
         "  hausdorff: {impl: hausdorff.bounded, to: {accept: [unfold], reject: [cut]}}\n"
         "  cut: {impl: cut.harmonic, back: [select]}\n"
         "  unfold: {impl: unfold.sequential, to: [merge]}\n"
         "  merge: {impl: merge.congruent, to: [layout]}\n"
         "  layout: {impl: layout.pages, to: [export]}\n"
         "  export: {impl: export.files}\n";
  const auto r = run_command("validate " + (dir / "bad.yaml").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("unknown setting 'depth'"), std::string::npos) << r.output;
}

TEST(Cli, GenerateWritesMesh) {
  const auto dir = testing::fresh_temp_dir("generate");
  const auto r = run_command("generate torus " + (dir / "torus.off").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "torus.off"));
  const auto bad = run_command("generate nosuchshape " + (dir / "x.obj").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("sphere"), std::string::npos) << "lists the known shapes";
  const auto param =
      run_command("generate sphere " + (dir / "s.obj").string() + " --param radius=-1");
  EXPECT_EQ(param.exit_code, 2) << param.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.obj"));
}

TEST(Cli, BatchWithABadMeshKeepsTheOthersAndExits1) {
  const auto dir = testing::fresh_temp_dir("batch");
  std::filesystem::create_directories(dir / "meshes");
  ASSERT_EQ(run_command("generate open_cylinder " + (dir / "meshes/a.obj").string()).exit_code, 0);
  ASSERT_EQ(run_command("generate cone_frustum " + (dir / "meshes/b.off").string()).exit_code, 0);
  std::ofstream(dir / "meshes/broken.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n";
  std::ofstream(dir / "job.yaml") << "inputs: [meshes/*]\noutput: out\ntolerance: 2%\nthreads: 2\n";
  const auto r = run_command("batch " + (dir / "job.yaml").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("broken.off"), std::string::npos) << "the error names the file";
  const auto batch = nlohmann::json::parse(testing::read_text(dir / "out/batch.json"));
  ASSERT_EQ(batch.at("models").get<int>(), 3);
  EXPECT_EQ(batch.at("failed").get<int>(), 1);
  for (const auto& row : batch.at("results")) {
    const std::string name = row.at("name");
    if (name == "broken") {
      EXPECT_EQ(row.at("status"), "error");
      EXPECT_FALSE(std::filesystem::exists(dir / "out/broken"));
    } else {
      EXPECT_EQ(row.at("status"), "ok") << row.dump();
      EXPECT_TRUE(std::filesystem::exists(dir / "out" / name / "report.json"));
      EXPECT_TRUE(std::filesystem::exists(dir / "out" / name / "pattern.pdf"));
    }
  }
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir / "out")) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
        << "temporary file left behind: " << entry.path();
  }
}

TEST(Cli, BatchShardsSplitTheInputs) {
  const auto dir = testing::fresh_temp_dir("shard");
  for (const char* name : {"a", "b", "c"}) {
    ASSERT_EQ(run_command("generate open_cylinder " + (dir / (std::string(name) + ".obj")).string())
                  .exit_code,
              0);
  }
  std::ofstream(dir / "job.yaml") << "inputs: ['*.obj']\noutput: out\nshard: 2/2\n";
  const auto r = run_command("batch " + (dir / "job.yaml").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const auto batch = nlohmann::json::parse(testing::read_text(dir / "out/batch.shard-2-of-2.json"));
  ASSERT_EQ(batch.at("models").get<int>(), 1);
  EXPECT_EQ(batch.at("shard"), "2/2");
  EXPECT_EQ(batch.at("results")[0].at("name"), "b");
  EXPECT_FALSE(std::filesystem::exists(dir / "out/batch.json")) << "a shard's own file only";
  // --shard on the command line wins over the job's; --list names what the shard would run.
  const auto list = run_command("batch " + (dir / "job.yaml").string() + " --shard 1/3 --list");
  EXPECT_EQ(list.exit_code, 0) << list.output;
  EXPECT_NE(list.output.find("a\t"), std::string::npos) << list.output;
  EXPECT_EQ(list.output.find("b\t"), std::string::npos) << list.output;
  const auto bad = run_command("batch " + (dir / "job.yaml").string() + " --shard 4/3");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--shard: expected a shard like 1/4"), std::string::npos) << bad.output;
}

TEST(Cli, BadJobFileAndBadToleranceExit2) {
  const auto dir = testing::fresh_temp_dir("badjob");
  std::ofstream(dir / "job.yaml") << "inputs: [none/*.obj]\noutptu: x\n";
  const auto r = run_command("batch " + (dir / "job.yaml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("job.yaml:2:1: unknown key 'outptu'"), std::string::npos) << r.output;
  const auto t = run_command("run x.obj --tolerance -3%");
  EXPECT_EQ(t.exit_code, 2);
  EXPECT_NE(t.output.find("tolerance"), std::string::npos) << t.output;
}

TEST(Cli, HeightTakesUnits) {
  const auto dir = testing::fresh_temp_dir("height");
  const auto mesh = dir / "cylinder.obj";
  ASSERT_EQ(run_command("generate open_cylinder " + mesh.string()).exit_code, 0);
  auto mm_per_unit = [&](const std::string& height) {
    const auto out = dir / height;
    const auto r =
        run_command("run " + mesh.string() + " -q --height " + height + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << height << "\n" << r.output;
    const auto report = nlohmann::json::parse(testing::read_text(out / "cylinder" / "report.json"));
    return report.at("result").at("mm_per_unit").get<double>();
  };
  const double mm = mm_per_unit("150");
  EXPECT_GT(mm, 0.0);
  EXPECT_DOUBLE_EQ(mm_per_unit("15cm"), mm);
  EXPECT_NEAR(mm_per_unit("2in"), mm * 50.8 / 150.0, 1e-9 * mm);
  const auto bad = run_command("run " + mesh.string() + " -q --height 150furlongs --out " +
                               (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--height: expected a positive length"), std::string::npos)
      << bad.output;
}

// A model's folder is replaced whole: a rerun that makes fewer pages leaves no page of the
// earlier run, and a failed rerun leaves the earlier result untouched and no staging folder.
TEST(Cli, RerunReplacesTheModelsFolderWhole) {
  const auto dir = testing::fresh_temp_dir("rerun");
  const auto mesh = dir / "cylinder.obj";
  ASSERT_EQ(run_command("generate open_cylinder " + mesh.string()).exit_code, 0);
  const auto out = dir / "out";
  auto svg_pages = [&] {
    int pages = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out / "cylinder"))
      pages += entry.path().extension() == ".svg" ? 1 : 0;
    return pages;
  };
  ASSERT_EQ(
      run_command("run " + mesh.string() + " -q --height 900 --out " + out.string()).exit_code, 0);
  const int big = svg_pages();
  ASSERT_GT(big, 1);
  std::ofstream(out / "cylinder" / "stale.txt") << "from an earlier run";
  ASSERT_EQ(
      run_command("run " + mesh.string() + " -q --height 100 --out " + out.string()).exit_code, 0);
  EXPECT_EQ(svg_pages(), 1);
  EXPECT_FALSE(std::filesystem::exists(out / "cylinder" / "stale.txt"));
  // A run that fails (a sphere of the same name that may not be cut twice) keeps the last
  // result.
  std::filesystem::create_directories(dir / "other");
  const auto sphere = dir / "other" / "cylinder.obj";
  ASSERT_EQ(run_command("generate sphere " + sphere.string()).exit_code, 0);
  std::string config = testing::read_text(kSource + "/configs/default.yaml");
  const std::string cut = "impl: cut.harmonic,";
  config.replace(config.find(cut), cut.size(), cut + " params: {max_depth: 1},");
  std::ofstream(dir / "strict.yaml") << config;
  const auto failed = run_command("run " + sphere.string() + " -q --tolerance 0.1% --out " +
                                  out.string() + " -c " + (dir / "strict.yaml").string());
  EXPECT_NE(failed.exit_code, 0);
  EXPECT_EQ(svg_pages(), 1);
  for (const auto& entry : std::filesystem::directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
}

TEST(Cli, MissingFileIsAnErrorRow) {
  const auto dir = testing::fresh_temp_dir("missing");
  const auto r =
      run_command("run --out " + (dir / "out").string() + " " + (dir / "nope.obj").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("nope.obj"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace papercraft
