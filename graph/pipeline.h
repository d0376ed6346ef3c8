#pragma once
// A validated PipelineConfig turned into a oneTBB flow graph and run over many models.
//
// Every message carries its ModelRun. Each node call adds the messages it emits to the
// model's in-flight count before sending them and removes its own input afterwards, so
// the count reaches zero exactly once per phase: when nothing of the model is left in the
// graph. Then the model's first pending gather (the input of a node that needs the whole
// model, such as merge) fires once with everything collected; when nothing is pending,
// the model is finished. No worker ever waits for another.

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <stop_token>
#include <string>
#include <vector>

#include "graph/config.h"
#include "graph/model_run.h"

namespace papercraft {

/// The message a run starts with: one input file, or a mesh given in memory (`mesh`; then
/// `input` only names it in messages and the report).
struct Job {
  static constexpr const char* kMessageName = "Job";
  std::filesystem::path input;
  std::shared_ptr<const TriangleMesh> mesh;
};

/// The outcome of one model, for the batch summary.
struct ModelResult {
  std::string name;
  std::filesystem::path input;
  bool started = false;  // false: the run was stopped before this model started
  bool ok = false;
  bool abandoned = false;       // the run was stopped while it ran; the rest of its work dropped
  bool internal_error = false;  // the error is a bug of papercraft, not of the input
  std::string error;
  double work_seconds = 0.0;   // the sum of its node calls
  double wall_seconds = 0.0;   // from its start to its finish
  double queue_seconds = 0.0;  // from the start of the run to its start
  ModelRecord record;
};

/// What the graph holds at one moment, for a progress display.
struct PipelineProgress {
  struct Running {
    std::string name;
    std::string stage;   // the node whose call on this model started last
    long in_flight = 0;  // its parts and strips in the graph
  };
  std::size_t total = 0;
  std::size_t started = 0;
  std::size_t done = 0;
  std::size_t failed = 0;
  std::vector<Running> running;
};

struct NodeTiming {
  std::string node;
  std::string impl;
  long calls = 0;
  double seconds = 0.0;
};

struct PipelineOptions {
  int threads = 0;               // 0: all cores
  int max_models_in_flight = 0;  // 0: 2 x threads
  /// Output folder names, one per input; empty: unique_model_names(inputs). A caller running
  /// a share of a larger list passes the names it has in the whole list.
  std::vector<std::string> names;
  /// Meshes given in memory (the Python module's arrays), one per input where not empty: the
  /// loader validates and repairs them as it does a file's, and `inputs` only name them.
  std::vector<std::shared_ptr<const TriangleMesh>> meshes;
  /// Called every progress_interval from a thread of the pipeline's own.
  std::function<void(const PipelineProgress&)> on_progress;
  std::chrono::milliseconds progress_interval{1000};
  /// Called when a model enters the graph and when it finishes (from a worker thread: hand
  /// the work to another thread rather than blocking it).
  std::function<void(const ModelRun&)> on_model_started;
  std::function<void(const ModelRun&, const ModelResult&)> on_model_done;
  /// Once requested, no further model starts (their results have started == false).
  std::stop_token stop_starting;
  /// Once requested, models still running are abandoned: a node call under way finishes, the
  /// rest of their messages are dropped, their results have abandoned == true.
  std::stop_token abandon;
};

class Pipeline {
 public:
  Pipeline(PipelineConfig config, const Registry& registry);
  ~Pipeline();

  /// Runs every input through the graph; returns one result per input, in input order.
  /// Never throws for a bad model: its error is in its result. Throws std::invalid_argument
  /// when options.names or options.meshes is neither empty nor one per input.
  std::vector<ModelResult> run(const std::vector<std::filesystem::path>& inputs,
                               std::shared_ptr<const RunSettings> settings,
                               const PipelineOptions& options = {});

  const PipelineConfig& config() const { return config_; }

  /// The refinement options the configured nodes give (what NodeContext::refine holds).
  RefineOptions refine_options() const;
  std::vector<std::string> node_names() const;

  /// Node timings of a finished model (calls and seconds per configured node).
  std::vector<NodeTiming> timings(const ModelRun& run) const;

 private:
  PipelineConfig config_;
  const Registry& registry_;
};

/// Output folder names for inputs: file stems, made unique with "-2", "-3", ...
std::vector<std::string> unique_model_names(const std::vector<std::filesystem::path>& inputs);

}  // namespace papercraft
