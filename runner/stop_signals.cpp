#include "runner/stop_signals.h"

#include <pthread.h>
#include <signal.h>

#include <ctime>

namespace papercraft {

namespace {

sigset_t stop_signal_set() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

void block_stop_signals() {
  const sigset_t set = stop_signal_set();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

StopSignals::StopSignals(StopSignalOptions options) : options_(std::move(options)) {
  thread_ = std::thread([this] { watch(); });
}

StopSignals::~StopSignals() {
  {
    std::lock_guard lock(mutex_);
    ended_ = true;
  }
  if (thread_.joinable()) thread_.join();
}

int StopSignals::signal() const {
  std::lock_guard lock(mutex_);
  return signal_;
}

void StopSignals::run_ended() {
  std::lock_guard lock(mutex_);
  ended_ = true;
}

void StopSignals::watch() {
  using Clock = std::chrono::steady_clock;
  const sigset_t set = stop_signal_set();
  Clock::time_point abandon_at = Clock::time_point::max();
  Clock::time_point hard_exit_at = Clock::time_point::max();
  int first = 0;
  while (true) {
    const timespec poll{0, 100'000'000};  // 0.1 s: how soon the end of a run is noticed
    const int received = ::sigtimedwait(&set, nullptr, &poll);
    const auto now = Clock::now();
    std::unique_lock lock(mutex_);
    if (ended_) return;
    if (received > 0) {
      if (first == 0) {
        first = received;
        signal_ = received;
        abandon_at = now + options_.grace;
        lock.unlock();
        stop_starting_.request_stop();
        if (options_.on_stop) options_.on_stop(received);
        lock.lock();
      } else if (!abandon_.stop_requested()) {
        abandon_at = now;  // a second signal: do not wait for the grace period
      } else {
        hard_exit_at = now;  // a third: do not wait for node calls to return
      }
    }
    if (first != 0 && !abandon_.stop_requested() && now >= abandon_at) {
      hard_exit_at = now + options_.abandon_wait;
      lock.unlock();
      abandon_.request_stop();
      if (options_.on_abandon) options_.on_abandon(first);
      lock.lock();
    }
    if (ended_) return;
    if (now >= hard_exit_at && options_.hard_exit) {
      options_.hard_exit(first);  // with mutex_ held: run_ended() waits until _exit
    }
  }
}

}  // namespace papercraft
