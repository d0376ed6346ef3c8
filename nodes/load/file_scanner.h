#pragma once
// Buffered reading for the pre-scan: lines (as views into the buffer, valid until the next call)
// and raw bytes, with the byte offset always known; and the tokens across lines of a text format.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "nodes/load/parse_values.h"

namespace papercraft::load_internal {

/// Reads a file of `size` bytes line by line or byte by byte. Messages start with `file`.
/// \throws IOException when the file cannot be opened, read or sought.
/// \throws InvalidInputException for a line longer than 64 MiB.
class FileScanner {
 public:
  FileScanner(const std::filesystem::path& path, const std::string& file, std::uint64_t size);
  ~FileScanner();
  FileScanner(const FileScanner&) = delete;
  FileScanner& operator=(const FileScanner&) = delete;

  std::uint64_t size() const { return size_; }
  std::uint64_t offset() const { return buffer_offset_ + begin_; }
  std::uint64_t remaining() const { return size_ - std::min(size_, offset()); }
  std::uint64_t line_number() const { return line_number_; }
  /// Whether the last line returned ended with "\r\n".
  bool last_line_had_carriage_return() const { return carriage_return_; }

  /// The next line without its "\n" or "\r\n"; false at the end of the file.
  bool next_line(std::string_view& line);
  /// Copies the next `count` bytes to `out`; false when fewer are left.
  bool read_bytes(void* out, std::size_t count);
  /// Skips `count` bytes; false, at the end of the file, when fewer are left.
  bool skip(std::uint64_t count);
  /// Goes on reading at byte `position`.
  void seek(std::uint64_t position);

 private:
  bool fill();

  std::string file_;
  std::uint64_t size_ = 0;
  std::FILE* handle_ = nullptr;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  std::uint64_t buffer_offset_ = 0;
  std::uint64_t line_number_ = 0;
  bool carriage_return_ = false;
  bool eof_ = false;
};

/// Whitespace-separated tokens across lines, as OpenMesh's ascii readers see the data.
class TokenReader {
 public:
  explicit TokenReader(FileScanner& in) : in_(in) {}

  /// The next token; false at the end of the file.
  bool next(std::string_view& token) {
    for (;;) {
      token = next_token(rest_);
      if (!token.empty()) return true;
      if (!in_.next_line(rest_)) return false;
    }
  }
  /// The line of the last token read.
  std::uint64_t line() const { return in_.line_number(); }

 private:
  FileScanner& in_;
  std::string_view rest_;
};

}  // namespace papercraft::load_internal
