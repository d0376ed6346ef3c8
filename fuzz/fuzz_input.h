#pragma once
// Shared by the fuzz targets: the readers take files, so each input is written to a scratch
// file of this process first; and the loggers are silenced, since a fuzzer runs millions of
// inputs that are meant to be refused.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace papercraft::fuzz {

/// A folder of this process's own under the temporary directory, created on first use.
const std::filesystem::path& scratch_dir();

/// Writes `size` bytes to `scratch_dir() / name` and returns the path.
std::filesystem::path write_scratch_file(const std::string& name, const std::uint8_t* data,
                                         std::size_t size);

/// Turns spdlog and OpenMesh's logs off (once).
void silence_logs();

}  // namespace papercraft::fuzz
