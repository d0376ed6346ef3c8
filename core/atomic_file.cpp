#include "core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <string>
#include <system_error>

#include "core/errors.h"

namespace papercraft {

namespace {

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  // Keeps the extension: some writers (OpenMesh) choose the format from it.
  return path.parent_path() /
         ("." + path.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
          std::to_string(counter.fetch_add(1)) + path.extension().string());
}

}  // namespace

void write_via_temporary(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write) {
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  if (ec)
    throw IOException(path.parent_path().string() + ": cannot create folder: " + ec.message());
  const std::filesystem::path temporary = temporary_name(path);
  try {
    write(temporary);
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
  std::filesystem::rename(temporary, path, ec);
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
