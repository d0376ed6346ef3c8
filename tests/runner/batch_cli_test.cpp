// `papercraft batch` as a user meets it: hostile files, signals in the middle, resuming,
// shards sharing a folder and `papercraft summary`, `run` beside a batch.

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include "support/command.h"
#include "support/pipeline_run.h"

namespace papercraft {
namespace {

using testing::read_text;
using testing::run_command;

const std::string kSource = PAPERCRAFT_SOURCE_DIR;

namespace fs = std::filesystem;

void generate(const std::string& shape, const fs::path& file, const std::string& params = "") {
  const auto r = run_command("generate " + shape + " '" + file.string() + "' " + params);
  ASSERT_EQ(r.exit_code, 0) << r.output;
}

nlohmann::json read_json(const fs::path& path) {
  return nlohmann::json::parse(read_text(path));
}

std::map<std::string, nlohmann::json> rows_by_name(const nlohmann::json& summary) {
  std::map<std::string, nlohmann::json> rows;
  for (const auto& row : summary.at("results")) {
    EXPECT_TRUE(rows.emplace(row.at("name").get<std::string>(), row).second)
        << "two rows for " << row.at("name");
  }
  return rows;
}

std::vector<nlohmann::json> journal_rows(const fs::path& path) {
  std::vector<nlohmann::json> rows;
  std::istringstream lines(read_text(path));
  for (std::string line; std::getline(lines, line);) rows.push_back(nlohmann::json::parse(line));
  return rows;
}

std::vector<fs::path> temporaries(const fs::path& folder) {
  std::vector<fs::path> found;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) {
      found.push_back(entry.path());
    }
  }
  return found;
}

// Meshes that take a second or so each on one thread, so that a signal after the first
// one finished finds the others running or waiting.
void write_slow_batch(const fs::path& dir, int models) {
  fs::create_directories(dir / "meshes");
  for (int i = 0; i < models; ++i) {
    generate("pawn", dir / "meshes" / ("pawn" + std::to_string(i) + ".obj"));
  }
  std::ofstream(dir / "job.yaml") << "inputs: [meshes/*.obj]\noutput: out\ntolerance: 1%\n"
                                     "threads: 1\n";
}

// Starts the batch, waits for the first finished model in batch.jsonl, sends `signal`.
int interrupt_after_first_model(const fs::path& dir, int signal,
                                const std::vector<std::string>& extra) {
  std::vector<std::string> arguments = {"batch", (dir / "job.yaml").string()};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  const pid_t pid = testing::spawn_command(arguments, dir / "first.log");
  EXPECT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(dir / "out/batch.jsonl") && !read_text(dir / "out/batch.jsonl").empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, signal);
  return testing::wait_exit_code(pid);
}

// What an interrupted batch must leave, and a resumed run that runs only the rest.
void check_interrupted_then_resume(const fs::path& dir, int models, const std::string& signal) {
  const auto summary = read_json(dir / "out/batch.json");
  EXPECT_TRUE(summary.at("complete").get<bool>());
  EXPECT_EQ(summary.at("interrupted_by"), signal);
  EXPECT_EQ(summary.at("models"), models);
  const auto rows = rows_by_name(summary);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(models));
  std::set<std::string> finished;
  for (const auto& [name, row] : rows) {
    const std::string status = row.at("status");
    EXPECT_TRUE(status == "ok" || status == "interrupted") << row.dump();
    if (status == "ok") {
      finished.insert(name);
      EXPECT_TRUE(fs::exists(dir / "out" / name / "finished.json")) << name;
      EXPECT_TRUE(fs::exists(dir / "out" / name / "report.json")) << name;
    } else {
      EXPECT_FALSE(fs::exists(dir / "out" / name / "finished.json")) << name;
    }
  }
  EXPECT_GE(finished.size(), 1u) << "the model finished before the signal";
  EXPECT_LT(finished.size(), static_cast<std::size_t>(models)) << "nothing was interrupted";
  // Every row of the journal is in the summary, with the same status.
  for (const auto& row : journal_rows(dir / "out/batch.jsonl")) {
    EXPECT_EQ(rows.at(row.at("name")).at("status"), row.at("status")) << row.dump();
  }
  EXPECT_EQ(temporaries(dir / "out"), std::vector<fs::path>{});

  std::map<std::string, fs::file_time_type> written;
  for (const auto& name : finished)
    written[name] = fs::last_write_time(dir / "out" / name / "report.json");
  const auto resumed = run_command("batch " + (dir / "job.yaml").string() + " -q");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  const auto after = rows_by_name(read_json(dir / "out/batch.json"));
  for (const auto& [name, row] : after) {
    EXPECT_EQ(row.at("status"), "ok") << row.dump();
    EXPECT_EQ(row.value("skipped", false), finished.count(name) == 1) << row.dump();
    const bool said_skipped = resumed.output.find(name + ": skipped") != std::string::npos;
    EXPECT_EQ(said_skipped, finished.count(name) == 1) << resumed.output;
  }
  for (const auto& [name, time] : written) {
    EXPECT_EQ(fs::last_write_time(dir / "out" / name / "report.json"), time) << name << " rerun";
  }
}

