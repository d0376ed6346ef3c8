#include "core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <system_error>

#include "core/errors.h"

namespace papercraft {

namespace {

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  // Keeps the extension: some writers (OpenMesh) choose the format from it.
  // Appended rather than `"." + ...`, which trips GCC 12's -Wrestrict once inlined.
  std::string name(1, '.');
  name.append(path.stem().string());
  name.append(".tmp-");
  name.append(std::to_string(::getpid()));
  name.append("-");
  name.append(std::to_string(counter.fetch_add(1)));
  name.append(path.extension().string());
  return path.parent_path() / name;
}

// The temporaries of the writes under way, for remove_temporary_files().
struct LiveTemporaries {
  std::mutex mutex;
  std::set<std::filesystem::path> paths;
  bool closed = false;
};

LiveTemporaries& live_temporaries() {
  static LiveTemporaries* live = new LiveTemporaries;  // never destroyed: used up to _exit
  return *live;
}

}  // namespace

int remove_temporary_files() {
  LiveTemporaries& live = live_temporaries();
  std::lock_guard lock(live.mutex);
  live.closed = true;
  int removed = 0;
  for (const auto& path : live.paths) {
    std::error_code ec;
    if (std::filesystem::remove(path, ec)) ++removed;
  }
  live.paths.clear();
  return removed;
}

void write_via_temporary(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write) {
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  if (ec)
    throw IOException(path.parent_path().string() + ": cannot create folder: " + ec.message());
  const std::filesystem::path temporary = temporary_name(path);
  LiveTemporaries& live = live_temporaries();
  {
    std::lock_guard lock(live.mutex);
    if (live.closed) throw IOException(path.string() + ": not written: the process is exiting");
    live.paths.insert(temporary);
  }
  const auto forget = [&] {
    std::lock_guard lock(live.mutex);
    live.paths.erase(temporary);
  };
  try {
    write(temporary);
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    forget();
    throw;
  }
  std::filesystem::rename(temporary, path, ec);
  forget();
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw IOException(path.string() + ": cannot write: " + ec.message());
  }
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  write_via_temporary(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) throw IOException(path.string() + ": cannot write (disk full or no permission?)");
  });
}

}  // namespace papercraft
