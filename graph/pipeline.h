#pragma once
// A validated PipelineConfig turned into a oneTBB flow graph and run over many models.
//
// Every message carries its ModelRun. Each node call adds the messages it emits to the
// model's in-flight count before sending them and removes its own input afterwards, so
// the count reaches zero exactly once per phase: when nothing of the model is left in the
// graph. Then the model's first pending gather (the input of a node that needs the whole
// model, such as merge) fires once with everything collected; when nothing is pending,
// the model is finished. No worker ever waits for another.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "graph/config.h"
#include "graph/model_run.h"

namespace papercraft {

/// The message a run starts with: one input file.
struct Job {
  static constexpr const char* kMessageName = "Job";
  std::filesystem::path input;
};

/// The outcome of one model, for the batch summary.
struct ModelResult {
  std::string name;
  std::filesystem::path input;
  bool ok = false;
  bool internal_error = false;  // the error is a bug of papercraft, not of the input
  std::string error;
  double seconds = 0.0;
  ModelRecord record;
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
  bool progress = false;         // a progress line on stderr about once a second
  /// Called when a model finishes (from a worker thread; keep it short).
  std::function<void(const ModelRun&, const ModelResult&)> on_model_done;
};

class Pipeline {
 public:
  Pipeline(PipelineConfig config, const Registry& registry);
  ~Pipeline();

  /// Runs every input through the graph; returns one result per input, in input order.
  /// Never throws for a bad model: its error is in its result.
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
