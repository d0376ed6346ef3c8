// Buffered line and byte reading for the pre-scan.

#include "nodes/load/file_scanner.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "nodes/load/messages.h"

namespace papercraft::load_internal {
namespace {

constexpr std::size_t kChunkBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;

}  // namespace

FileScanner::FileScanner(const std::filesystem::path& path, const std::string& file,
                         std::uint64_t size)
    : file_(file), size_(size), buffer_(kChunkBytes) {
  handle_ = std::fopen(path.c_str(), "rb");
  if (handle_ == nullptr) {
    throw_io(file_, std::string("cannot open the file: ") + std::strerror(errno));
  }
}

FileScanner::~FileScanner() {
  std::fclose(handle_);
}

bool FileScanner::next_line(std::string_view& line) {
  std::size_t searched = 0;
  for (;;) {
    const char* start = buffer_.data() + begin_;
    const std::size_t available = end_ - begin_;
    const void* newline =
        searched < available ? std::memchr(start + searched, '\n', available - searched) : nullptr;
    if (newline != nullptr) {
      const auto length = static_cast<std::size_t>(static_cast<const char*>(newline) - start);
      line = std::string_view(start, length);
      begin_ += length + 1;
      break;
    }
    searched = available;
    if (!fill()) {
      if (begin_ == end_) return false;
      line = std::string_view(buffer_.data() + begin_, end_ - begin_);
      begin_ = end_;
      break;
    }
  }
  ++line_number_;
  carriage_return_ = !line.empty() && line.back() == '\r';
  if (carriage_return_) line.remove_suffix(1);
  return true;
}

bool FileScanner::read_bytes(void* out, std::size_t count) {
  if (count == 0) return true;  // `out` may be null then
  while (end_ - begin_ < count) {
    if (!fill()) return false;
  }
  std::memcpy(out, buffer_.data() + begin_, count);
  begin_ += count;
  return true;
}

bool FileScanner::skip(std::uint64_t count) {
  if (count <= end_ - begin_) {
    begin_ += static_cast<std::size_t>(count);
    return true;
  }
  if (count > remaining()) {
    seek(size_);
    return false;
  }
  seek(offset() + count);
  return true;
}

void FileScanner::seek(std::uint64_t position) {
  if (fseeko(handle_, static_cast<off_t>(position), SEEK_SET) != 0) {
    throw_io(file_, std::string("cannot seek: ") + std::strerror(errno));
  }
  buffer_offset_ = position;
  begin_ = end_ = 0;
  eof_ = false;
}

bool FileScanner::fill() {
  if (eof_) return false;
  if (begin_ > 0) {
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    buffer_offset_ += begin_;
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buffer_.size()) {
    if (buffer_.size() >= kMaxLineBytes) {
      throw_invalid(file_, at_line(line_number_ + 1) +
                               "the line is longer than 64 MiB (binary data in a text file?)");
    }
    buffer_.resize(buffer_.size() * 2);
  }
  const std::size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, handle_);
  if (got == 0) {
    if (std::ferror(handle_)) throw_io(file_, std::string("read error: ") + std::strerror(errno));
    eof_ = true;
    return false;
  }
  end_ += got;
  return true;
}

}  // namespace papercraft::load_internal
