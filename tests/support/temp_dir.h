#pragma once
// Scratch folders for tests: unique per process and name, removed when the test process exits
// (set PAPERCRAFT_KEEP_TEST_OUTPUT=1 to keep them for a look).

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace papercraft::testing {

namespace detail {
class TempDirRegistry {
 public:
  ~TempDirRegistry() {
    if (std::getenv("PAPERCRAFT_KEEP_TEST_OUTPUT") != nullptr) return;
    std::error_code ignored;
    for (const auto& dir : dirs_) std::filesystem::remove_all(dir, ignored);
  }
  void add(const std::filesystem::path& dir) {
    const std::lock_guard lock(mutex_);
    dirs_.push_back(dir);
  }

 private:
  std::mutex mutex_;
  std::vector<std::filesystem::path> dirs_;
};

inline TempDirRegistry& temp_dir_registry() {
  static TempDirRegistry registry;
  return registry;
}
}  // namespace detail

/// A new empty folder under the system temp directory, removed at process exit.
inline std::filesystem::path fresh_temp_dir(const std::string& name) {
  static std::atomic<int> counter{0};
  auto dir = std::filesystem::temp_directory_path() /
             ("papercraft-test-" + std::to_string(::getpid()) + "-" + name + "-" +
              std::to_string(counter.fetch_add(1)));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  detail::temp_dir_registry().add(dir);
  return dir;
}

}  // namespace papercraft::testing
