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
/// removes the temporary file if it throws. Throws IOException if the rename fails, or if
/// remove_temporary_files() was called (the process is about to exit).
/// The temporary is `.<stem>.tmp-<pid>-<n><extension>` in the target's folder.
void write_via_temporary(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

/// For a process that exits while other threads may be writing (an interrupted batch):
/// removes the temporary files of every write under way and makes later writes throw.
/// Returns how many files it removed. A writer that opens its temporary between this call
/// and the process's exit can still leave one behind; call it last, right before _exit.
int remove_temporary_files();

}  // namespace papercraft
