#pragma once
// Files are written to a temporary name beside the target and renamed into place, so a
// reader never sees a half-written file and a crash leaves no partial output.

#include <filesystem>
#include <functional>
#include <string_view>

namespace papercraft {

/// Writes `content` to `path` atomically. Creates parent folders. Throws IOException.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Calls `write(temporary_path)` and renames the result to `path` if it returns normally;
/// removes the temporary file if it throws. Throws IOException if the rename fails.
void write_via_temporary(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

}  // namespace papercraft