TEST(BatchCli, HostileFilesGiveOneRowPerInputAndExit1) {
  const auto dir = testing::fresh_temp_dir("hostile");
  fs::create_directories(dir / "in");
  std::mt19937 random(15);
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(random() & 0xFF);
  std::ofstream(dir / "in/noise.off", std::ios::binary) << noise;
  // A header, then bytes a parser quotes in its message.
  std::ofstream(dir / "in/quoted.off", std::ios::binary)
      << "OFF\n3 1 0\n0 0 0\n\xFF\xFE\xE9 1 0\n0 1 0\n3 0 1 2\n";
  generate("pawn", dir / "in/caf\xE9.obj");  // a Latin-1 name: a good mesh
  generate("sphere", dir / "in/whole.off");
  const std::string whole = read_text(dir / "in/whole.off");
  std::ofstream(dir / "in/truncated.off", std::ios::binary) << whole.substr(0, whole.size() / 2);
  generate("open_cylinder", dir / "in/good.obj");
  std::ofstream(dir / "job.yaml") << "inputs: [in/*]\noutput: out\ntolerance: 2%\n";
  const auto r = run_command("batch " + (dir / "job.yaml").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  const auto rows = rows_by_name(read_json(dir / "out/batch.json"));
  ASSERT_EQ(rows.size(), 6u) << read_text(dir / "out/batch.json");
  EXPECT_EQ(rows.at("noise").at("status"), "error");
  EXPECT_EQ(rows.at("quoted").at("status"), "error");
  EXPECT_NE(rows.at("quoted").at("error").get<std::string>().find("\\xFF\\xFE\\xE9"),
            std::string::npos)
      << "the loader quotes the bytes, escaped: " << rows.at("quoted").dump();
  EXPECT_EQ(rows.at("truncated").at("status"), "error");
  EXPECT_EQ(rows.at("whole").at("status"), "ok");
  EXPECT_EQ(rows.at("good").at("status"), "ok");
  ASSERT_EQ(rows.count("caf\\xE9"), 1u) << "the name's byte escaped";
  EXPECT_EQ(rows.at("caf\\xE9").at("status"), "ok") << rows.at("caf\\xE9").dump();
  EXPECT_EQ(
      rows.at("caf\\xE9").at("input").get<std::string>().find("caf\\xE9.obj") != std::string::npos,
      true);
  // The model's own folder keeps the file's bytes; its report escapes them.
  const auto report = read_json(dir / "out/caf\xE9/report.json");
  EXPECT_EQ(report.at("input").at("name"), "caf\\xE9");
  EXPECT_EQ(journal_rows(dir / "out/batch.jsonl").size(), 6u);
}

TEST(BatchCli, SigintKeepsEveryFinishedRowAndResumeRunsTheRest) {
  const auto dir = testing::fresh_temp_dir("sigint");
  write_slow_batch(dir, 6);
  EXPECT_EQ(interrupt_after_first_model(dir, SIGINT, {}), 130) << read_text(dir / "first.log");
  check_interrupted_then_resume(dir, 6, "SIGINT");
}

TEST(BatchCli, SigtermAbandonsRunningModelsAndResumeRunsTheRest) {
  const auto dir = testing::fresh_temp_dir("sigterm");
  write_slow_batch(dir, 6);
  // No grace: the models running at the signal are abandoned, not waited for.
  EXPECT_EQ(interrupt_after_first_model(dir, SIGTERM, {"--grace", "0"}), 143)
      << read_text(dir / "first.log");
  const auto rows = rows_by_name(read_json(dir / "out/batch.json"));
  int abandoned = 0;
  for (const auto& [name, row] : rows) {
    abandoned += row.value("error", std::string()).find("while it ran") != std::string::npos;
  }
  EXPECT_GE(abandoned, 1) << read_text(dir / "out/batch.json");
  check_interrupted_then_resume(dir, 6, "SIGTERM");
}

// A node call that runs on after the models were abandoned: the process exits anyway, soon,
// with the summary written and no temporary file left.
TEST(BatchCli, SignalDuringALongNodeCallExitsWithinSeconds) {
  const auto dir = testing::fresh_temp_dir("hardexit");
  generate("sphere", dir / "big.off", "--param subdivisions=7");  // 327,680 faces
  // segment.fuzzy on the whole mesh (no proxy: its one long call is the segmentation's).
  std::string config = read_text(kSource + "/configs/segment-fuzzy.yaml");
  const auto proxy = config.find("impl: proxy.decimate,");
  ASSERT_NE(proxy, std::string::npos);
  const auto params_end = config.find("}, to:", proxy);
  ASSERT_NE(params_end, std::string::npos);
  config.replace(proxy, params_end + 2 - proxy, "impl: proxy.none,");
  std::ofstream(dir / "fuzzy.yaml") << config;
  std::ofstream(dir / "job.yaml") << "inputs: [big.off]\noutput: out\ntolerance: 0.5%\n"
                                     "threads: 1\nconfig: "
                                  << (dir / "fuzzy.yaml").string() << "\n";
  const pid_t pid =
      testing::spawn_command({"batch", (dir / "job.yaml").string(), "--grace", "0"}, dir / "log");
  ASSERT_GT(pid, 0);
  while (!fs::exists(dir / "out/batch.json")) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // Past the load, inside segment.fuzzy's one long call on the whole mesh.
  std::this_thread::sleep_for(std::chrono::seconds(3));
  const auto signalled = std::chrono::steady_clock::now();
  ::kill(pid, SIGTERM);
  EXPECT_EQ(testing::wait_exit_code(pid), 143);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
  EXPECT_LT(seconds, 6.0) << "2 s after the abandon, and the summary";
  const std::string log = read_text(dir / "log");
  EXPECT_NE(log.find("exiting without them"), std::string::npos) << log;
  const auto summary = read_json(dir / "out/batch.json");
  EXPECT_TRUE(summary.at("complete").get<bool>());
  EXPECT_EQ(summary.at("interrupted_by"), "SIGTERM");
  const auto row = summary.at("results").at(0);
  EXPECT_EQ(row.at("status"), "interrupted");
  EXPECT_NE(row.at("error").get<std::string>().find("while it ran"), std::string::npos);
  EXPECT_GT(row.at("wall_seconds").get<double>(), 3.0);
  EXPECT_EQ(journal_rows(dir / "out/batch.jsonl").size(), 1u);
  EXPECT_EQ(temporaries(dir / "out"), std::vector<fs::path>{});
}

TEST(BatchCli, ResumeSkipsOnlyWhatIsUnchanged) {
  const auto dir = testing::fresh_temp_dir("resume");
  generate("open_cylinder", dir / "a.obj");
  generate("cone_frustum", dir / "b.obj");
  const auto job = [&](const std::string& tolerance) {
    std::ofstream(dir / "job.yaml")
        << "inputs: ['*.obj']\noutput: out\ntolerance: " << tolerance << "\n";
  };
  const auto skipped = [&](const std::string& extra) {
    const auto r = run_command("batch " + (dir / "job.yaml").string() + " -q " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_json(dir / "out/batch.json").at("skipped").get<int>();
  };
  job("2%");
  EXPECT_EQ(skipped(""), 0);
  EXPECT_EQ(skipped(""), 2);
  EXPECT_EQ(skipped("--force"), 0);
  generate("cone_frustum", dir / "b.obj", "--param height=3");  // new bytes
  EXPECT_EQ(skipped(""), 1);
  job("3%");
  EXPECT_EQ(skipped(""), 0);
  EXPECT_EQ(skipped(""), 2);
  const auto rows = rows_by_name(read_json(dir / "out/batch.json"));
  EXPECT_TRUE(rows.at("a").value("skipped", false));
  EXPECT_EQ(rows.at("a").at("output"), (dir / "out/a").string());
}

// The job's tolerance reaches the models as written, every digit of it (not as printed back).
TEST(BatchCli, JobToleranceKeepsEveryDigit) {
  const auto dir = testing::fresh_temp_dir("job-tolerance");
  generate("open_cylinder", dir / "a.obj");
  std::ofstream(dir / "job.yaml") << "inputs: [a.obj]\noutput: out\ntolerance: 0.0123456789\n";
  const auto r = run_command("batch " + (dir / "job.yaml").string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json report = read_json(dir / "out/a/report.json");
  EXPECT_EQ(report.at("tolerance").at("absolute").get<double>(), 0.0123456789);
}

TEST(BatchCli, TwoShardsIntoOneFolderThenSummary) {
  const auto dir = testing::fresh_temp_dir("shards");
  for (const char* sub : {"a", "b"}) fs::create_directories(dir / sub);
  generate("open_cylinder", dir / "a/x.obj");
  generate("cone_frustum", dir / "b/x.obj");  // same stem: a name of its own in every shard
  generate("sphere", dir / "c.obj");
  generate("torus", dir / "d.off");
  std::ofstream(dir / "e.obj") << "not a mesh\n";
  std::ofstream(dir / "job.yaml") << "inputs: [a/x.obj, b/x.obj, '*.obj', '*.off']\n"
                                     "output: out\ntolerance: 3%\nthreads: 1\n";
  // Both shards at once, as two machines would.
  const pid_t one = testing::spawn_command(
      {"batch", (dir / "job.yaml").string(), "--shard", "1/2", "-q"}, dir / "one.log");
  const pid_t two = testing::spawn_command(
      {"batch", (dir / "job.yaml").string(), "--shard", "2/2", "-q"}, dir / "two.log");
  const int one_code = testing::wait_exit_code(one);
  const int two_code = testing::wait_exit_code(two);
  EXPECT_EQ(one_code + two_code, 1) << "e fails in one shard only\n"
                                    << read_text(dir / "one.log") << read_text(dir / "two.log");
  EXPECT_FALSE(fs::exists(dir / "out/batch.json"));
  const auto first = read_json(dir / "out/batch.shard-1-of-2.json");
  const auto second = read_json(dir / "out/batch.shard-2-of-2.json");
  EXPECT_EQ(first.at("models").get<int>() + second.at("models").get<int>(), 5);

  const auto r = run_command("summary " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const auto merged = read_json(dir / "out/batch.json");
  const auto rows = rows_by_name(merged);
  EXPECT_EQ(rows.size(), 5u);
  EXPECT_EQ(merged.at("models"), 5);
  EXPECT_EQ(merged.at("ok"), 4);
  EXPECT_EQ(merged.at("failed"), 1);
  EXPECT_TRUE(merged.at("complete").get<bool>());
  for (const char* name : {"x", "x-2", "c", "d", "e"}) {
    ASSERT_EQ(rows.count(name), 1u) << name;
    EXPECT_NE(r.output.find(std::string(name) + " "), std::string::npos) << r.output;
  }
  EXPECT_EQ(rows.at("e").at("status"), "error");
  EXPECT_NE(rows.at("x").at("input"), rows.at("x-2").at("input"));
  EXPECT_NE(r.output.find("5 models: 4 ok"), std::string::npos) << r.output;

  // `run` into the same folder leaves the batch's files alone.
  const std::string before = read_text(dir / "out/batch.json");
  const std::string shard_before = read_text(dir / "out/batch.shard-1-of-2.json");
  const auto run =
      run_command("run -q --out " + (dir / "out").string() + " " + (dir / "c.obj").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(read_text(dir / "out/batch.json"), before);
  EXPECT_EQ(read_text(dir / "out/batch.shard-1-of-2.json"), shard_before);
  EXPECT_EQ(read_json(dir / "out/run.json").at("models"), 1);
  // ... and the next summary takes its row in: c's latest result.
  EXPECT_EQ(run_command("summary " + (dir / "out").string()).exit_code, 1);
  EXPECT_EQ(rows_by_name(read_json(dir / "out/batch.json")).size(), 5u);
}

TEST(BatchCli, SummaryWithoutSummariesExits2) {
  const auto dir = testing::fresh_temp_dir("nosummary");
  const auto r = run_command("summary " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no batch summary"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace papercraft
