#include "runner/batch_journal.h"

#include <fcntl.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/atomic_file.h"
#include "core/errors.h"

namespace papercraft {

BatchJournal::BatchJournal(JournalOptions options, std::vector<BatchRow> rows)
    : options_(std::move(options)),
      started_at_(options_.ran_to > 0.0 ? options_.ran_from : unix_seconds_now()),
      rows_(std::move(rows)) {
  write_summary(false);
  journal_fd_ = ::open(options_.files.journal.c_str(),
                       O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (journal_fd_ < 0) {
    throw IOException(options_.files.journal.string() + ": cannot write: " + std::strerror(errno));
  }
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (rows_[i].status == RowStatus::kPending) continue;
    append(rows_[i]);
    if (options_.on_recorded) options_.on_recorded(i, rows_[i]);
  }
  thread_ = std::thread([this] { loop(); });
}

BatchJournal::~BatchJournal() {
  close("");
  if (journal_fd_ >= 0) ::close(journal_fd_);
}

void BatchJournal::started(std::size_t index) {
  const double now = unix_seconds_now();
  std::lock_guard lock(mutex_);
  if (index < rows_.size() && rows_[index].status == RowStatus::kPending) {
    rows_[index].started_at = now;
  }
}

void BatchJournal::record(std::size_t index, BatchRow row) {
  {
    std::lock_guard lock(mutex_);
    if (closing_) return;
    queue_.emplace_back(index, std::move(row));
  }
  wake_.notify_one();
}

void BatchJournal::append(const BatchRow& row) {
  // One write() per line: with O_APPEND the line lands whole at the end.
  const std::string line = row_to_json(row).dump() + "\n";
  std::size_t written = 0;
  while (written < line.size()) {
    const ssize_t n = ::write(journal_fd_, line.data() + written, line.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      spdlog::error("{}: cannot append: {}", options_.files.journal.string(), std::strerror(errno));
      return;
    }
    written += static_cast<std::size_t>(n);
  }
}

BatchSummary BatchJournal::write_summary(bool complete) {
  BatchSummary summary;
  summary.shard = options_.shard;
  summary.complete = complete;
  summary.interrupted_by = interrupted_by_;
  summary.started_at = started_at_;
  summary.finished_at = options_.ran_to > 0.0 ? options_.ran_to : unix_seconds_now();
  {
    std::lock_guard lock(mutex_);
    summary.rows = rows_;
  }
  write_file_atomic(options_.files.summary, summary_json_text(summary));
  return summary;
}

void BatchJournal::loop() {
  auto last_write = std::chrono::steady_clock::now();
  bool dirty = false;
  std::unique_lock lock(mutex_);
  while (true) {
    const auto deadline = last_write + options_.rewrite_interval;
    if (dirty) {
      wake_.wait_until(lock, deadline, [this] { return !queue_.empty() || closing_; });
    } else {
      wake_.wait(lock, [this] { return !queue_.empty() || closing_; });
    }
    while (!queue_.empty()) {
      auto [index, row] = std::move(queue_.front());
      queue_.pop_front();
      if (index < rows_.size()) rows_[index] = row;
      lock.unlock();
      append(row);
      if (options_.on_recorded) options_.on_recorded(index, row);
      dirty = true;
      lock.lock();
    }
    if (closing_) return;  // close() writes the final summary
    if (dirty && std::chrono::steady_clock::now() >= last_write + options_.rewrite_interval) {
      lock.unlock();
      try {
        write_summary(false);
      } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
      }
      last_write = std::chrono::steady_clock::now();
      dirty = false;
      lock.lock();
    }
  }
}

BatchSummary BatchJournal::close(const std::string& interrupted_by) {
  std::lock_guard close_lock(close_mutex_);
  {
    std::lock_guard lock(mutex_);
    if (closed_) return final_;
    closing_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
  std::vector<std::size_t> interrupted;
  {
    const double now = unix_seconds_now();
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      BatchRow& row = rows_[i];
      if (row.status != RowStatus::kPending) continue;
      row.status = RowStatus::kInterrupted;
      if (row.started_at > 0) {
        row.error = "interrupted while it ran (the process exited)";
        row.finished_at = now;
        row.wall_seconds = now - row.started_at;
        row.queue_seconds = row.started_at - started_at_;
      } else {
        row.error = "interrupted before it started";
      }
      interrupted.push_back(i);
    }
  }
  interrupted_by_ = interrupted_by;
  for (const std::size_t i : interrupted) {
    append(rows_[i]);
    if (options_.on_recorded) options_.on_recorded(i, rows_[i]);
  }
  BatchSummary summary;
  try {
    summary = write_summary(true);
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    summary.rows = rows_;
  }
  std::lock_guard lock(mutex_);
  closed_ = true;
  final_ = summary;
  return final_;
}

}  // namespace papercraft
