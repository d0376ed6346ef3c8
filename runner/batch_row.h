#pragma once
// One row of a batch summary (batch.json, batch.jsonl and their shard and run variants;
// docs/outputs.md, "Run and batch summaries"): what became of one input. Every text field
// holds valid UTF-8 (bytes of a file name that are not are escaped as \xNN), so a row always
// goes into JSON.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "graph/pipeline.h"

namespace papercraft {

enum class RowStatus {
  kOk,           // finished, outputs written (or skipped: finished by an earlier run)
  kError,        // failed; `error` says why
  kInterrupted,  // the batch was stopped before the model started or while it ran
  kPending,      // not finished yet (only in the summary of a batch still running, or killed)
};

std::string to_string(RowStatus status);
/// Throws std::invalid_argument on any other text.
RowStatus row_status_from_string(const std::string& text);

struct BatchRow {
  std::string name;   // the output folder's name
  std::string input;  // the mesh file
  RowStatus status = RowStatus::kPending;
  bool skipped = false;  // ok by an earlier run with the same input, config and settings
  std::string error;     // error and interrupted rows: why
  std::string output;    // ok rows: the output folder
  int strips_3d = 0;
  int flat_strips = 0;
  int pages = 0;
  double hausdorff_bound = 0.0;  // model units
  double hausdorff_bound_percent = 0.0;
  bool certified = false;
  double work_seconds = 0.0;    // the sum of the model's node calls
  double wall_seconds = 0.0;    // from the model's start to its finish
  double queue_seconds = 0.0;   // from the start of its batch to the model's start
  double started_at = 0.0;      // unix seconds; 0: never started
  double finished_at = 0.0;     // unix seconds; 0: not finished
  bool internal_error = false;  // a bug of papercraft (not written; sets the exit code)
};

/// A pending row for an input.
BatchRow pending_row(const std::string& name, const std::filesystem::path& input);

/// The row of a model the pipeline returned, finished at `finished_at` (unix seconds).
BatchRow row_from_result(const ModelResult& result, const std::filesystem::path& output_dir,
                         double finished_at);

nlohmann::json row_to_json(const BatchRow& row);
/// Throws nlohmann::json::exception or std::invalid_argument on a malformed row.
BatchRow row_from_json(const nlohmann::json& json);

/// Unix time now, in seconds.
double unix_seconds_now();

}  // namespace papercraft
