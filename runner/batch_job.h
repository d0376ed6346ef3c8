#pragma once
// `papercraft batch JOB.yaml`: the job file.
//
//   inputs: [meshes/*.off, extra/bunny.obj]   # paths or globs, relative to the job file
//   output: out/batch                         # relative to the job file
//   config: ../configs/fast.yaml              # optional; default: the builtin default
//   tolerance: 2%                             # optional; overrides the config
//   threads: 0                                # optional; 0 = all cores
//   height_mm: 150                            # optional
//   min_width_mm: 5                           # optional
//   min_area_mm2: 100                         # optional
//   shard: 1/4                                # optional: this machine runs every 4th input,
//                                             # from the 1st

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "graph/tolerance.h"

namespace papercraft {

struct BatchJob {
  std::vector<std::filesystem::path> inputs;  // expanded, sorted, de-duplicated
  std::filesystem::path output = "out";
  std::optional<std::filesystem::path> config;
  std::optional<ToleranceSpec> tolerance;
  std::optional<int> threads;
  std::optional<double> height_mm;
  std::optional<double> min_width_mm;
  std::optional<double> min_area_mm2;
  int shard_index = 0;  // 0-based
  int shard_count = 1;
};

/// Reads and checks a job file. Throws ConfigException ("file:line:column: ...") or
/// IOException. Patterns that match nothing are an error naming the pattern.
BatchJob load_batch_job(const std::filesystem::path& path);

/// Expands a path or a glob pattern (`*`, `?`, `[...]`) into sorted existing paths.
std::vector<std::filesystem::path> expand_pattern(const std::string& pattern);

/// The indices of the inputs shard `shard_index` (0-based) of `shard_count` runs: every
/// shard_count-th from shard_index, so the split is the same on every machine.
std::vector<std::size_t> shard_indices(std::size_t input_count, int shard_index, int shard_count);

struct Shard {
  int index = 0;  // 0-based
  int count = 1;
};

/// "2/4" (the second of four) -> {1, 4}. Throws std::invalid_argument unless 1 <= I <= N.
Shard parse_shard(const std::string& text);

}  // namespace papercraft
