#pragma once
// `papercraft run` and `papercraft batch`: the pipeline over a list of meshes, recorded as
// models finish (batch_journal.h), resumable (resume.h), stoppable by SIGINT/SIGTERM
// (stop_signals.h), with progress on stderr and one line per model on stdout.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "graph/config.h"
#include "graph/model_run.h"
#include "graph/tolerance.h"
#include "runner/progress_display.h"

namespace papercraft {

// Exit codes (README "Exit codes").
inline constexpr int kExitOk = 0;
inline constexpr int kExitModelFailed = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInternal = 3;
// A run stopped by a signal exits with 128 + the signal: 130 (SIGINT), 143 (SIGTERM).

struct RunRequest {
  enum class Kind { kRun, kBatch };
  Kind kind = Kind::kRun;
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> names;          // output folder names, one per input
  std::string config_file;                 // empty: builtin default
  std::optional<ToleranceSpec> tolerance;  // else the config's
  std::filesystem::path output = "out";
  int threads = -1;  // -1: from the config
  // Paper: each set only when given (command line or job file); else the config's, else the
  // defaults of PaperSpec.
  std::optional<double> height_mm, scale, min_width_mm, min_area_mm2;
  std::optional<int> max_pages;        // else RunSettings' default
  bool allow_large_tolerance = false;  // accept a tolerance above 50% of the largest side
  int shard_index = 0;                 // batch: which shard this is (0-based) of shard_count
  int shard_count = 1;
  bool force = false;           // batch: redo models an earlier run finished
  double grace_seconds = 10.0;  // SIGINT/SIGTERM: how long running models may finish
};

/// A tolerance given as text ("2%", "0.004") on the command line or to the Python module.
/// \throws InvalidInputException, naming --tolerance, when it does not parse.
ToleranceSpec parse_tolerance_option(const std::string& text);

/// The settings every model of `request` runs with: its tolerance, paper and threads over the
/// config's. Throws InvalidInputException for a tolerance above 50% of the largest side without
/// allow_large_tolerance.
std::shared_ptr<RunSettings> run_settings(const RunRequest& request, const PipelineConfig& config);

/// Runs the request and returns the exit code. block_stop_signals() must have been called
/// before any thread started. Throws ConfigException, InvalidInputException or IOException
/// for a bad config, bad settings or unwritable summary files.
int run_models(const RunRequest& request, ProgressDisplay& display);

}  // namespace papercraft
