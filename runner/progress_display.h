#pragma once
// Progress of a run on stderr (docs/batches.md, "Progress"): on a terminal one line redrawn in
// place, which log messages and result lines print above; otherwise a plain line every few
// seconds.

#include <spdlog/sinks/sink.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

#include "graph/pipeline.h"

namespace papercraft {

/// "3/40 done, 1 failed, 2 skipped, 1m12s elapsed, about 6m05s left; cow: hausdorff, 12
/// parts in flight" — the running model's stage when one model runs, else how many run.
/// `skipped` models were done before the run started and are not in `progress`.
std::string progress_text(const PipelineProgress& progress, std::size_t skipped,
                          double elapsed_seconds);

/// "59s", "1m12s", "2h03m".
std::string format_duration(double seconds);

struct ProgressDisplayOptions {
  bool enabled = true;    // false with --quiet
  bool terminal = false;  // stderr is a terminal
  std::chrono::milliseconds terminal_interval{250};
  std::chrono::milliseconds plain_interval{5000};
};

class ProgressDisplay {
 public:
  explicit ProgressDisplay(ProgressDisplayOptions options);

  /// How often update() should be called.
  std::chrono::milliseconds interval() const;
  /// The clock of the elapsed time starts; `skipped` models were done before.
  void start(std::size_t skipped);
  /// Shows the progress (from any thread).
  void update(const PipelineProgress& progress);
  /// Adds a note to the line, such as "stopping (SIGINT)"; empty removes it.
  void set_note(const std::string& note);
  /// Prints `line` and a newline on `stream` without tearing the progress line.
  void print(std::FILE* stream, const std::string& line);
  /// Removes the progress line for good.
  void finish();
  /// A sink that writes through `inner` after clearing the progress line, and redraws it.
  std::shared_ptr<spdlog::sinks::sink> wrap(std::shared_ptr<spdlog::sinks::sink> inner);

  /// Runs `write` with the line cleared from the terminal, then redraws it.
  template <typename Write>
  void above(Write&& write) {
    std::lock_guard lock(mutex_);
    clear_locked();
    write();
    draw_locked();
  }

 private:
  void clear_locked();
  void draw_locked();

  ProgressDisplayOptions options_;
  std::mutex mutex_;
  std::string line_;  // what is shown (terminal) or was last printed
  std::string note_;
  bool shown_ = false;
  bool finished_ = false;
  std::size_t skipped_ = 0;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_plain_{};
};

}  // namespace papercraft
