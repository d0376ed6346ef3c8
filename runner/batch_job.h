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
//   shard: 1/4                                # optional: this machine runs every 4th input from
//   the 1st

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

/// Keeps every shard_count-th input starting at shard_index (stable across machines).
std::vector<std::filesystem::path> select_shard(const std::vector<std::filesystem::path>& inputs,
                                                int shard_index, int shard_count);

}  // namespace papercraft
