#pragma once
// Per-model state shared by every message of one model while it flows through the graph:
// identity, settings, the count of messages in flight (model completion), gathered
// messages, per-node statistics, the error record and values for report.json.

#include <any>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "graph/tolerance.h"

namespace papercraft {

/// Settings that apply to every model of a run (from the command line and the config).
struct RunSettings {
  ToleranceSpec tolerance;
  std::filesystem::path output_dir = "out";
  int threads = 0;          // 0: all cores
  std::string config_file;  // path or "<builtin>"
  std::string config_text;  // the YAML actually used (copied into report.json)
  double height_mm = 0.0;   // 0: use scale or the layout default
  double scale = 0.0;       // mm per model unit; 0: unset
};

struct NodeStatistics {
  std::atomic<long> calls{0};
  std::atomic<long> nanoseconds{0};
};

struct ModelRun {
  ModelRun(int index, std::filesystem::path input, std::string name,
           std::shared_ptr<const RunSettings> settings, std::size_t node_count);

  const int index;
  const std::filesystem::path input_path;
  const std::string name;  // output folder name: <out>/<name>/
  const std::shared_ptr<const RunSettings> settings;
  const std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

  std::filesystem::path output_dir() const { return settings->output_dir / name; }

  /// Absolute tolerance, set by the load node once the bounding box is known.
  std::atomic<double> tolerance{0.0};
  std::atomic<double> largest_side{0.0};

  /// Messages of this model currently in flight (framework-managed).
  std::atomic<long> in_flight{0};

  std::atomic<int> next_part_id{0};
  std::atomic<int> next_strip_id{0};

  /// Record the first error; later messages of this model are dropped.
  void fail(const std::string& node, const std::string& message);
  bool failed() const { return failed_.load(); }
  std::string error() const;

  /// Values for report.json's "result" section, set by nodes ("strips_3d", ...).
  void set_result(const std::string& key, double value);
  void add_result(const std::string& key, double value);
  void max_result(const std::string& key, double value);
  std::map<std::string, double> results() const;

  /// Lines for the report's "notes" (repairs made by the loader, warnings).
  void note(const std::string& text);
  std::vector<std::string> notes() const;

  std::vector<NodeStatistics> node_stats;  // index: node index in the pipeline
  /// Configured node names and implementations, same indexing (set by the pipeline).
  std::vector<std::pair<std::string, std::string>> node_labels;

  // Framework-internal: gathered payloads per gather index and which gathers flushed.
  std::mutex gather_mutex;
  std::map<int, std::vector<std::any>> gathered;
  std::vector<bool> gather_flushed;

  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }

 private:
  mutable std::mutex mutex_;
  std::atomic<bool> failed_{false};
  std::string error_;
  std::map<std::string, double> results_;
  std::vector<std::string> notes_;
};

}  // namespace papercraft
