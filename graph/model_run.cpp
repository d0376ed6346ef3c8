#include "graph/model_run.h"

#include <algorithm>

namespace papercraft {

ModelRun::ModelRun(int index_in, std::filesystem::path input, std::string name_in,
                   std::shared_ptr<const RunSettings> settings_in, std::size_t node_count)
    : index(index_in),
      input_path(std::move(input)),
      name(std::move(name_in)),
      settings(std::move(settings_in)),
      node_stats(node_count) {}

void ModelRun::fail(const std::string& node, const std::string& message) {
  std::lock_guard lock(mutex_);
  if (failed_.load()) return;
  error_ = node.empty() ? message : node + ": " + message;
  failed_.store(true);
}

std::string ModelRun::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void ModelRun::set_result(const std::string& key, double value) {
  std::lock_guard lock(mutex_);
  results_[key] = value;
}

void ModelRun::add_result(const std::string& key, double value) {
  std::lock_guard lock(mutex_);
  results_[key] += value;
}

void ModelRun::max_result(const std::string& key, double value) {
  std::lock_guard lock(mutex_);
  auto [it, inserted] = results_.emplace(key, value);
  if (!inserted) it->second = std::max(it->second, value);
}

std::map<std::string, double> ModelRun::results() const {
  std::lock_guard lock(mutex_);
  return results_;
}

void ModelRun::note(const std::string& text) {
  std::lock_guard lock(mutex_);
  notes_.push_back(text);
}

std::vector<std::string> ModelRun::notes() const {
  std::lock_guard lock(mutex_);
  return notes_;
}

}  // namespace papercraft
