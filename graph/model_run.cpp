#include "graph/model_run.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/printable_utf8.h"
#include "graph/params.h"

namespace papercraft {

namespace {

// A measured size in a message as a person writes it: "7.43", "1031", "52630", "3.75e+13".
std::string rounded(double value) {
  char text[32];
  const double size = std::abs(value);
  std::snprintf(text, sizeof text, size >= 100 && size < 1e9 ? "%.0f" : "%.3g", value);
  return text;
}

// Sizes that would make a pattern no one wants: refused before the refinement starts.
void check_sizes(const RunSettings& settings, const MeshSummary& input, double tolerance,
                 double mm_per_unit) {
  if (!settings.allow_large_tolerance && input.largest_side > 0.0 &&
      tolerance > kLargestTolerance * input.largest_side) {
    throw InvalidInputException(
        "tolerance " + format_number(tolerance) + " is " +
        rounded(100.0 * tolerance / input.largest_side) + "% of the model's largest side (" +
        rounded(input.largest_side) +
        "), above the 50% that still resembles the model; give a smaller tolerance or "
        "--allow-large-tolerance");
  }
  if (settings.page_area_mm2 <= 0.0 || settings.max_pages <= 0) return;
  const double pages = input.area * mm_per_unit * mm_per_unit / settings.page_area_mm2;
  if (pages > settings.max_pages) {
    const std::string estimate =
        pages < 1e6 ? std::to_string(static_cast<long>(std::ceil(pages))) : rounded(pages);
    throw InvalidInputException("the pattern would need about " + estimate + " pages (surface " +
                                rounded(input.area) + " units^2 at " + rounded(mm_per_unit) +
                                " mm per unit over " + rounded(settings.page_area_mm2) +
                                " mm^2 printable per page), more than max_pages " +
                                std::to_string(settings.max_pages) +
                                "; give a smaller --height or --scale, or raise --max-pages");
  }
}

}  // namespace

ModelRun::ModelRun(int index_in, std::filesystem::path input, std::string name_in,
                   std::shared_ptr<const RunSettings> settings_in, std::size_t node_count)
    : index(index_in),
      input_path(std::move(input)),
      name(std::move(name_in)),
      settings(std::move(settings_in)),
      node_stats(node_count) {}

void ModelRun::set_input(const MeshSummary& input) {
  const double tolerance = settings->tolerance.absolute(input.largest_side);
  const double mm_per_unit = settings->paper.mm_per_unit(input.largest_side);
  check_sizes(*settings, input, tolerance, mm_per_unit);
  std::lock_guard lock(mutex_);
  record_.loaded = true;
  record_.input = input;
  record_.tolerance = tolerance;
  record_.mm_per_unit = mm_per_unit;
  tolerance_.store(tolerance);
  mm_per_unit_.store(mm_per_unit);
}

void ModelRun::set_proxy_distance(double distance) {
  if (!(distance >= 0.0 && distance < tolerance()))
    throw InternalError("proxy distance " + std::to_string(distance) +
                        " is not below the tolerance " + std::to_string(tolerance()));
  proxy_distance_.store(distance);
}

PieceLimits ModelRun::piece_limits() const {
  const double scale = mm_per_unit();
  PieceLimits limits;
  if (scale > 0.0) {
    limits.min_width = settings->paper.min_width_mm / scale;
    limits.min_area = settings->paper.min_area_mm2 / (scale * scale);
  }
  return limits;
}

void ModelRun::fail(const std::string& node, const std::string& message, bool internal) {
  std::lock_guard lock(mutex_);
  if (failed_.load()) return;
  error_ = printable_utf8(node.empty() ? message : node + ": " + message);
  internal_ = internal;
  failed_.store(true);
}

bool ModelRun::internal_error() const {
  std::lock_guard lock(mutex_);
  return internal_;
}

void ModelRun::abandon() {
  std::lock_guard lock(mutex_);
  if (failed_.load()) return;
  error_ = "abandoned: the run was stopped while it ran";
  abandoned_ = true;
  failed_.store(true);
}

bool ModelRun::abandoned() const {
  std::lock_guard lock(mutex_);
  return abandoned_;
}

std::string ModelRun::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void ModelRun::update(const std::function<void(ModelRecord&)>& change) {
  std::lock_guard lock(mutex_);
  change(record_);
}

void ModelRun::write_file(const std::string& name,
                          const std::function<void(std::ostream&)>& write) {
  if (settings->keep_in_memory) {
    std::ostringstream out(std::ios::binary);
    write(out);
    std::lock_guard lock(mutex_);
    files_[name] = std::move(out).str();
    return;
  }
  const std::filesystem::path path = output_dir() / name;
  write_via_temporary(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw IOException(printable_utf8(path.string()) + ": cannot open for writing");
    write(out);
    out.close();
    if (!out) throw IOException(printable_utf8(path.string()) + ": cannot write");
  });
}

void ModelRun::write_file(const std::string& name, std::string_view contents) {
  if (settings->keep_in_memory) {
    std::lock_guard lock(mutex_);
    files_[name] = std::string(contents);
    return;
  }
  write_file_atomic(output_dir() / name, contents);
}

std::map<std::string, std::string> ModelRun::files() const {
  std::lock_guard lock(mutex_);
  return files_;
}

ModelRecord ModelRun::record() const {
  std::lock_guard lock(mutex_);
  return record_;
}

void ModelRun::note(const std::string& text) {
  update([&](ModelRecord& record) { record.notes.push_back(printable_utf8(text)); });
}

}  // namespace papercraft
