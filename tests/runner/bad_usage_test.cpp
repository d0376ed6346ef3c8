// Bad usage is refused before any model runs, with exit code 2 and a message that names the
// setting, the range or choices it takes and where it was written; sizes no one wants (a
// tolerance above 50%, a pattern over max_pages) are refused with the numbers.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "support/command.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::run_command;

const std::string kSource = PAPERCRAFT_SOURCE_DIR;

// The default config with `from` replaced by `to`, written into `dir`.
std::filesystem::path edited_default_config(const std::filesystem::path& dir,
                                            const std::string& from, const std::string& to) {
  std::string text = testing::read_text(kSource + "/configs/default.yaml");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const auto path = dir / "config.yaml";
  std::ofstream(path) << text;
  return path;
}

std::filesystem::path small_mesh(const std::filesystem::path& dir) {
  const auto mesh = dir / "cylinder.obj";
  EXPECT_EQ(run_command("generate open_cylinder " + mesh.string()).exit_code, 0);
  return mesh;
}

struct BadValue {
  std::string from, to, message;
};

TEST(BadUsage, ValidateRefusesEveryOutOfRangeParameter) {
  const auto dir = testing::fresh_temp_dir("bad-params");
  const std::string layout = "params: {page: A4, margin_mm: 10}";
  for (const BadValue& bad : std::vector<BadValue>{
           {layout, "params: {page: A4, margin_mm: -5}",
            "config.yaml:15:70: parameter 'margin_mm' of node 'layout': must be at least 0, got "
            "-5"},
           {layout, "params: {tab_width_mm: -3}",
            "parameter 'tab_width_mm' of node 'layout': must be at least 0, got -3"},
           {layout, "params: {page: B5}",
            "unknown page size 'B5': use A3, A4, A5, Letter, Legal, Tabloid"},
           {"precision: 0.05", "precision: -1",
            "config.yaml:11:60: parameter 'precision' of node 'hausdorff': must be greater than "
            "0, got -1"},
           {"tolerance: 2%", "height_mm: 0\ntolerance: 2%",
            "config.yaml:4:12: height_mm must be greater than 0"}}) {
    const auto config = edited_default_config(dir, bad.from, bad.to);
    const auto r = run_command("validate " + config.string());
    EXPECT_EQ(r.exit_code, 2) << bad.to << "\n" << r.output;
    EXPECT_NE(r.output.find(bad.message), std::string::npos) << bad.to << "\n" << r.output;
    // `run` refuses it the same way before loading any mesh.
    const auto run = run_command("run -q --config " + config.string() + " --out " +
                                 (dir / "out").string() + " " + kSource + "/examples/pawn.obj");
    EXPECT_EQ(run.exit_code, 2) << bad.to << "\n" << run.output;
    EXPECT_NE(run.output.find(bad.message), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "pawn")) << bad.to;
  }
}

TEST(BadUsage, NodesListsEveryPageSize) {
  const auto r = run_command("nodes");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* page : {"A3", "A4", "A5", "Letter", "Legal", "Tabloid", "WIDTHxHEIGHT"}) {
    EXPECT_NE(r.output.find(page), std::string::npos) << page;
  }
}

TEST(BadUsage, NumericRangesReadAsAPersonWritesThem) {
  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {"run x.obj --threads -1", "--threads: must be at least 0, got -1"},
           {"run x.obj --scale 0", "--scale: must be greater than 0, got 0"},
           {"run x.obj --min-area -2", "--min-area: must be at least 0, got -2"},
           {"run x.obj --max-pages 0", "--max-pages: must be at least 1, got 0"},
           {"run x.obj --grace abc", "--grace: expected a number, got 'abc'"},
           {"batch job.yaml --threads -4", "--threads: must be at least 0, got -4"}}) {
    const auto r = run_command(arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << arguments << "\n" << r.output;
    EXPECT_LT(r.output.size(), 400u) << "no 300-digit number: " << r.output;
  }
}

TEST(BadUsage, ToleranceAboveHalfTheModelIsRefusedUnlessAllowed) {
  const auto dir = testing::fresh_temp_dir("large-tolerance");
  const auto mesh = small_mesh(dir);
  const auto r =
      run_command("run -q --tolerance 200% --out " + (dir / "out").string() + " " + mesh.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--tolerance 200% is above 50% of the largest side"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--allow-large-tolerance"), std::string::npos) << r.output;
  // An absolute tolerance is judged against each model's size.
  const auto absolute =
      run_command("run -q --tolerance 1000 --out " + (dir / "out").string() + " " + mesh.string());
  EXPECT_EQ(absolute.exit_code, 1) << absolute.output;
  EXPECT_NE(absolute.output.find("of the model's largest side"), std::string::npos)
      << absolute.output;
  const auto allowed = run_command("run -q --tolerance 60% --allow-large-tolerance --out " +
                                   (dir / "out").string() + " " + mesh.string());
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
}

