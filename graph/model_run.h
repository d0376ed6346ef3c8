#pragma once
// Per-model state shared by every message of one model while it flows through the graph:
// identity, settings, the count of messages in flight (model completion), gathered
// messages, per-node statistics, the error and the typed record of what the model produced.

#include <any>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/effort.h"
#include "core/piece_limits.h"
#include "graph/model_record.h"
#include "graph/tolerance.h"

namespace papercraft {

class CutMemo;  // engine/refine/cut_memo.h

/// Settings that apply to every model of a run (from the command line and the config).
struct RunSettings {
  ToleranceSpec tolerance;
  std::filesystem::path output_dir = "out";
  int threads = 0;          // 0: all cores
  std::string config_file;  // path or "<builtin>"
  std::string config_text;  // the YAML actually used (copied into report.json)
  PaperSpec paper;
  /// The assembly effort's weights (the config's `effort:` map): report.json's `effort`.
  EffortWeights effort;
  /// A model whose surface area at the print scale needs more pages than this (estimated
  /// from the printable area of one page, `page_area_mm2`) is refused before refinement.
  int max_pages = 100;
  double page_area_mm2 = 0.0;  // 0: not estimated
  /// Refuse a tolerance above 50% of the largest side unless set.
  bool allow_large_tolerance = false;
  /// Keep every model's files in memory (ModelRun::files) and write none: no folder is made
  /// under output_dir, which only names the model. The Python module runs so.
  bool keep_in_memory = false;
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

  /// Where the model's files are written while it runs: <out>/.<name>.partial. When the
  /// model succeeds the framework swaps it for <out>/<name> (final_dir) whole, so no file of
  /// an earlier run survives next to the new ones; when it fails the folder is removed and
  /// an earlier result stays as it was.
  std::filesystem::path output_dir() const {
    return settings->output_dir / ("." + name + ".partial");
  }
  std::filesystem::path final_dir() const { return settings->output_dir / name; }

  /// Writes one of the model's files, `name` in its folder: atomically into output_dir()
  /// (made when needed), or into files() with settings->keep_in_memory. `write` gets a stream
  /// to write the contents to (a file's, or memory's). Throws IOException as write_file_atomic.
  void write_file(const std::string& name, const std::function<void(std::ostream&)>& write);
  void write_file(const std::string& name, std::string_view contents);
  /// The files written in memory (settings->keep_in_memory), by name.
  std::map<std::string, std::string> files() const;

  /// The absolute tolerance (model units), fixed by the framework when the loader emits the
  /// model (set_input); 0 before.
  double tolerance() const { return tolerance_.load(); }

  /// The tolerance the strips are refined at: tolerance() less the proxy's certified
  /// distance to the input (set_proxy_distance), so that strips within it of the proxy are
  /// within tolerance() of the input.
  double refinement_tolerance() const { return tolerance_.load() - proxy_distance_.load(); }
  double proxy_distance() const { return proxy_distance_.load(); }
  /// Called by the proxy stage before it emits the model. \pre 0 <= distance < tolerance().
  void set_proxy_distance(double distance);

  /// Messages of this model currently in flight (framework-managed).
  std::atomic<long> in_flight{0};

  /// mm on paper per model unit, fixed with the tolerance (set_input); 0 before.
  double mm_per_unit() const { return mm_per_unit_.load(); }

  /// The run's min_width_mm and min_area_mm2 in model units (0 before set_input).
  PieceLimits piece_limits() const;

  /// Records the loaded input and fixes the absolute tolerance and the print scale from the
  /// run's settings and the input's largest side. Framework-only: called once, when the
  /// entry node emits Model.
  void set_input(const MeshSummary& input);

  /// Record the first error; later messages of this model are dropped. `internal` marks a
  /// broken invariant of papercraft itself (a bug) rather than a problem of the input. The
  /// message is made printable (printable_utf8: bytes that are not UTF-8 and control
  /// characters escaped), so that it can go into JSON and onto a terminal as it is.
  void fail(const std::string& node, const std::string& message, bool internal = false);
  bool failed() const { return failed_.load(); }
  bool internal_error() const;
  std::string error() const;

  /// Fails the model as abandoned (the run was stopped while it ran), unless it failed
  /// already. Framework-only.
  void abandon();
  bool abandoned() const;

  /// Changes the record under the model's lock (nodes of one model run concurrently).
  void update(const std::function<void(ModelRecord&)>& change);
  /// A copy of the record as it stands.
  ModelRecord record() const;

  /// A line for the report's notes (repairs made by the loader, warnings), made printable as
  /// error messages are (a note may quote a file's bytes).
  void note(const std::string& text);

  std::vector<NodeStatistics> node_stats;  // index: node index in the pipeline
  /// Configured node names and implementations, same indexing (set by the pipeline).
  std::vector<std::pair<std::string, std::string>> node_labels;

  // Framework-internal: gathered payloads per gather index and which gathers flushed.
  std::mutex gather_mutex;
  std::map<int, std::vector<std::any>> gathered;
  std::vector<bool> gather_flushed;
  /// Framework-internal: the node whose call on this model started last (for progress).
  std::atomic<int> stage{-1};

  /// Cuts the segment stage made while it chose the parts (count_strips), for the cut stage to
  /// take instead of cutting the same part again. Set before the parts are emitted; null when
  /// there are none.
  std::shared_ptr<CutMemo> cut_memo;

  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }

 private:
  mutable std::mutex mutex_;
  std::atomic<double> tolerance_{0.0};
  std::atomic<double> mm_per_unit_{0.0};
  std::atomic<double> proxy_distance_{0.0};
  std::atomic<bool> failed_{false};
  bool internal_ = false;
  bool abandoned_ = false;
  std::string error_;
  ModelRecord record_;
  std::map<std::string, std::string> files_;  // with keep_in_memory
};

}  // namespace papercraft
