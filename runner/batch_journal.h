#pragma once
// The record of a running batch: every finished model is appended to the journal (.jsonl) at
// once and the summary (.json) is rewritten atomically at most once a rewrite_interval, so a
// batch stopped in any way leaves the rows of all it finished. Models finish on worker
// threads; they only queue their row here, and one thread of the journal's own does the I/O.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "runner/batch_summary.h"

namespace papercraft {

struct JournalOptions {
  SummaryFiles files;
  std::string shard;  // "2/3" or empty
  std::chrono::milliseconds rewrite_interval{1000};
  /// Called on the journal's thread after the row of input `index` was appended.
  std::function<void(std::size_t index, const BatchRow& row)> on_recorded;
  /// A run written down after it happened (the Python module's Result.write): when it started
  /// and finished (unix seconds), the summary's times in place of the journal's own. 0: none.
  double ran_from = 0.0, ran_to = 0.0;
};

class BatchJournal {
 public:
  /// Writes the summary with `rows` (one per input: skipped rows ok, the others pending),
  /// starts the journal afresh with the rows that are not pending (reported to on_recorded
  /// on the calling thread), and starts the thread.
  /// Throws IOException if the files cannot be written.
  BatchJournal(JournalOptions options, std::vector<BatchRow> rows);
  ~BatchJournal();
  BatchJournal(const BatchJournal&) = delete;
  BatchJournal& operator=(const BatchJournal&) = delete;

  /// Marks row `index` as running since now (for the row close() writes if it never ends).
  void started(std::size_t index);
  /// Queues the final row of input `index`; returns at once. Ignored after close().
  void record(std::size_t index, BatchRow row);
  /// Writes every queued row, marks the rows still pending as interrupted, appends those and
  /// writes the final summary. `interrupted_by`: the signal's name, or empty. Returns what it
  /// wrote. From any thread; a second call returns the same; never throws (a failed write is
  /// logged).
  BatchSummary close(const std::string& interrupted_by);

 private:
  void loop();
  void append(const BatchRow& row);
  BatchSummary write_summary(bool complete);

  JournalOptions options_;
  double started_at_ = 0.0;
  std::string interrupted_by_;
  int journal_fd_ = -1;

  std::mutex mutex_;  // guards queue_, rows_, closing_, closed_
  std::condition_variable wake_;
  std::deque<std::pair<std::size_t, BatchRow>> queue_;
  std::vector<BatchRow> rows_;
  bool closing_ = false;
  bool closed_ = false;
  BatchSummary final_;
  std::mutex close_mutex_;  // one close() at a time
  std::thread thread_;
};

}  // namespace papercraft
