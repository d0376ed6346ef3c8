#include "runner/progress_display.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cmath>

#include "core/printable_utf8.h"

namespace papercraft {

namespace {

int terminal_columns() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

// A spdlog sink that keeps the progress line below the messages.
class AboveProgressSink : public spdlog::sinks::sink {
 public:
  AboveProgressSink(ProgressDisplay& display, std::shared_ptr<spdlog::sinks::sink> inner)
      : display_(display), inner_(std::move(inner)) {}
  void log(const spdlog::details::log_msg& message) override {
    display_.above([&] {
      inner_->log(message);
      inner_->flush();
    });
  }
  void flush() override { inner_->flush(); }
  void set_pattern(const std::string& pattern) override { inner_->set_pattern(pattern); }
  void set_formatter(std::unique_ptr<spdlog::formatter> formatter) override {
    inner_->set_formatter(std::move(formatter));
  }

 private:
  ProgressDisplay& display_;
  std::shared_ptr<spdlog::sinks::sink> inner_;
};

}  // namespace

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  char buffer[32];
  if (total < 60) {
    std::snprintf(buffer, sizeof buffer, "%lds", total);
  } else if (total < 3600) {
    std::snprintf(buffer, sizeof buffer, "%ldm%02lds", total / 60, total % 60);
  } else {
    std::snprintf(buffer, sizeof buffer, "%ldh%02ldm", total / 3600, total % 3600 / 60);
  }
  return buffer;
}

std::string progress_text(const PipelineProgress& progress, std::size_t skipped,
                          double elapsed_seconds) {
  std::string text = std::to_string(progress.done) + "/" + std::to_string(progress.total) + " done";
  if (progress.failed > 0) text += ", " + std::to_string(progress.failed) + " failed";
  if (skipped > 0) text += ", " + std::to_string(skipped) + " skipped";
  text += ", " + format_duration(elapsed_seconds) + " elapsed";
  if (progress.done > 0 && progress.done < progress.total) {
    // The rate so far holds for the rest: models of a batch are alike on average.
    const double left = elapsed_seconds / static_cast<double>(progress.done) *
                        static_cast<double>(progress.total - progress.done);
    text += ", about " + format_duration(left) + " left";
  }
  if (progress.running.size() == 1) {
    const PipelineProgress::Running& model = progress.running.front();
    text += "; " + printable_utf8(model.name) + ": " + model.stage + ", " +
            std::to_string(model.in_flight) + (model.in_flight == 1 ? " part" : " parts") +
            " in flight";
  } else if (!progress.running.empty()) {
    text += "; " + std::to_string(progress.running.size()) + " running";
  }
  return text;
}

ProgressDisplay::ProgressDisplay(ProgressDisplayOptions options) : options_(options) {}

std::chrono::milliseconds ProgressDisplay::interval() const {
  return options_.terminal ? options_.terminal_interval : options_.plain_interval;
}

void ProgressDisplay::start(std::size_t skipped) {
  std::lock_guard lock(mutex_);
  skipped_ = skipped;
  started_ = std::chrono::steady_clock::now();
  last_plain_ = started_;
}

void ProgressDisplay::update(const PipelineProgress& progress) {
  if (!options_.enabled) return;
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard lock(mutex_);
  if (finished_) return;
  line_ = progress_text(progress, skipped_, std::chrono::duration<double>(now - started_).count());
  if (options_.terminal) {
    draw_locked();
  } else if (now - last_plain_ >= options_.plain_interval) {
    std::fprintf(stderr, "progress: %s%s\n", line_.c_str(),
                 note_.empty() ? "" : ("; " + note_).c_str());
    std::fflush(stderr);
    last_plain_ = now;
  }
}

void ProgressDisplay::set_note(const std::string& note) {
  std::lock_guard lock(mutex_);
  note_ = note;
  if (options_.enabled && options_.terminal && !line_.empty()) draw_locked();
}

void ProgressDisplay::print(std::FILE* stream, const std::string& line) {
  above([&] {
    std::fputs(line.c_str(), stream);
    std::fputc('\n', stream);
    std::fflush(stream);
  });
}

void ProgressDisplay::finish() {
  std::lock_guard lock(mutex_);
  clear_locked();
  finished_ = true;
}

std::shared_ptr<spdlog::sinks::sink> ProgressDisplay::wrap(
    std::shared_ptr<spdlog::sinks::sink> inner) {
  return std::make_shared<AboveProgressSink>(*this, std::move(inner));
}

void ProgressDisplay::clear_locked() {
  if (!shown_) return;
  std::fputs("\r\x1b[K", stderr);
  std::fflush(stderr);
  shown_ = false;
}

void ProgressDisplay::draw_locked() {
  if (!options_.enabled || !options_.terminal || finished_ || line_.empty()) return;
  std::string text = line_ + (note_.empty() ? "" : "; " + note_);
  // A line that wraps cannot be redrawn in place with \r.
  const std::size_t width = static_cast<std::size_t>(std::max(10, terminal_columns() - 1));
  if (text.size() > width) {
    std::size_t cut = width - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text = text.substr(0, cut) + "...";
  }
  std::fprintf(stderr, "\r%s\x1b[K", text.c_str());
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace papercraft
