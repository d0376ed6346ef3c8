#include "runner/batch_summary.h"

#include <regex>

namespace papercraft {

RowCounts count_rows(const std::vector<BatchRow>& rows) {
  RowCounts counts;
  for (const BatchRow& row : rows) {
    switch (row.status) {
      case RowStatus::kOk:
        ++counts.ok;
        if (row.skipped) {
          ++counts.skipped;
        } else {
          ++counts.finished_here;
        }
        break;
      case RowStatus::kError:
        ++counts.failed;
        ++counts.finished_here;
        break;
      case RowStatus::kInterrupted:
        ++counts.interrupted;
        break;
      case RowStatus::kPending:
        ++counts.pending;
        break;
    }
  }
  return counts;
}

std::string summary_json_text(const BatchSummary& summary) {
  const RowCounts counts = count_rows(summary.rows);
  const double wall = std::max(0.0, summary.finished_at - summary.started_at);
  nlohmann::json rows = nlohmann::json::array();
  for (const BatchRow& row : summary.rows) rows.push_back(row_to_json(row));
  nlohmann::json root = {{"version", PAPERCRAFT_VERSION}};
  if (!summary.shard.empty()) root["shard"] = summary.shard;
  if (!summary.merged_from.empty()) root["merged_from"] = summary.merged_from;
  root["complete"] = summary.complete;
  if (!summary.interrupted_by.empty()) root["interrupted_by"] = summary.interrupted_by;
  root["models"] = summary.rows.size();
  root["ok"] = counts.ok;
  root["skipped"] = counts.skipped;
  root["failed"] = counts.failed;
  root["interrupted"] = counts.interrupted;
  root["pending"] = counts.pending;
  root["started_at"] = summary.started_at;
  root["finished_at"] = summary.finished_at;
  root["wall_seconds"] = wall;
  root["models_per_minute"] = wall > 0 ? 60.0 * counts.finished_here / wall : 0.0;
  root["results"] = std::move(rows);
  return root.dump(2) + "\n";
}

BatchSummary summary_from_json(const nlohmann::json& json) {
  BatchSummary summary;
  summary.shard = json.value("shard", std::string());
  summary.complete = json.value("complete", false);
  summary.interrupted_by = json.value("interrupted_by", std::string());
  summary.started_at = json.value("started_at", 0.0);
  summary.finished_at = json.value("finished_at", 0.0);
  summary.merged_from = json.value("merged_from", std::vector<std::string>());
  for (const auto& row : json.at("results")) summary.rows.push_back(row_from_json(row));
  return summary;
}

SummaryFiles batch_summary_files(const std::filesystem::path& output, int shard_index,
                                 int shard_count) {
  const std::string stem = shard_count > 1 ? "batch.shard-" + std::to_string(shard_index + 1) +
                                                 "-of-" + std::to_string(shard_count)
                                           : "batch";
  return {output / (stem + ".json"), output / (stem + ".jsonl")};
}

SummaryFiles run_summary_files(const std::filesystem::path& output) {
  return {output / "run.json", output / "run.jsonl"};
}

bool is_summary_file_name(const std::string& file_name) {
  static const std::regex pattern(R"((batch|batch\.shard-[0-9]+-of-[0-9]+|run)\.jsonl?)");
  return std::regex_match(file_name, pattern);
}

}  // namespace papercraft
