#pragma once
// A batch summary file (docs/outputs.md, "Run and batch summaries"): batch.json of a whole batch,
// batch.shard-I-of-N.json of one shard, run.json of `papercraft run`, each with its journal
// (.jsonl: one row per line, appended as models finish). Each process writes only its own
// pair, so shards sharing an output folder never write the same file.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runner/batch_row.h"

namespace papercraft {

struct BatchSummary {
  std::string shard;                     // "2/3" in a shard's file; empty otherwise
  bool complete = false;                 // false: the batch is still running, or was killed
  std::string interrupted_by;            // "SIGINT" or "SIGTERM" when it was stopped; else empty
  double started_at = 0.0;               // unix seconds
  double finished_at = 0.0;              // unix seconds: the last write
  std::vector<BatchRow> rows;            // one per input
  std::vector<std::string> merged_from;  // `papercraft summary`: the files it read
};

struct RowCounts {
  int ok = 0;  // skipped rows included
  int skipped = 0;
  int failed = 0;
  int interrupted = 0;
  int pending = 0;
  int finished_here = 0;  // ok or failed by this batch (not skipped): what its speed counts
};

RowCounts count_rows(const std::vector<BatchRow>& rows);

/// The file's text: counts, wall seconds, models per minute and the rows.
std::string summary_json_text(const BatchSummary& summary);
/// Throws nlohmann::json::exception or std::invalid_argument on a malformed file.
BatchSummary summary_from_json(const nlohmann::json& json);

/// A summary file and its journal.
struct SummaryFiles {
  std::filesystem::path summary;  // .json
  std::filesystem::path journal;  // .jsonl
};

/// batch.json / batch.jsonl, or batch.shard-I-of-N.json(l) when shard_count > 1 (shard_index
/// is 0-based).
SummaryFiles batch_summary_files(const std::filesystem::path& output, int shard_index,
                                 int shard_count);
/// run.json / run.jsonl.
SummaryFiles run_summary_files(const std::filesystem::path& output);

/// Whether `file_name` is one of the summaries or journals above.
bool is_summary_file_name(const std::string& file_name);

}  // namespace papercraft
