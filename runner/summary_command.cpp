#include "runner/summary_command.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/printable_utf8.h"
#include "runner/run_models.h"

namespace papercraft {

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A journal's rows; a line cut short by a kill is skipped with a warning.
BatchSummary read_journal(const std::filesystem::path& path) {
  BatchSummary summary;
  std::istringstream lines(read_text(path));
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (line.empty()) continue;
    try {
      summary.rows.push_back(row_from_json(nlohmann::json::parse(line)));
    } catch (const std::exception&) {
      spdlog::warn("{}:{}: not a row (cut short?), skipped", printable_utf8(path.string()), number);
    }
  }
  summary.complete = true;  // a journal says nothing of completeness; its summary does
  return summary;
}

std::string cell(std::string text, std::size_t width) {
  if (text.size() > width) {
    std::size_t cut = width - 1;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text = text.substr(0, cut) + "~";
  }
  return text + std::string(width - std::min(width, text.size()), ' ');
}

std::string number(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

BatchSummary merge_summaries(const std::vector<BatchSummary>& summaries) {
  struct Candidate {
    BatchRow row;
    double time = 0.0;
  };
  BatchSummary merged;
  merged.complete = true;
  std::map<std::string, Candidate> rows;
  for (const BatchSummary& summary : summaries) {
    merged.complete = merged.complete && summary.complete;
    if (merged.interrupted_by.empty()) merged.interrupted_by = summary.interrupted_by;
    if (summary.started_at > 0 &&
        (merged.started_at == 0 || summary.started_at < merged.started_at)) {
      merged.started_at = summary.started_at;
    }
    merged.finished_at = std::max(merged.finished_at, summary.finished_at);
    for (const BatchRow& row : summary.rows) {
      if (!row.skipped) merged.finished_at = std::max(merged.finished_at, row.finished_at);
      Candidate candidate{row, row.finished_at > 0 ? row.finished_at : summary.finished_at};
      const auto found = rows.find(row.name);
      if (found == rows.end()) {
        rows.emplace(row.name, std::move(candidate));
        continue;
      }
      const bool pending = row.status == RowStatus::kPending;
      const bool had_pending = found->second.row.status == RowStatus::kPending;
      if (pending != had_pending ? had_pending : candidate.time > found->second.time) {
        found->second = std::move(candidate);
      }
    }
  }
  for (auto& [name, candidate] : rows) merged.rows.push_back(std::move(candidate.row));
  std::stable_sort(merged.rows.begin(), merged.rows.end(),
                   [](const BatchRow& a, const BatchRow& b) {
                     return a.input != b.input ? a.input < b.input : a.name < b.name;
                   });
  return merged;
}

int summary_command(const std::filesystem::path& output) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(output, ec)) {
    if (entry.is_regular_file() && is_summary_file_name(entry.path().filename().string())) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<BatchSummary> summaries;
  BatchSummary merged_names;
  for (const auto& file : files) {
    const std::string shown = printable_utf8(file.filename().string());
    try {
      if (file.extension() == ".jsonl") {
        summaries.push_back(read_journal(file));
      } else {
        summaries.push_back(summary_from_json(nlohmann::json::parse(read_text(file))));
        if (!summaries.back().complete) {
          spdlog::warn("{}: not complete (its batch is still running, or was killed)", shown);
        }
      }
      merged_names.merged_from.push_back(shown);
    } catch (const std::exception& e) {
      spdlog::warn("{}: not a batch summary, skipped ({})", shown, printable_utf8(e.what()));
    }
  }
  if (summaries.empty()) {
    spdlog::error("{}: no batch summary (batch.json, batch.shard-I-of-N.json, run.json)",
                  printable_utf8(output.string()));
    return kExitUsage;
  }
  BatchSummary merged = merge_summaries(summaries);
  merged.merged_from = merged_names.merged_from;
  const std::filesystem::path target = output / "batch.json";
  write_file_atomic(target, summary_json_text(merged));

  std::printf("%s%s%s%s%s%s%s\n", cell("model", 24).c_str(), cell("status", 12).c_str(),
              cell("strips", 8).c_str(), cell("pages", 7).c_str(), cell("bound%", 8).c_str(),
              cell("work s", 9).c_str(), "wall s");
  for (const BatchRow& row : merged.rows) {
    std::string status = to_string(row.status) + (row.skipped ? " (s)" : "");
    std::string line = cell(row.name, 23) + " " + cell(status, 12);
    if (row.status == RowStatus::kOk) {
      line += cell(std::to_string(row.flat_strips), 8) + cell(std::to_string(row.pages), 7) +
              cell(number("%.3g", row.hausdorff_bound_percent), 8) +
              cell(number("%.3g", row.work_seconds), 9) + number("%.3g", row.wall_seconds);
    } else {
      line += row.error;
    }
    std::printf("%s\n", line.c_str());
  }
  const RowCounts counts = count_rows(merged.rows);
  const double wall = std::max(0.0, merged.finished_at - merged.started_at);
  std::printf(
      "%zu models: %d ok (%d skipped), %d failed, %d interrupted, %d pending; "
      "wall %.1f s, %.3g models/min; from %zu file(s) -> %s\n",
      merged.rows.size(), counts.ok, counts.skipped, counts.failed, counts.interrupted,
      counts.pending, wall, wall > 0 ? 60.0 * counts.finished_here / wall : 0.0, summaries.size(),
      printable_utf8(target.string()).c_str());
  return counts.ok == static_cast<int>(merged.rows.size()) ? kExitOk : kExitModelFailed;
}

}  // namespace papercraft
