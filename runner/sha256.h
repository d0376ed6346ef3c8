#pragma once
// SHA-256 (FIPS 180-4) of a text or a file: the content hash a resumed batch compares, so
// that a model is skipped only when its input file holds the same bytes as before.

#include <filesystem>
#include <string>
#include <string_view>

namespace papercraft {

/// The SHA-256 digest of `data` as 64 lower-case hex digits.
std::string sha256_hex(std::string_view data);

/// The SHA-256 digest of the file's bytes, read in blocks. Throws IOException if it cannot
/// be read.
std::string file_sha256_hex(const std::filesystem::path& path);

}  // namespace papercraft