TEST(BadUsage, PatternOverMaxPagesIsRefusedBeforeRefinement) {
  const auto dir = testing::fresh_temp_dir("max-pages");
  const auto mesh = small_mesh(dir);
  const auto huge =
      run_command("run -q --height 1e9 --out " + (dir / "out").string() + " " + mesh.string());
  EXPECT_EQ(huge.exit_code, 1) << huge.output;
  EXPECT_NE(huge.output.find("pages"), std::string::npos) << huge.output;
  EXPECT_NE(huge.output.find("more than max_pages 100"), std::string::npos) << huge.output;
  EXPECT_NE(huge.output.find("--max-pages"), std::string::npos) << huge.output;
  const auto one = run_command("run -q --height 300 --max-pages 1 --out " + (dir / "out").string() +
                               " " + mesh.string());
  EXPECT_EQ(one.exit_code, 1) << one.output;
  EXPECT_NE(one.output.find("more than max_pages 1;"), std::string::npos) << one.output;
  const auto raised = run_command("run -q --height 300 --max-pages 10 --out " +
                                  (dir / "out").string() + " " + mesh.string());
  EXPECT_EQ(raised.exit_code, 0) << raised.output;
}

TEST(BadUsage, UnwritableOutputIsReportedOnceBeforeAnyModel) {
  const auto dir = testing::fresh_temp_dir("unwritable");
  std::ofstream(dir / "file") << "x";
  const auto r = run_command("run -q --out " + (dir / "file" / "out").string() + " " + kSource +
                             "/examples/pawn.obj");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("cannot create folder"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("segment"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("pawn"), std::string::npos) << "no model ran: " << r.output;
}

TEST(BadUsage, DirectoryOrMissingFileAsMeshSaysSo) {
  const auto dir = testing::fresh_temp_dir("mesh-kind");
  std::filesystem::create_directories(dir / "folder.obj");
  const auto folder =
      run_command("run -q --out " + (dir / "out").string() + " " + (dir / "folder.obj").string());
  EXPECT_EQ(folder.exit_code, 1) << folder.output;
  EXPECT_NE(folder.output.find("is a directory"), std::string::npos) << folder.output;
  const auto plain = run_command("run -q --out " + (dir / "out").string() + " " + dir.string());
  EXPECT_NE(plain.output.find("is a directory"), std::string::npos) << plain.output;
  EXPECT_EQ(plain.output.find("no file extension"), std::string::npos) << plain.output;
  const auto missing =
      run_command("run -q --out " + (dir / "out").string() + " " + (dir / "missing.stl").string());
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(missing.output.find("no such file"), std::string::npos) << missing.output;
}

// Found by fuzz_batch_job: a file name longer than the system allows made the pattern's
// existence check throw, an internal error (exit 3) instead of the job file's fault.
TEST(BadUsage, JobInputNameTooLongIsAJobFileError) {
  const auto dir = testing::fresh_temp_dir("long-name");
  std::ofstream(dir / "job.yaml") << "inputs: [" << std::string(300, 'x') << ".obj]\n";
  const auto r = run_command("batch " + (dir / "job.yaml").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("job.yaml:1:10: no file matches"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  const auto summary = run_command("summary " + (dir / std::string(300, 'y')).string());
  EXPECT_EQ(summary.exit_code, 2) << summary.output;
  EXPECT_EQ(summary.output.find("internal error"), std::string::npos) << summary.output;
}

// Found by fuzz_batch_job: a thread count beyond int was converted with undefined behaviour.
TEST(BadUsage, JobThreadsBeyondAnyMachineIsAJobFileError) {
  const auto dir = testing::fresh_temp_dir("job-threads");
  small_mesh(dir);
  for (const char* threads : {"15555555555555", "2.5"}) {
    std::ofstream(dir / "job.yaml") << "inputs: [cylinder.obj]\noutput: out\nthreads: " << threads << "\n";
    const auto r = run_command("batch " + (dir / "job.yaml").string());
    EXPECT_EQ(r.exit_code, 2) << threads << "\n" << r.output;
    EXPECT_NE(r.output.find("job.yaml:3:10: expected a whole number of threads from 0 to 100000"),
              std::string::npos)
        << r.output;
  }
}

TEST(BadUsage, PlyClaimingBillionsOfVerticesIsRefusedAtOnce) {
  const auto dir = testing::fresh_temp_dir("huge-ply");
  for (const char* name : {"claims-4e9-vertices.ply", "claims-4e9-vertices-binary.ply"}) {
    const auto start = std::chrono::steady_clock::now();
    const auto r = run_command("run -q --out " + (dir / "out").string() + " " + kSource +
                               "/fuzz/regressions/load_ply/" + name);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("declares 4000000000 vertices"), std::string::npos) << r.output;
    EXPECT_LT(elapsed.count(), 1.0) << name;
  }
}

}  // namespace
}  // namespace papercraft
