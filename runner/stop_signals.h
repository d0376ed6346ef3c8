#pragma once
// SIGINT and SIGTERM as requests to stop a run (docs/batches.md, "Nothing lost"): the first stops
// starting models and gives the running ones a grace period; then (or at a second signal)
// they are abandoned; a run whose node calls do not return soon after is ended by a hard
// exit that still writes the summary. The signals are taken by a thread of our own
// (sigtimedwait), so no work happens in a signal handler.

#include <chrono>
#include <functional>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>

namespace papercraft {

/// Blocks SIGINT and SIGTERM in the calling thread and every thread it starts afterwards.
/// Call before any other thread exists (TBB's workers would otherwise take the signals).
void block_stop_signals();

/// "SIGINT", "SIGTERM", or "signal N".
std::string signal_name(int signal);

struct StopSignalOptions {
  std::chrono::milliseconds grace{10000};        // first signal -> abandon
  std::chrono::milliseconds abandon_wait{2000};  // abandon -> hard exit
  /// Called on the watching thread at the first signal and when models are abandoned.
  std::function<void(int signal)> on_stop;
  std::function<void(int signal)> on_abandon;
  /// Called on the watching thread when the run did not end in time; must not return.
  std::function<void(int signal)> hard_exit;
};

class StopSignals {
 public:
  /// Starts watching. block_stop_signals() must have been called.
  explicit StopSignals(StopSignalOptions options);
  /// Stops watching (a signal after this is left pending, blocked).
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  std::stop_token stop_starting() const { return stop_starting_.get_token(); }
  std::stop_token abandon() const { return abandon_.get_token(); }
  /// The first signal received, 0 if none.
  int signal() const;
  /// The run has ended: no hard exit from now on. Blocks while one is under way (for good).
  void run_ended();

 private:
  void watch();

  StopSignalOptions options_;
  std::stop_source stop_starting_;
  std::stop_source abandon_;
  mutable std::mutex mutex_;  // held by a hard exit, so run_ended() waits for it
  int signal_ = 0;
  bool ended_ = false;
  std::thread thread_;
};

}  // namespace papercraft
