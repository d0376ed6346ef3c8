#pragma once
// Resuming a batch (docs/batches.md, "Resuming"): each model that finishes ok gets
// <out>/<name>/finished.json, written after all its other files, holding its batch row and
// the key of its result: the input's content hash, the config's hash, the tolerance, the
// paper settings and the version. A later batch skips the model while the key is the same.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "graph/model_run.h"
#include "runner/batch_row.h"

namespace papercraft {

/// The name of the record in a model's folder.
inline constexpr const char* kFinishedRecord = "finished.json";

/// What a model's result depends on besides its input file. Thread counts are left out:
/// the output does not depend on them.
struct ResultKey {
  std::string config_sha256;  // of the config text used
  std::string tolerance;      // as given: "2%" or "0.004"
  PaperSpec paper;
  std::string version;
};

ResultKey result_key(const RunSettings& settings);

/// Writes <model_dir>/finished.json (atomically). Throws IOException.
void write_finished_record(const std::filesystem::path& model_dir, const BatchRow& row,
                           const ResultKey& key, const std::string& input_sha256);

/// The row of an earlier ok result in `model_dir` made from the same bytes as `input` with
/// the same key, marked skipped; nullopt when there is none, it differs or cannot be read.
/// Hashes the input only when everything else matches.
std::optional<BatchRow> earlier_result(const std::filesystem::path& model_dir,
                                       const std::filesystem::path& input, const ResultKey& key);

}  // namespace papercraft
