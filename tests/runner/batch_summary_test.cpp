// Batch summaries: rows to JSON and back, the journal of a running batch, and the merge of
// shards that `papercraft summary` does.

#include "runner/batch_summary.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "runner/batch_journal.h"
#include "runner/summary_command.h"
#include "support/temp_dir.h"

namespace papercraft {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

BatchRow row(const std::string& name, RowStatus status, double finished_at) {
  BatchRow r;
  r.name = name;
  r.input = "in/" + name + ".obj";
  r.status = status;
  r.finished_at = finished_at;
  r.started_at = finished_at > 0 ? finished_at - 1 : 0;
  if (status == RowStatus::kError) r.error = "load: bad";
  return r;
}

TEST(BatchRow, JsonRoundTrip) {
  BatchRow r = row("cow", RowStatus::kOk, 1000.5);
  r.output = "out/cow";
  r.strips_3d = 12;
  r.flat_strips = 14;
  r.pages = 3;
  r.hausdorff_bound = 0.25;
  r.hausdorff_bound_percent = 1.5;
  r.certified = true;
  r.work_seconds = 2.5;
  r.wall_seconds = 3.0;
  r.queue_seconds = 0.5;
  r.skipped = true;
  const BatchRow back = row_from_json(nlohmann::json::parse(row_to_json(r).dump()));
  EXPECT_EQ(back.name, "cow");
  EXPECT_EQ(back.status, RowStatus::kOk);
  EXPECT_TRUE(back.skipped);
  EXPECT_EQ(back.flat_strips, 14);
  EXPECT_DOUBLE_EQ(back.work_seconds, 2.5);
  EXPECT_DOUBLE_EQ(back.queue_seconds, 0.5);
  EXPECT_DOUBLE_EQ(back.finished_at, 1000.5);
  EXPECT_THROW(row_status_from_string("fine"), std::invalid_argument);
}

TEST(BatchRow, ResultOfABadFileNameGoesIntoJson) {
  ModelResult result;
  result.name = "caf\xE9";
  result.input = "in/caf\xE9.off";
  result.started = true;
  result.error = "load: in/caf\xE9.off: expected 'OFF', got '\xFF\xFE'";
  const BatchRow r = row_from_result(result, "out", 50.0);
  EXPECT_EQ(r.status, RowStatus::kError);
  EXPECT_EQ(r.name, "caf\\xE9");
  EXPECT_EQ(r.input, "in/caf\\xE9.off");
  EXPECT_NO_THROW((void)row_to_json(r).dump());
}

TEST(BatchSummary, FileNames) {
  EXPECT_EQ(batch_summary_files("out", 0, 1).summary, std::filesystem::path("out/batch.json"));
  EXPECT_EQ(batch_summary_files("out", 1, 3).journal,
            std::filesystem::path("out/batch.shard-2-of-3.jsonl"));
  EXPECT_EQ(run_summary_files("out").summary, std::filesystem::path("out/run.json"));
  for (const char* name : {"batch.json", "batch.jsonl", "batch.shard-2-of-3.json",
                           "batch.shard-10-of-12.jsonl", "run.json", "run.jsonl"}) {
    EXPECT_TRUE(is_summary_file_name(name)) << name;
  }
  for (const char* name : {"report.json", "batch.json.bak", ".batch.tmp-1-0.json",
                           "batch.shard-x-of-3.json", "finished.json"}) {
    EXPECT_FALSE(is_summary_file_name(name)) << name;
  }
}

TEST(BatchSummary, MergeKeepsOneRowPerModelTheLatest) {
  BatchSummary one;
  one.shard = "1/2";
  one.complete = true;
  one.started_at = 100;
  one.finished_at = 200;
  one.rows = {row("a", RowStatus::kOk, 150), row("b", RowStatus::kError, 160),
              row("c", RowStatus::kInterrupted, 0)};
  BatchSummary two;
  two.shard = "2/2";
  two.complete = false;
  two.started_at = 120;
  two.finished_at = 300;
  two.rows = {row("d", RowStatus::kPending, 0), row("b", RowStatus::kOk, 250)};
  BatchSummary journal;  // a later run of c, and d finished after two's last rewrite
  journal.complete = true;
  journal.rows = {row("c", RowStatus::kOk, 310), row("d", RowStatus::kOk, 320)};
  BatchSummary stale;  // an older file with a pending row of a: never wins over a result
  stale.complete = true;
  stale.finished_at = 400;
  stale.rows = {row("a", RowStatus::kPending, 0)};

  const BatchSummary merged = merge_summaries({one, two, journal, stale});
  ASSERT_EQ(merged.rows.size(), 4u);
  EXPECT_EQ(merged.rows[0].name, "a");
  EXPECT_EQ(merged.rows[0].status, RowStatus::kOk);
  EXPECT_EQ(merged.rows[1].status, RowStatus::kOk) << "b: the later row";
  EXPECT_EQ(merged.rows[2].status, RowStatus::kOk) << "c: the later row";
  EXPECT_EQ(merged.rows[3].status, RowStatus::kOk) << "d: the journal's row";
  EXPECT_FALSE(merged.complete);
  EXPECT_DOUBLE_EQ(merged.started_at, 100);
  EXPECT_DOUBLE_EQ(merged.finished_at, 400);

  // An interrupted row of a later run wins over an older result: the model was being redone.
  BatchSummary later;
  later.finished_at = 500;
  later.rows = {row("a", RowStatus::kInterrupted, 0)};
  EXPECT_EQ(merge_summaries({one, later}).rows[0].status, RowStatus::kInterrupted);
}

TEST(BatchSummary, JsonCountsAndSpeed) {
  BatchSummary s;
  s.complete = true;
  s.started_at = 1000;
  s.finished_at = 1030;
  s.rows = {row("a", RowStatus::kOk, 1010), row("b", RowStatus::kError, 1020),
            row("c", RowStatus::kInterrupted, 0), row("d", RowStatus::kOk, 900)};
  s.rows[3].skipped = true;
  const auto json = nlohmann::json::parse(summary_json_text(s));
  EXPECT_EQ(json.at("models"), 4);
  EXPECT_EQ(json.at("ok"), 2);
  EXPECT_EQ(json.at("skipped"), 1);
  EXPECT_EQ(json.at("failed"), 1);
  EXPECT_EQ(json.at("interrupted"), 1);
  EXPECT_DOUBLE_EQ(json.at("wall_seconds").get<double>(), 30.0);
  // a and b were run by this batch in 30 s: 4 per minute; d was skipped.
  EXPECT_DOUBLE_EQ(json.at("models_per_minute").get<double>(), 4.0);
  const BatchSummary back = summary_from_json(json);
  EXPECT_EQ(back.rows.size(), 4u);
  EXPECT_TRUE(back.complete);
}

TEST(BatchJournal, EveryRowOnceAndPendingRowsInterruptedAtClose) {
  const auto dir = testing::fresh_temp_dir("journal");
  JournalOptions options;
  options.files = batch_summary_files(dir, 0, 1);
  std::vector<std::size_t> recorded;
  options.on_recorded = [&](std::size_t index, const BatchRow&) { recorded.push_back(index); };
  BatchRow skipped = row("s", RowStatus::kOk, 10);
  skipped.skipped = true;
  BatchJournal journal(options,
                       {skipped, row("a", RowStatus::kPending, 0), row("b", RowStatus::kPending, 0),
                        row("c", RowStatus::kPending, 0)});
  {
    const auto first = nlohmann::json::parse(read_text(options.files.summary));
    EXPECT_EQ(first.at("models"), 4);
    EXPECT_EQ(first.at("pending"), 3);
    EXPECT_FALSE(first.at("complete").get<bool>());
  }
  journal.started(2);
  journal.record(1, row("a", RowStatus::kOk, 20));
  const BatchSummary closed = journal.close("SIGINT");
  journal.record(3, row("c", RowStatus::kOk, 30));  // after close: ignored
  ASSERT_EQ(closed.rows.size(), 4u);
  EXPECT_EQ(closed.rows[1].status, RowStatus::kOk);
  EXPECT_EQ(closed.rows[2].status, RowStatus::kInterrupted);
  EXPECT_NE(closed.rows[2].error.find("while it ran"), std::string::npos);
  EXPECT_EQ(closed.rows[3].status, RowStatus::kInterrupted);
  EXPECT_NE(closed.rows[3].error.find("before it started"), std::string::npos);
  EXPECT_EQ(recorded, (std::vector<std::size_t>{0, 1, 2, 3}));

  const auto final_json = nlohmann::json::parse(read_text(options.files.summary));
  EXPECT_TRUE(final_json.at("complete").get<bool>());
  EXPECT_EQ(final_json.at("interrupted_by"), "SIGINT");
  EXPECT_EQ(final_json.at("interrupted"), 2);
  std::istringstream lines(read_text(options.files.journal));
  std::vector<std::string> names;
  for (std::string line; std::getline(lines, line);) {
    names.push_back(nlohmann::json::parse(line).at("name"));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"s", "a", "b", "c"}));
}

}  // namespace
}  // namespace papercraft
