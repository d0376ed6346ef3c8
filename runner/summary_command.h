#pragma once
// `papercraft summary OUT`: merges every batch summary and journal in OUT (batch.json(l),
// batch.shard-I-of-N.json(l), run.json(l)) into OUT/batch.json with one row per model, and
// prints a short table.

#include <filesystem>
#include <string>
#include <vector>

#include "runner/batch_summary.h"

namespace papercraft {

/// Merges the summaries: one row per model name, the latest (its finished_at, or for a row
/// that never finished the time of its file), but a pending row only when there is no other;
/// rows sorted by input, then name. The merged batch spans from the earliest start to the
/// latest finish; it is complete when every summary is.
BatchSummary merge_summaries(const std::vector<BatchSummary>& summaries);

/// Reads and merges the files of `output`, writes output/batch.json and prints the table.
/// Returns the exit code: 0 when every model is ok, 1 when one failed, was interrupted or is
/// still pending, 2 when `output` holds no summary. Throws IOException if batch.json cannot
/// be written.
int summary_command(const std::filesystem::path& output);

}  // namespace papercraft
