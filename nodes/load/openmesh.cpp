#include "nodes/load/openmesh.h"

#include <tbb/parallel_sort.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <map>
#include <mutex>
#include <numeric>
#include <sstream>
#include <string_view>
#include <system_error>
#include <unordered_map>

#include "core/errors.h"

namespace papercraft {
namespace {

using OpenMesh::Vec2d;
using OpenMesh::Vec3d;
using Triangle3 = std::array<int, 3>;

constexpr std::size_t kChunkBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 20;
constexpr std::size_t kMaxPlyHeaderLines = 100'000;

// ---------------------------------------------------------------------------------------------
// Messages

[[noreturn]] void throw_invalid(const std::string& file, const std::string& what) {
  throw InvalidInputException(file + ": " + what);
}

[[noreturn]] void throw_io(const std::string& file, const std::string& what) {
  throw IOException(file + ": " + what);
}

std::string counted(std::uint64_t n, std::string_view singular, std::string_view plural) {
  return std::to_string(n) + " " + std::string(n == 1 ? singular : plural);
}

std::string at_line(std::uint64_t line) {
  return "line " + std::to_string(line) + ": ";
}

std::string in_quotes(std::string_view text) {
  if (text.size() > 40) return "'" + std::string(text.substr(0, 40)) + "...'";
  return "'" + std::string(text) + "'";
}

std::string vertex_list(const std::vector<int>& source_vertex, const Triangle3& t) {
  return std::to_string(source_vertex[t[0]]) + ", " + std::to_string(source_vertex[t[1]]) + ", " +
         std::to_string(source_vertex[t[2]]);
}

// ---------------------------------------------------------------------------------------------
// Text helpers

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

std::string_view next_token(std::string_view& rest) {
  std::size_t begin = 0;
  while (begin < rest.size() && is_space(rest[begin])) ++begin;
  std::size_t end = begin;
  while (end < rest.size() && !is_space(rest[end])) ++end;
  const std::string_view token = rest.substr(begin, end - begin);
  rest.remove_prefix(end);
  return token;
}

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(prefix[i]))) {
      return false;
    }
  }
  return true;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && starts_with_ignoring_case(a, b);
}

enum class NumberKind { finite, non_finite, invalid };

// As OpenMesh's `stream >> float` reads a token: NaN, infinities and magnitudes beyond single
// precision make its readers fail or drop the record, so they count as non-finite. An underflow
// reads as zero, as it does for OpenMesh.
NumberKind classify_float(std::string_view token, float* value = nullptr) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return NumberKind::invalid;
  double number = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), number);
  if (end != token.data() + token.size()) return NumberKind::invalid;
  if (error == std::errc::result_out_of_range) {
    const std::size_t exponent = token.find_first_of("eE");
    const bool underflow = exponent != std::string_view::npos && exponent + 1 < token.size() &&
                           token[exponent + 1] == '-';
    if (!underflow) return NumberKind::non_finite;
    number = 0.0;
  } else if (error != std::errc()) {
    return NumberKind::invalid;
  }
  if (!std::isfinite(number) || std::fabs(number) > FLT_MAX) return NumberKind::non_finite;
  if (value != nullptr) *value = static_cast<float>(number);
  return NumberKind::finite;
}

bool parse_integer(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size();
}

std::uint64_t multiply_saturating(std::uint64_t a, std::uint64_t b) {
  std::uint64_t product = 0;
  return __builtin_mul_overflow(a, b, &product) ? UINT64_MAX : product;
}

std::uint64_t add_saturating(std::uint64_t a, std::uint64_t b) {
  return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

std::int64_t decode_integer(const unsigned char* bytes, int size, bool is_signed, bool big_endian) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    value |= std::uint64_t{bytes[big_endian ? size - 1 - i : i]} << (8 * i);
  }
  if (is_signed && size < 8 && ((value >> (8 * size - 1)) & 1u) != 0) {
    value |= ~std::uint64_t{0} << (8 * size);
  }
  return static_cast<std::int64_t>(value);
}

float decode_float_little_endian(const unsigned char* bytes) {
  const std::uint32_t bits = static_cast<std::uint32_t>(decode_integer(bytes, 4, false, false));
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// ---------------------------------------------------------------------------------------------
// Buffered reading for the pre-scan: lines (as views into the buffer, valid until the next call)
// and raw bytes, with the byte offset always known.

class FileScanner {
 public:
  FileScanner(const std::filesystem::path& path, const std::string& file, std::uint64_t size)
      : file_(file), size_(size), buffer_(kChunkBytes) {
    handle_ = std::fopen(path.c_str(), "rb");
    if (handle_ == nullptr) {
      throw_io(file_, std::string("cannot open the file: ") + std::strerror(errno));
    }
  }
  ~FileScanner() { std::fclose(handle_); }
  FileScanner(const FileScanner&) = delete;
  FileScanner& operator=(const FileScanner&) = delete;

  std::uint64_t size() const { return size_; }
  std::uint64_t offset() const { return buffer_offset_ + begin_; }
  std::uint64_t remaining() const { return size_ - std::min(size_, offset()); }
  std::uint64_t line_number() const { return line_number_; }
  // Whether the last line returned ended with "\r\n".
  bool last_line_had_carriage_return() const { return carriage_return_; }

  bool next_line(std::string_view& line) {
    std::size_t searched = 0;
    for (;;) {
      const char* start = buffer_.data() + begin_;
      const std::size_t available = end_ - begin_;
      const void* newline = searched < available
                                ? std::memchr(start + searched, '\n', available - searched)
                                : nullptr;
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

  bool read_bytes(void* out, std::size_t count) {
    while (end_ - begin_ < count) {
      if (!fill()) return false;
    }
    std::memcpy(out, buffer_.data() + begin_, count);
    begin_ += count;
    return true;
  }

  bool skip(std::uint64_t count) {
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

  void seek(std::uint64_t position) {
    if (fseeko(handle_, static_cast<off_t>(position), SEEK_SET) != 0) {
      throw_io(file_, std::string("cannot seek: ") + std::strerror(errno));
    }
    buffer_offset_ = position;
    begin_ = end_ = 0;
    eof_ = false;
  }

 private:
  bool fill() {
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

// Whitespace-separated tokens across lines, as OpenMesh's ascii readers see the data.
class TokenReader {
 public:
  explicit TokenReader(FileScanner& in) : in_(in) {}

  bool next(std::string_view& token) {
    for (;;) {
      token = next_token(rest_);
      if (!token.empty()) return true;
      if (!in_.next_line(rest_)) return false;
    }
  }
  std::uint64_t line() const { return in_.line_number(); }

 private:
  FileScanner& in_;
  std::string_view rest_;
};

// ---------------------------------------------------------------------------------------------
// Pre-scan: what the file must contain, checked before OpenMesh sees it.

enum class Format { obj, off, ply, stl };

struct Prescan {
  Format format = Format::obj;
  // Records OpenMesh must report (for an STL, `vertices` is 3 per triangle before welding).
  std::uint64_t vertices = 0;
  std::uint64_t faces = 0;
  std::uint64_t corners = 0;
  std::filesystem::path material_library;  // OBJ mtllib, resolved against the OBJ's folder
  std::string ply_texture;                 // PLY "comment TextureFile <name>"
  bool off_comments = false;               // an ascii OFF with '#' comments
  std::uint64_t off_face_extras = 0;       // OFF faces with values after their indices
};

void check_counts(const std::string& file, std::uint64_t vertices, std::uint64_t faces,
                  const LoadOptions& options) {
  if (faces > options.max_faces) {
    throw_invalid(file, "declares " + counted(faces, "face", "faces") +
                            ", more than the limit of " + std::to_string(options.max_faces) +
                            " (LoadOptions::max_faces)");
  }
  if (vertices > static_cast<std::uint64_t>(INT_MAX) - 1) {
    throw_invalid(file, "declares " + counted(vertices, "vertex", "vertices") +
                            ", more than OpenMesh can index");
  }
}

std::string declared(std::uint64_t vertices, std::uint64_t faces) {
  return counted(vertices, "vertex", "vertices") + " and " + counted(faces, "face", "faces");
}

void check_room(const std::string& file, const std::string& what, std::uint64_t needed,
                std::uint64_t available) {
  if (needed > available) {
    throw_invalid(file, "truncated or corrupt header: it declares " + what +
                            ", which need at least " + std::to_string(needed) +
                            " bytes, but only " + std::to_string(available) +
                            " bytes follow the header");
  }
}

void check_some_faces(const std::string& file, const Prescan& scan) {
  if (scan.faces > 0) return;
  throw_invalid(
      file, "mesh has no faces" + (scan.vertices > 0
                                       ? " (only " + counted(scan.vertices, "vertex", "vertices") +
                                             ": a point cloud?)"
                                       : std::string()));
}

// -- OBJ

Prescan prescan_obj(FileScanner& in, const std::string& file, const std::filesystem::path& path,
                    const LoadOptions& options) {
  Prescan scan;
  scan.format = Format::obj;
  std::uint64_t degenerate = 0;
  std::uint64_t first_degenerate_line = 0;
  std::vector<std::int64_t> face;
  std::string_view line;
  while (in.next_line(line)) {
    std::string_view rest = trim(line);
    if (rest.empty() || rest.front() == '#') continue;
    const std::string_view keyword = next_token(rest);
    if (keyword == "v") {
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view token = next_token(rest);
        const NumberKind kind = classify_float(token);
        if (kind == NumberKind::non_finite) {
          throw_invalid(file, at_line(in.line_number()) + "vertex " +
                                  std::to_string(scan.vertices) + " has a non-finite coordinate " +
                                  in_quotes(token) + " (NaN, infinite or beyond single precision)");
        }
        if (kind == NumberKind::invalid) {
          throw_invalid(file, at_line(in.line_number()) + "expected 3 coordinates after 'v', got " +
                                  in_quotes(trim(line)));
        }
      }
      ++scan.vertices;
    } else if (keyword == "vt") {
      for (int axis = 0; axis < 2; ++axis) {
        const std::string_view token = next_token(rest);
        const NumberKind kind = classify_float(token);
        if (kind != NumberKind::finite) {
          throw_invalid(file, at_line(in.line_number()) +
                                  "expected 2 finite texture coordinates after 'vt', got " +
                                  in_quotes(trim(line)));
        }
      }
    } else if (keyword == "f") {
      face.clear();
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
        std::int64_t index = 0;
        if (!parse_integer(token.substr(0, token.find('/')), index) || index == 0) {
          throw_invalid(file, at_line(in.line_number()) + "bad vertex reference " +
                                  in_quotes(token) +
                                  " in a face (expected a non-zero vertex number, optionally "
                                  "followed by /texcoord/normal)");
        }
        // Negative references count back from the vertices read so far, as in OpenMesh.
        face.push_back(index < 0 ? static_cast<std::int64_t>(scan.vertices) + index : index - 1);
      }
      std::vector<std::int64_t> sorted = face;
      std::sort(sorted.begin(), sorted.end());
      // OpenMesh silently drops a face with fewer than 3 distinct vertices and shrinks one that
      // repeats a vertex (but not its texture coordinates).
      if (face.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
        if (degenerate++ == 0) first_degenerate_line = in.line_number();
      }
      ++scan.faces;
      scan.corners += face.size();
    } else if (keyword == "mtllib" && scan.material_library.empty()) {
      const std::string_view name = trim(rest);
      if (!name.empty()) scan.material_library = path.parent_path() / std::string(name);
    }
  }
  if (degenerate > 0) {
    throw_invalid(file, "mesh has " + counted(degenerate, "degenerate face", "degenerate faces") +
                            " (a vertex repeated or fewer than 3 vertices), first at line " +
                            std::to_string(first_degenerate_line));
  }
  check_some_faces(file, scan);
  check_counts(file, scan.vertices, scan.faces, options);
  return scan;
}

// -- OFF

// The next line with content, without its comment ('#' to the end of the line). OpenMesh's OFF
// reader would misread comments as data, so a file that has any is handed to it without them
// (`Prescan::off_comments`).
bool next_off_line(FileScanner& in, std::string_view& line, bool& comments) {
  while (in.next_line(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) {
      comments = true;
      line = line.substr(0, hash);
    }
    line = trim(line);
    if (!line.empty()) return true;
  }
  return false;
}

Prescan prescan_off(FileScanner& in, const std::string& file, const LoadOptions& options) {
  Prescan scan;
  scan.format = Format::off;
  std::string_view line;
  // Comment and blank lines may come before the keyword (CGAL writes a block of them).
  while (in.next_line(line)) {
    const std::string_view content = trim(line);
    if (!content.empty() && content.front() != '#') break;
    scan.off_comments = scan.off_comments || !content.empty();
    line = {};
  }
  const std::string first_line = at_line(in.line_number());
  if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
    scan.off_comments = true;
    line = line.substr(0, hash);
    while (!line.empty() && is_space(line.back())) line.remove_suffix(1);
  }
  std::string_view rest = line;
  const std::string_view keyword = next_token(rest);
  // OpenMesh checks the first line for [ST][C][N][4][n]OFF[ BINARY].
  std::size_t prefix = 0;
  const bool texcoords = keyword.substr(0, 2) == "ST";
  if (texcoords) prefix += 2;
  const bool colors = keyword.substr(prefix, 1) == "C";
  if (colors) ++prefix;
  const bool normals = keyword.substr(prefix, 1) == "N";
  if (normals) ++prefix;
  if (keyword.substr(prefix, 1) == "4" || keyword.substr(prefix, 1) == "n") {
    throw_invalid(file, first_line + "only 3-dimensional OFF is supported, got " + in_quotes(keyword));
  }
  if (line.empty() || is_space(line.front()) || keyword.substr(prefix) != "OFF") {
    throw_invalid(file,
                  first_line + "expected 'OFF' (optionally prefixed by ST, C, N) at the start of "
                  "the first line, got " +
                      in_quotes(line));
  }
  const std::string_view after = next_token(rest);
  const bool binary = after == "BINARY";
  if (binary && (line.substr(keyword.size(), 7) != " BINARY" || !trim(rest).empty())) {
    throw_invalid(file, first_line + "write the binary OFF header exactly as '" + std::string(keyword) +
                            " BINARY'");
  }
  if (!after.empty() && !binary) {
    throw_invalid(file, first_line + "unexpected " + in_quotes(after) +
                            " after 'OFF' (OpenMesh's reader expects the counts on the next line)");
  }

  if (binary) {
    if (prefix != 0) {
      throw_invalid(file, "binary OFF with ST, C or N prefixes is not supported");
    }
    if (scan.off_comments) {
      throw_invalid(file, "comments before a binary OFF header are not supported");
    }
    unsigned char header[12];
    if (!in.read_bytes(header, sizeof header)) {
      throw_invalid(file, "truncated: the binary OFF file ends inside its counts");
    }
    const auto vertices = static_cast<std::uint64_t>(decode_integer(header, 4, false, false));
    const auto faces = static_cast<std::uint64_t>(decode_integer(header + 4, 4, false, false));
    scan.vertices = vertices;
    scan.faces = faces;
    check_some_faces(file, scan);
    check_room(file, declared(vertices, faces),
               add_saturating(multiply_saturating(vertices, 12), multiply_saturating(faces, 16)),
               in.remaining());
    check_counts(file, vertices, faces, options);
    in.skip(vertices * 12);
    for (std::uint64_t face = 0; face < faces; ++face) {
      unsigned char count_bytes[4];
      std::uint64_t count = 0;
      bool complete = in.read_bytes(count_bytes, 4);
      if (complete) {
        count = static_cast<std::uint64_t>(decode_integer(count_bytes, 4, false, false));
        complete = in.skip(count * 4);
      }
      if (!complete) {
        throw_invalid(file, "truncated: the header declares " + declared(vertices, faces) +
                                ", but the data ends in face " + std::to_string(face));
      }
      scan.corners += count;
    }
    return scan;
  }

  if (!next_off_line(in, line, scan.off_comments)) {
    throw_invalid(file, "truncated: expected the counts line (vertices faces edges) after 'OFF'");
  }
  std::int64_t counts[3] = {0, 0, 0};
  {
    std::string_view tokens = line;
    for (std::int64_t& count : counts) {
      if (!parse_integer(next_token(tokens), count) || count < 0) {
        throw_invalid(file, at_line(in.line_number()) +
                                "expected 3 counts (vertices faces edges), got " + in_quotes(line));
      }
    }
    if (!trim(tokens).empty()) {
      throw_invalid(file, at_line(in.line_number()) +
                              "expected exactly 3 counts (vertices faces edges), got " +
                              in_quotes(line));
    }
  }
  const auto vertices = static_cast<std::uint64_t>(counts[0]);
  const auto faces = static_cast<std::uint64_t>(counts[1]);
  scan.vertices = vertices;
  scan.faces = faces;
  check_some_faces(file, scan);
  // Shortest records: "0 0 0\n" and "3 0 1 2\n".
  check_room(file, declared(vertices, faces),
             add_saturating(multiply_saturating(vertices, 6), multiply_saturating(faces, 8)),
             in.remaining());
  check_counts(file, vertices, faces, options);

  for (std::uint64_t vertex = 0; vertex < vertices; ++vertex) {
    if (!next_off_line(in, line, scan.off_comments)) {
      throw_invalid(file, "truncated: the header declares " + declared(vertices, faces) +
                              ", but the file ends after " +
                              counted(vertex, "vertex line", "vertex lines"));
    }
    std::string_view tokens = line;
    for (int value = 0; value < (normals ? 6 : 3); ++value) {
      const std::string_view token = next_token(tokens);
      const NumberKind kind = classify_float(token);
      if (kind == NumberKind::non_finite) {
        throw_invalid(file, at_line(in.line_number()) + "vertex " + std::to_string(vertex) +
                                " has a non-finite " + (value < 3 ? "coordinate " : "normal ") +
                                in_quotes(token) + " (NaN, infinite or beyond single precision)");
      }
      if (kind == NumberKind::invalid) {
        throw_invalid(file, at_line(in.line_number()) + "expected " +
                                (normals ? "6 numbers (position, normal)" : "3 coordinates") +
                                " for vertex " + std::to_string(vertex) + ", got " +
                                in_quotes(line));
      }
    }
  }
  for (std::uint64_t face = 0; face < faces; ++face) {
    if (!next_off_line(in, line, scan.off_comments)) {
      throw_invalid(file, "truncated: the header declares " + declared(vertices, faces) +
                              ", but the file ends after " +
                              counted(face, "face line", "face lines"));
    }
    std::string_view tokens = line;
    std::int64_t count = 0;
    const std::string_view count_token = next_token(tokens);
    if (!parse_integer(count_token, count) || count < 0) {
      throw_invalid(file, at_line(in.line_number()) + "expected the vertex count of face " +
                              std::to_string(face) + ", got " + in_quotes(count_token));
    }
    for (std::int64_t corner = 0; corner < count; ++corner) {
      std::int64_t index = 0;
      const std::string_view token = next_token(tokens);
      if (token.empty()) {
        throw_invalid(file, at_line(in.line_number()) + "face " + std::to_string(face) +
                                " declares " + std::to_string(count) + " vertices but lists " +
                                std::to_string(corner));
      }
      if (!parse_integer(token, index)) {
        throw_invalid(file, at_line(in.line_number()) + "expected a vertex index in face " +
                                std::to_string(face) + ", got " + in_quotes(token));
      }
    }
    // Without the C prefix OpenMesh reads faces token by token, so trailing values (colors)
    // would be taken for the next face.
    // They are dropped before OpenMesh reads the file (`Prescan::off_face_extras`).
    if (!colors && !trim(tokens).empty()) ++scan.off_face_extras;
    scan.corners += static_cast<std::uint64_t>(count);
  }
  if (next_off_line(in, line, scan.off_comments)) {
    throw_invalid(file, "the header declares " + declared(vertices, faces) +
                            ", but more data follows at line " + std::to_string(in.line_number()) +
                            " (wrong counts?)");
  }
  return scan;
}

// -- PLY

struct PlyType {
  std::string_view name;
  int bytes;
  bool is_float;
  bool is_signed;
};

constexpr PlyType kPlyTypes[] = {
    {"char", 1, false, true},    {"int8", 1, false, true},    {"uchar", 1, false, false},
    {"uint8", 1, false, false},  {"short", 2, false, true},   {"int16", 2, false, true},
    {"ushort", 2, false, false}, {"uint16", 2, false, false}, {"int", 4, false, true},
    {"int32", 4, false, true},   {"uint", 4, false, false},   {"uint32", 4, false, false},
    {"float", 4, true, true},    {"float32", 4, true, true},  {"double", 8, true, true},
    {"float64", 8, true, true},
};

const PlyType* find_ply_type(std::string_view name) {
  for (const PlyType& type : kPlyTypes) {
    if (type.name == name) return &type;
  }
  return nullptr;
}

// How OpenMesh's ascii PLY reader consumes a value: as a float, as an int, or as a string.
enum class PlyReading { as_float, as_integer, as_token };

struct PlyProperty {
  std::string name;
  const PlyType* type = nullptr;  // the list entries' type for a list
  const PlyType* count_type = nullptr;
  bool is_list = false;
  bool is_vertex_indices = false;
  bool is_coordinate = false;
  PlyReading reading = PlyReading::as_token;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

bool is_one_of(std::string_view name, std::initializer_list<std::string_view> names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

Prescan prescan_ply(FileScanner& in, const std::string& file, const LoadOptions& options) {
  Prescan scan;
  scan.format = Format::ply;
  // The header's bytes as read, to find where OpenMesh's reader will look for binary data.
  std::string header_bytes;
  std::size_t openmesh_position = 0;  // where OpenMesh's `tellg` is before it reads a keyword
  std::vector<PlyElement> elements;
  std::string format;
  bool big_endian = false;
  bool ended = false;
  std::string_view line;
  while (!ended && in.next_line(line)) {
    const std::uint64_t number = in.line_number();
    if (number > kMaxPlyHeaderLines) {
      throw_invalid(file, "the PLY header has no end_header in its first " +
                              std::to_string(kMaxPlyHeaderLines) + " lines");
    }
    const std::size_t line_start = header_bytes.size();
    header_bytes.append(line);
    if (in.last_line_had_carriage_return()) header_bytes.push_back('\r');
    header_bytes.push_back('\n');
    const std::string_view content = trim(line);
    const std::size_t content_end =
        line_start + static_cast<std::size_t>(content.data() + content.size() - line.data());
    std::string_view rest = content;
    const std::string_view keyword = next_token(rest);
    std::vector<std::string_view> tokens;
    for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
      tokens.push_back(token);
    }
    const std::string where = at_line(number);

    if (number == 1) {
      if (content != "ply" && content != "PLY") {
        throw_invalid(file, "line 1: not a PLY file (the first line must be 'ply')");
      }
      continue;
    }
    if (number == 2) {
      // OpenMesh reads the second line as the format whatever it says.
      if (keyword != "format" || tokens.size() != 2) {
        throw_invalid(file, where +
                                "expected 'format <ascii|binary_little_endian|"
                                "binary_big_endian> 1.0' on the second line, got " +
                                in_quotes(content));
      }
      format = std::string(tokens[0]);
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") {
        throw_invalid(file, where + "unsupported PLY format " + in_quotes(format));
      }
      big_endian = format == "binary_big_endian";
      openmesh_position = content_end;
      continue;
    }
    if (keyword == "comment") {
      if (!tokens.empty() && equals_ignoring_case(tokens[0], "TextureFile") &&
          scan.ply_texture.empty()) {
        std::string_view name = content;
        next_token(name);
        next_token(name);
        scan.ply_texture = std::string(trim(name));
      }
      // OpenMesh skips the rest of a comment line with getline, newline included.
      openmesh_position = header_bytes.size();
      continue;
    }
    if (keyword == "end_header") {
      if (!tokens.empty()) throw_invalid(file, where + "unexpected text after end_header");
      ended = true;
      if (format != "ascii") {
        // OpenMesh seeks to 12 (or 14 after "\r\n") bytes past its stream position before the
        // end_header keyword, which is right only when "\nend_header\n" directly follows the
        // last token of the header.
        const bool crlf = openmesh_position + 1 < header_bytes.size() &&
                          header_bytes[openmesh_position] == '\r' &&
                          header_bytes[openmesh_position + 1] == '\n';
        const std::size_t openmesh_data = openmesh_position + (crlf ? 14 : 12);
        if (openmesh_data != header_bytes.size()) {
          throw_invalid(file, where +
                                  "OpenMesh's reader would misplace the binary data: remove the "
                                  "comment, blank line or spaces directly before end_header, and "
                                  "any spaces around it");
        }
      }
      break;
    }
    openmesh_position = content_end;
    if (keyword == "obj_info") continue;
    if (keyword == "element") {
      std::int64_t count = 0;
      if (tokens.size() != 2 || !parse_integer(tokens[1], count) || count < 0) {
        throw_invalid(file, where + "expected 'element <name> <count>', got " + in_quotes(content));
      }
      if (static_cast<std::uint64_t>(count) > UINT32_MAX) {
        throw_invalid(file, where + "element " + in_quotes(tokens[0]) + " declares " +
                                std::to_string(count) +
                                " records, more than OpenMesh's PLY reader can count");
      }
      elements.push_back({std::string(tokens[0]), static_cast<std::uint64_t>(count), {}});
      continue;
    }
    if (keyword == "property") {
      if (elements.empty()) throw_invalid(file, where + "property before any element");
      PlyElement& element = elements.back();
      PlyProperty property;
      if (!tokens.empty() && tokens[0] == "list") {
        if (tokens.size() != 4) {
          throw_invalid(file, where + "expected 'property list <count type> <entry type> <name>'");
        }
        property.is_list = true;
        property.name = std::string(tokens[3]);
        property.count_type = find_ply_type(tokens[1]);
        property.type = find_ply_type(tokens[2]);
        if (property.count_type == nullptr || property.type == nullptr) {
          throw_invalid(file, where + "unknown type in " + in_quotes(content));
        }
        if (!is_one_of(tokens[1], {"uchar", "uint8", "uint16", "int"})) {
          throw_invalid(file, where + "list count type " + in_quotes(tokens[1]) +
                                  " is not supported by OpenMesh's PLY reader (use uchar, "
                                  "uint8, uint16 or int)");
        }
        property.is_vertex_indices =
            element.name == "face" && is_one_of(property.name, {"vertex_indices", "vertex_index"});
        if (!property.is_vertex_indices) {
          throw_invalid(file, where + "list property " + in_quotes(property.name) + " of element " +
                                  in_quotes(element.name) +
                                  " is not supported (OpenMesh's PLY reader can only read the "
                                  "face's vertex_indices list)");
        }
        if (property.type->is_float) {
          throw_invalid(file, where + "vertex indices must have an integer type, got " +
                                  in_quotes(tokens[2]));
        }
        property.reading = PlyReading::as_integer;
      } else {
        if (tokens.size() != 2) {
          throw_invalid(file,
                        where + "expected 'property <type> <name>', got " + in_quotes(content));
        }
        property.name = std::string(tokens[1]);
        property.type = find_ply_type(tokens[0]);
        if (property.type == nullptr) {
          throw_invalid(file, where + "unknown property type " + in_quotes(tokens[0]));
        }
        const bool is_vertex = element.name == "vertex";
        const bool is_face = element.name == "face";
        property.is_coordinate = is_vertex && is_one_of(property.name, {"x", "y", "z"});
        const bool read_as_float =
            is_vertex &&
            is_one_of(property.name, {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t"});
        const bool is_color =
            (is_vertex && is_one_of(property.name, {"red", "green", "blue", "alpha", "diffuse_red",
                                                    "diffuse_green", "diffuse_blue"})) ||
            (is_face && is_one_of(property.name, {"red", "green", "blue", "alpha"}));
        const bool single_float = property.type->is_float && property.type->bytes == 4;
        if (read_as_float) {
          property.reading = PlyReading::as_float;
          if (format != "ascii" && !property.type->is_float) {
            throw_invalid(file, where + "property " + in_quotes(property.name) + " has type " +
                                    in_quotes(tokens[0]) +
                                    "; OpenMesh's binary PLY reader needs float or double");
          }
        } else if (is_color) {
          property.reading = single_float ? PlyReading::as_float : PlyReading::as_integer;
          if (property.type->is_float && !single_float) {
            throw_invalid(file, where + "color property " + in_quotes(property.name) +
                                    " of type double is not supported by OpenMesh's PLY reader");
          }
        }
      }
      element.properties.push_back(std::move(property));
      continue;
    }
    throw_invalid(file, where + "unknown PLY header keyword " + in_quotes(keyword));
  }
  if (!ended) {
    throw_invalid(file, "truncated: the PLY header has no end_header");
  }

  // Which elements OpenMesh reads: all up to and including the face element.
  std::size_t face_element = elements.size();
  const PlyElement* vertex_element = nullptr;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (elements[i].name == "vertex" && vertex_element == nullptr) vertex_element = &elements[i];
    if (elements[i].name == "face" && face_element == elements.size()) face_element = i;
  }
  if (vertex_element == nullptr) throw_invalid(file, "the PLY header has no vertex element");
  for (std::string_view axis : {"x", "y", "z"}) {
    const auto& properties = vertex_element->properties;
    if (std::count_if(properties.begin(), properties.end(),
                      [&](const PlyProperty& p) { return p.name == axis; }) != 1) {
      throw_invalid(file, "the PLY vertex element needs exactly one property " + in_quotes(axis));
    }
  }
  scan.vertices = vertex_element->count;
  if (face_element < elements.size()) {
    const auto& properties = elements[face_element].properties;
    if (std::none_of(properties.begin(), properties.end(),
                     [](const PlyProperty& p) { return p.is_vertex_indices; })) {
      throw_invalid(file, "the PLY face element has no vertex_indices list");
    }
    scan.faces = elements[face_element].count;
  }
  check_some_faces(file, scan);

  const bool ascii = format == "ascii";
  const std::size_t read_elements = face_element + 1;
  std::uint64_t needed = 0;
  for (std::size_t i = 0; i < read_elements; ++i) {
    std::uint64_t record = 0;
    for (const PlyProperty& property : elements[i].properties) {
      // Shortest records: a one-character token and a separator per value; a face has 3 indices.
      const std::uint64_t entries = property.is_vertex_indices ? 3 : 0;
      if (ascii) {
        record += property.is_list ? 2 * (1 + entries) : 2;
      } else {
        record += property.is_list ? property.count_type->bytes + entries * property.type->bytes
                                   : property.type->bytes;
      }
    }
    needed = add_saturating(needed, multiply_saturating(record, elements[i].count));
  }
  check_room(file, declared(scan.vertices, scan.faces), needed, in.remaining());
  check_counts(file, scan.vertices, scan.faces, options);

  auto truncated = [&](const PlyElement& element, std::uint64_t record) {
    throw_invalid(file, "truncated: the header declares " + declared(scan.vertices, scan.faces) +
                            ", but the data ends in " + element.name + " " +
                            std::to_string(record) + " (of " + std::to_string(element.count) + ")");
  };

  if (!ascii) {
    for (std::size_t i = 0; i < read_elements; ++i) {
      const PlyElement& element = elements[i];
      const bool has_list = std::any_of(element.properties.begin(), element.properties.end(),
                                        [](const PlyProperty& p) { return p.is_list; });
      if (!has_list) {
        std::uint64_t record = 0;
        for (const PlyProperty& property : element.properties) record += property.type->bytes;
        const std::uint64_t available = in.remaining();
        if (!in.skip(multiply_saturating(record, element.count))) {
          truncated(element, record == 0 ? 0 : available / record);
        }
        continue;
      }
      for (std::uint64_t r = 0; r < element.count; ++r) {
        for (const PlyProperty& property : element.properties) {
          if (!property.is_list) {
            if (!in.skip(property.type->bytes)) truncated(element, r);
            continue;
          }
          unsigned char count_bytes[8];
          if (!in.read_bytes(count_bytes, property.count_type->bytes)) truncated(element, r);
          const std::int64_t count = decode_integer(count_bytes, property.count_type->bytes,
                                                    property.count_type->is_signed, big_endian);
          if (count < 0) {
            throw_invalid(file, element.name + " " + std::to_string(r) + " has a negative " +
                                    property.name + " count (" + std::to_string(count) + ")");
          }
          if (!in.skip(
                  multiply_saturating(static_cast<std::uint64_t>(count), property.type->bytes))) {
            truncated(element, r);
          }
          if (property.is_vertex_indices) scan.corners += static_cast<std::uint64_t>(count);
        }
      }
    }
    return scan;
  }

  TokenReader tokens(in);
  std::string_view token;
  auto check_value = [&](const PlyElement& element, std::uint64_t r, const PlyProperty& property,
                         std::string_view value) {
    if (property.reading == PlyReading::as_float) {
      const NumberKind kind = classify_float(value);
      if (kind == NumberKind::non_finite) {
        throw_invalid(
            file, at_line(tokens.line()) + element.name + " " + std::to_string(r) +
                      " has a non-finite " +
                      (property.is_coordinate ? "coordinate " : "value of " + property.name + " ") +
                      in_quotes(value) + " (NaN, infinite or beyond single precision)");
      }
      if (kind == NumberKind::invalid) {
        throw_invalid(file, at_line(tokens.line()) + "expected a number for " + property.name +
                                " of " + element.name + " " + std::to_string(r) + ", got " +
                                in_quotes(value));
      }
    } else if (property.reading == PlyReading::as_integer) {
      std::int64_t integer = 0;
      if (!parse_integer(value, integer)) {
        throw_invalid(file, at_line(tokens.line()) + "expected an integer for " + property.name +
                                " of " + element.name + " " + std::to_string(r) + ", got " +
                                in_quotes(value));
      }
    }
  };
  for (std::size_t i = 0; i < read_elements; ++i) {
    const PlyElement& element = elements[i];
    for (std::uint64_t r = 0; r < element.count; ++r) {
      for (const PlyProperty& property : element.properties) {
        if (!tokens.next(token)) truncated(element, r);
        if (!property.is_list) {
          check_value(element, r, property, token);
          continue;
        }
        std::int64_t count = 0;
        if (!parse_integer(token, count) || count < 0) {
          throw_invalid(file, at_line(tokens.line()) + "expected the length of list " +
                                  property.name + " of " + element.name + " " + std::to_string(r) +
                                  ", got " + in_quotes(token));
        }
        for (std::int64_t entry = 0; entry < count; ++entry) {
          if (!tokens.next(token)) truncated(element, r);
          check_value(element, r, property, token);
        }
        if (property.is_vertex_indices) scan.corners += static_cast<std::uint64_t>(count);
      }
    }
  }
  if (read_elements == elements.size() && tokens.next(token)) {
    throw_invalid(file, "the header declares " + declared(scan.vertices, scan.faces) +
                            ", but more data follows at line " + std::to_string(tokens.line()) +
                            " (wrong counts?)");
  }
  return scan;
}

// -- STL

std::string degenerate_triangles_message(std::uint64_t count, std::uint64_t first) {
  return "mesh has " + counted(count, "degenerate face", "degenerate faces") +
         " (two corners of a triangle coincide), first triangle " + std::to_string(first);
}

Prescan prescan_stl(FileScanner& in, const std::string& file, const LoadOptions& options) {
  Prescan scan;
  scan.format = Format::stl;
  const std::uint64_t size = in.size();
  std::uint64_t declared_triangles = 0;
  if (size >= 84) {
    unsigned char header[84] = {};
    in.read_bytes(header, sizeof header);  // size >= 84
    declared_triangles = static_cast<std::uint64_t>(decode_integer(header + 80, 4, false, false));
  }
  std::uint64_t degenerate = 0;
  std::uint64_t first_degenerate = 0;
  // OpenMesh's test: binary exactly when the size matches, whatever the header says.
  if (size >= 84 && 84 + 50 * declared_triangles == size) {
    scan.faces = declared_triangles;
    check_some_faces(file, scan);
    check_counts(file, 0, scan.faces, options);
    unsigned char record[50] = {};
    for (std::uint64_t t = 0; t < declared_triangles; ++t) {
      if (!in.read_bytes(record, sizeof record)) {
        throw_io(file, "the file shrank while being read");
      }
      std::array<std::array<float, 3>, 3> corners{};
      for (int c = 0; c < 3; ++c) {
        for (int axis = 0; axis < 3; ++axis) {
          corners[c][axis] = decode_float_little_endian(record + 12 + 12 * c + 4 * axis);
          if (!std::isfinite(corners[c][axis])) {
            throw_invalid(file, "triangle " + std::to_string(t) +
                                    " has a non-finite coordinate (NaN or infinite)");
          }
        }
      }
      if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) {
        if (degenerate++ == 0) first_degenerate = t;
      }
    }
    if (degenerate > 0)
      throw_invalid(file, degenerate_triangles_message(degenerate, first_degenerate));
    scan.vertices = 3 * scan.faces;
    scan.corners = 3 * scan.faces;
    return scan;
  }

  in.seek(0);
  const std::string binary_hint =
      size >= 84 ? " (if this is meant as a binary STL: its header declares " +
                       counted(declared_triangles, "triangle", "triangles") + ", which need " +
                       std::to_string(84 + 50 * declared_triangles) + " bytes, but the file has " +
                       std::to_string(size) + ")"
                 : std::string();
  std::string_view line;
  while (in.next_line(line) && trim(line).empty()) {
  }
  if (!starts_with_ignoring_case(trim(line), "solid")) {
    throw_invalid(file, "not an STL file: it does not start with 'solid' and is not a binary STL" +
                            binary_hint);
  }
  try {
    bool facet_open = false;
    bool solid_ended = false;
    while (in.next_line(line)) {
      const std::string_view content = trim(line);
      // OpenMesh takes any line containing "outer" as the start of a triangle and the next three
      // lines as its corners.
      if (content.find("outer") != std::string_view::npos ||
          content.find("OUTER") != std::string_view::npos) {
        std::array<std::array<float, 3>, 3> corners{};
        for (auto& corner : corners) {
          if (!in.next_line(line)) {
            throw_invalid(file,
                          "truncated: the file ends inside triangle " + std::to_string(scan.faces));
          }
          std::string_view rest = trim(line);
          if (!equals_ignoring_case(next_token(rest), "vertex")) {
            throw_invalid(file, at_line(in.line_number()) + "expected 'vertex x y z' in triangle " +
                                    std::to_string(scan.faces) + ", got " + in_quotes(trim(line)));
          }
          for (float& value : corner) {
            const std::string_view token = next_token(rest);
            const NumberKind kind = classify_float(token, &value);
            if (kind == NumberKind::non_finite) {
              throw_invalid(file, at_line(in.line_number()) + "triangle " +
                                      std::to_string(scan.faces) + " has a non-finite coordinate " +
                                      in_quotes(token) +
                                      " (NaN, infinite or beyond single precision)");
            }
            if (kind == NumberKind::invalid) {
              throw_invalid(file, at_line(in.line_number()) +
                                      "expected 3 coordinates after 'vertex', got " +
                                      in_quotes(trim(line)));
            }
          }
        }
        if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) {
          if (degenerate++ == 0) first_degenerate = scan.faces;
        }
        if (++scan.faces > options.max_faces) check_counts(file, 0, scan.faces, options);
      } else if (starts_with_ignoring_case(content, "endsolid")) {
        solid_ended = true;
      } else if (starts_with_ignoring_case(content, "solid")) {
        solid_ended = false;
      } else if (starts_with_ignoring_case(content, "endfacet")) {
        facet_open = false;
      } else if (starts_with_ignoring_case(content, "facet")) {
        facet_open = true;
      }
    }
    if (facet_open) {
      throw_invalid(file, "truncated: the file ends inside triangle " +
                              std::to_string(scan.faces > 0 ? scan.faces - 1 : 0) +
                              " (expected 'endfacet')");
    }
    if (!solid_ended) {
      throw_invalid(file, "truncated: expected 'endsolid' after triangle " +
                              std::to_string(scan.faces > 0 ? scan.faces - 1 : 0));
    }
  } catch (const InvalidInputException& error) {
    throw InvalidInputException(error.what() + binary_hint);
  }
  check_some_faces(file, scan);
  if (degenerate > 0)
    throw_invalid(file, degenerate_triangles_message(degenerate, first_degenerate));
  scan.vertices = 3 * scan.faces;
  scan.corners = 3 * scan.faces;
  return scan;
}

// ---------------------------------------------------------------------------------------------
// OpenMesh's reader into a recording importer.

struct RawMesh {
  std::vector<Vec3d> positions;
  std::vector<std::size_t> face_start{0};  // face f has corners [face_start[f], face_start[f+1])
  std::vector<int> corners;
  // Per-corner texture coordinates, parallel to `corners` once any face had them.
  std::vector<Vec2d> corner_uv;
  std::vector<char> face_has_uv;
  // Per-vertex texture coordinates, once any vertex had them.
  std::vector<Vec2d> vertex_uv;
  std::vector<char> vertex_has_uv;
  std::map<int, std::string> textures;  // OBJ texture id -> map_Kd
  std::map<int, std::size_t> faces_per_texture;

  std::size_t n_faces() const { return face_start.size() - 1; }
};

// Records what OpenMesh's reader finds: fake handles are raw indices, nothing is validated or
// dropped, header counts given to reserve() are ignored (they are not trusted).
class RecordingImporter final : public OpenMesh::IO::BaseImporter {
 public:
  explicit RecordingImporter(RawMesh& raw) : raw_(raw) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& point) override {
    return push_vertex(Vec3d(point[0], point[1], point[2]));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& point) override {
    return push_vertex(point);
  }
  OpenMesh::VertexHandle add_vertex() override { return push_vertex(Vec3d(0.0, 0.0, 0.0)); }
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    return OpenMesh::HalfedgeHandle();  // only the OM format builds halfedges directly
  }
  OpenMesh::FaceHandle add_face(const VHandles& indices) override {
    for (const OpenMesh::VertexHandle& vertex : indices) raw_.corners.push_back(vertex.idx());
    raw_.face_start.push_back(raw_.corners.size());
    return OpenMesh::FaceHandle(static_cast<int>(raw_.n_faces() - 1));
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
    return OpenMesh::FaceHandle();
  }
  void add_face_texcoords(OpenMesh::FaceHandle face, OpenMesh::VertexHandle first,
                          const std::vector<OpenMesh::Vec2f>& texcoords) override {
    if (face.idx() < 0 || static_cast<std::size_t>(face.idx()) >= raw_.n_faces()) return;
    const std::size_t begin = raw_.face_start[face.idx()];
    const std::size_t size = raw_.face_start[face.idx() + 1] - begin;
    if (texcoords.size() != size || size == 0) return;
    std::size_t offset = 0;
    while (offset < size && raw_.corners[begin + offset] != first.idx()) ++offset;
    if (offset == size) return;
    raw_.corner_uv.resize(raw_.corners.size());
    raw_.face_has_uv.resize(raw_.n_faces(), 0);
    for (std::size_t i = 0; i < size; ++i) {
      const OpenMesh::Vec2f& uv = texcoords[i];
      raw_.corner_uv[begin + (offset + i) % size] = Vec2d(uv[0], uv[1]);
    }
    raw_.face_has_uv[face.idx()] = 1;
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int texture) override {
    if (texture > 0) ++raw_.faces_per_texture[texture];
  }
  void set_point(OpenMesh::VertexHandle vertex, const OpenMesh::Vec3f& point) override {
    if (vertex.idx() >= 0 && static_cast<std::size_t>(vertex.idx()) < raw_.positions.size()) {
      raw_.positions[vertex.idx()] = Vec3d(point[0], point[1], point[2]);
    }
  }
  void set_texcoord(OpenMesh::VertexHandle vertex, const OpenMesh::Vec2f& uv) override {
    if (vertex.idx() < 0 || static_cast<std::size_t>(vertex.idx()) >= raw_.positions.size()) return;
    if (raw_.vertex_uv.size() < raw_.positions.size()) {
      raw_.vertex_uv.resize(raw_.positions.size());
      raw_.vertex_has_uv.resize(raw_.positions.size(), 0);
    }
    raw_.vertex_uv[vertex.idx()] = Vec2d(uv[0], uv[1]);
    raw_.vertex_has_uv[vertex.idx()] = 1;
  }
  void add_texture_information(int id, std::string name) override {
    raw_.textures[id] = std::move(name);
  }
  size_t n_vertices() const override { return raw_.positions.size(); }
  size_t n_faces() const override { return raw_.n_faces(); }
  size_t n_edges() const override { return 0; }

  // Normals, colors, status bits, halfedge links and 3D texture coordinates are not needed.
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void reserve(unsigned int, unsigned int, unsigned int) override {}

 private:
  OpenMesh::VertexHandle push_vertex(const Vec3d& point) {
    raw_.positions.push_back(point);
    return OpenMesh::VertexHandle(static_cast<int>(raw_.positions.size() - 1));
  }

  RawMesh& raw_;
};

// An ascii OFF as OpenMesh's reader can take it: no comments, no blank lines, and faces without
// values after their indices (the pre-scan has checked the rest).
std::string clean_off(const std::filesystem::path& path, const std::string& file,
                      const Prescan& scan) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_io(file, "cannot open the file");
  std::string out;
  std::string line;
  std::uint64_t content_lines = 0;
  const std::uint64_t first_face = 2 + scan.vertices;
  while (std::getline(in, line)) {
    std::string_view content = line;
    const std::size_t hash = content.find('#');
    if (hash != std::string_view::npos) content = content.substr(0, hash);
    content = trim(content);
    if (content.empty()) continue;
    if (content_lines >= first_face && scan.off_face_extras > 0) {
      std::string_view tokens = content;
      std::int64_t count = 0;
      parse_integer(next_token(tokens), count);
      for (std::int64_t corner = 0; corner < count; ++corner) next_token(tokens);
      content = content.substr(0, content.size() - tokens.size());
    }
    out.append(content);
    out.push_back('\n');
    ++content_lines;
  }
  return out;
}

RawMesh read_with_openmesh(const std::filesystem::path& path, const std::string& file,
                           const Prescan& scan) {
  RawMesh raw;
  RecordingImporter importer(raw);
  OpenMesh::IO::Options options;
  options += OpenMesh::IO::Options::VertexTexCoord;
  options += OpenMesh::IO::Options::FaceTexCoord;
  // OpenMesh's stream reader skips the header check that sets the OFF reader's options, so a
  // cleaned OFF goes through a temporary file.
  std::filesystem::path source = path;
  struct RemoveOnExit {
    std::filesystem::path path;
    ~RemoveOnExit() {
      std::error_code ignored;
      if (!path.empty()) std::filesystem::remove(path, ignored);
    }
  } cleaned;
  if (scan.format == Format::off && (scan.off_comments || scan.off_face_extras > 0)) {
    static std::atomic<std::uint64_t> counter{0};
    cleaned.path = std::filesystem::temp_directory_path() /
                   ("papercraft-clean-" + std::to_string(::getpid()) + "-" +
                    std::to_string(counter.fetch_add(1)) + ".off");
    std::ofstream out(cleaned.path, std::ios::binary);
    out << clean_off(path, file, scan);
    if (!out.flush()) throw_io(file, "cannot write a cleaned copy to " + cleaned.path.string());
    source = cleaned.path;
  }
  // The reader modules are process-wide singletons that keep per-file state in members.
  static std::mutex reader_mutex;
  bool ok = false;
  {
    std::lock_guard<std::mutex> lock(reader_mutex);
    ok = OpenMesh::IO::IOManager().read(source.string(), importer, options);
  }
  if (!ok) throw_io(file, "OpenMesh's reader failed on the file");
  return raw;
}

// ---------------------------------------------------------------------------------------------
// Validation, repairs and the Mesh.

struct Soup {
  std::vector<Vec3d> positions;
  std::vector<int> source_vertex;  // index in the file's vertex list
  std::vector<Triangle3> triangles;
  std::vector<int> source_face;                 // index in the file's face list
  std::vector<std::array<Vec2d, 3>> corner_uv;  // empty without UVs
};

void check_raw_faces(const RawMesh& raw, const std::string& file) {
  const std::size_t vertices = raw.positions.size();
  std::uint64_t non_finite = 0, short_faces = 0, out_of_range = 0, repeated = 0;
  std::size_t first_non_finite = 0, first_short = 0, first_out = 0, first_repeated = 0;
  std::int64_t first_bad_index = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    const Vec3d& p = raw.positions[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      if (non_finite++ == 0) first_non_finite = v;
    }
  }
  if (non_finite > 0) {
    const Vec3d& p = raw.positions[first_non_finite];
    throw_invalid(file, "mesh has " + counted(non_finite, "vertex", "vertices") +
                            " with non-finite coordinates (NaN or infinite), first vertex " +
                            std::to_string(first_non_finite) + " (" + std::to_string(p[0]) + ", " +
                            std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")");
  }
  for (std::size_t f = 0; f < raw.n_faces(); ++f) {
    const std::size_t begin = raw.face_start[f];
    const std::size_t end = raw.face_start[f + 1];
    if (end - begin < 3) {
      if (short_faces++ == 0) first_short = f;
      continue;
    }
    bool bad = false;
    for (std::size_t c = begin; c < end; ++c) {
      const int index = raw.corners[c];
      if (index < 0 || static_cast<std::size_t>(index) >= vertices) {
        if (!bad && out_of_range++ == 0) {
          first_out = f;
          first_bad_index = index;
        }
        bad = true;
      }
    }
    if (bad) continue;
    for (std::size_t c = begin; c < end && !bad; ++c) {
      for (std::size_t d = c + 1; d < end; ++d) {
        if (raw.corners[c] == raw.corners[d]) {
          if (repeated++ == 0) first_repeated = f;
          bad = true;
          break;
        }
      }
    }
  }
  if (short_faces > 0) {
    throw_invalid(
        file, "mesh has " + counted(short_faces, "face", "faces") +
                  " with fewer than 3 vertices (degenerate), first face " +
                  std::to_string(first_short) + " (" +
                  std::to_string(raw.face_start[first_short + 1] - raw.face_start[first_short]) +
                  " vertices)");
  }
  if (out_of_range > 0) {
    throw_invalid(file, "mesh has " + counted(out_of_range, "face", "faces") +
                            " with out-of-range vertex indices, first face " +
                            std::to_string(first_out) + " refers to vertex " +
                            std::to_string(first_bad_index) + " but there are " +
                            counted(vertices, "vertex", "vertices") + " (indices are 0-based)");
  }
  if (repeated > 0) {
    throw_invalid(file, "mesh has " + counted(repeated, "degenerate face", "degenerate faces") +
                            " (a vertex repeated), first face " + std::to_string(first_repeated));
  }
}

Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return OpenMesh::cross(a, b);
}

// Ear clipping of a polygon (indices into `points`, in order) in the plane orthogonal to its
// Newell normal; corner positions in the polygon go to `ears`. False when no ear is left to
// clip (a self-intersecting polygon).
bool ear_clip(const Vec3d* const* points, std::size_t size, const Vec3d& normal,
              std::vector<std::array<std::size_t, 3>>& ears) {
  // Drop the normal's dominant axis; flip so that the projected polygon runs counterclockwise.
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  }
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] < 0.0 ? -1.0 : 1.0;
  std::vector<std::array<double, 2>> p(size);
  for (std::size_t i = 0; i < size; ++i) p[i] = {(*points[i])[u], flip * (*points[i])[v]};
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
  };
  std::vector<std::size_t> ring(size);
  std::iota(ring.begin(), ring.end(), std::size_t{0});
  ears.clear();
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const std::size_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                        c = ring[(i + 1) % ring.size()];
      if (orient(a, b, c) <= 0.0) continue;  // reflex or flat corner
      bool empty = true;
      for (const std::size_t q : ring) {
        if (q == a || q == b || q == c) continue;
        if (orient(a, b, q) >= 0.0 && orient(b, c, q) >= 0.0 && orient(c, a, q) >= 0.0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      ears.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return false;
  }
  if (orient(ring[0], ring[1], ring[2]) <= 0.0) return false;
  ears.push_back({ring[0], ring[1], ring[2]});
  return true;
}

// Fan triangulation with texture coordinates; polygons a fan would fold over are ear-clipped,
// and refused when that fails too (self-intersecting).
Soup triangulate(RawMesh& raw, bool with_uvs, const LoadOptions& options, const std::string& file,
                 std::vector<std::string>& repairs) {
  Soup soup;
  soup.triangles.reserve(raw.corners.size() >= 2 * raw.n_faces()
                             ? raw.corners.size() - 2 * raw.n_faces()
                             : raw.n_faces());
  std::uint64_t polygons = 0, non_convex = 0, self_intersecting = 0;
  std::size_t first_self_intersecting = 0;
  std::vector<const Vec3d*> points;
  std::vector<std::array<std::size_t, 3>> ears;
  for (std::size_t f = 0; f < raw.n_faces(); ++f) {
    const std::size_t begin = raw.face_start[f];
    const std::size_t size = raw.face_start[f + 1] - begin;
    const int* corner = raw.corners.data() + begin;
    if (size > 3) {
      ++polygons;
      Vec3d normal(0.0, 0.0, 0.0);  // Newell's normal
      for (std::size_t i = 0; i < size; ++i) {
        normal += cross(raw.positions[corner[i]], raw.positions[corner[(i + 1) % size]]);
      }
      bool folds = false;
      for (std::size_t i = 1; i + 1 < size; ++i) {
        const Vec3d& origin = raw.positions[corner[0]];
        const Vec3d turn =
            cross(raw.positions[corner[i]] - origin, raw.positions[corner[i + 1]] - origin);
        if (OpenMesh::dot(turn, normal) < 0.0) folds = true;
      }
      if (folds) {
        ++non_convex;
        points.resize(size);
        for (std::size_t i = 0; i < size; ++i) points[i] = &raw.positions[corner[i]];
        if (!ear_clip(points.data(), size, normal, ears)) {
          if (self_intersecting++ == 0) first_self_intersecting = f;
          continue;
        }
        for (const auto& ear : ears) {
          soup.triangles.push_back({corner[ear[0]], corner[ear[1]], corner[ear[2]]});
          soup.source_face.push_back(static_cast<int>(f));
          if (with_uvs) {
            soup.corner_uv.push_back({raw.corner_uv[begin + ear[0]], raw.corner_uv[begin + ear[1]],
                                      raw.corner_uv[begin + ear[2]]});
          }
        }
        continue;
      }
    }
    for (std::size_t i = 1; i + 1 < size; ++i) {
      soup.triangles.push_back({corner[0], corner[i], corner[i + 1]});
      soup.source_face.push_back(static_cast<int>(f));
      if (with_uvs) {
        soup.corner_uv.push_back(
            {raw.corner_uv[begin], raw.corner_uv[begin + i], raw.corner_uv[begin + i + 1]});
      }
    }
  }
  if (self_intersecting > 0) {
    throw_invalid(file, "mesh has " +
                            counted(self_intersecting, "self-intersecting polygon",
                                    "self-intersecting polygons") +
                            " (no ear to clip), first face " +
                            std::to_string(first_self_intersecting) +
                            "; triangulate it before loading");
  }
  if (non_convex > 0) {
    repairs.push_back("ear-clipped " +
                      counted(non_convex, "non-convex polygon", "non-convex polygons"));
  }
  if (soup.triangles.size() > options.max_faces) {
    throw_invalid(file, "mesh has " + std::to_string(soup.triangles.size()) +
                            " triangles, more than the limit of " +
                            std::to_string(options.max_faces) + " (LoadOptions::max_faces)");
  }
  if (polygons > 0) {
    repairs.push_back(
        "triangulated " + counted(polygons, "polygon", "polygons") + " into " +
        counted(polygons + (soup.triangles.size() - raw.n_faces()), "triangle", "triangles"));
  }
  soup.positions = std::move(raw.positions);
  soup.source_vertex.resize(soup.positions.size());
  std::iota(soup.source_vertex.begin(), soup.source_vertex.end(), 0);
  return soup;
}

// Keeps the vertices with keep[v]; target[v] is the kept vertex that v becomes (target[v] <= v).
void compact_vertices(Soup& soup, const std::vector<int>& target) {
  std::vector<int> new_index(soup.positions.size(), -1);
  int next = 0;
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    if (target[v] == static_cast<int>(v)) {
      soup.positions[next] = soup.positions[v];
      soup.source_vertex[next] = soup.source_vertex[v];
      new_index[v] = next++;
    } else if (target[v] >= 0) {
      new_index[v] = new_index[target[v]];
    }
  }
  soup.positions.resize(next);
  soup.source_vertex.resize(next);
  for (Triangle3& t : soup.triangles) {
    for (int& v : t) v = new_index[v];
  }
}

std::size_t remove_unreferenced_vertices(Soup& soup) {
  std::vector<int> target(soup.positions.size(), -1);
  for (const Triangle3& t : soup.triangles) {
    for (int v : t) target[v] = v;
  }
  const auto removed = static_cast<std::size_t>(std::count(target.begin(), target.end(), -1));
  if (removed > 0) compact_vertices(soup, target);
  return removed;
}

std::size_t merge_duplicate_vertices(Soup& soup, double epsilon) {
  const std::size_t n = soup.positions.size();
  std::vector<int> target(n);
  std::iota(target.begin(), target.end(), 0);
  const std::vector<Vec3d>& p = soup.positions;
  if (epsilon <= 0.0) {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) {
      for (int axis = 0; axis < 3; ++axis) {
        if (p[a][axis] != p[b][axis]) return p[a][axis] < p[b][axis];
      }
      return a < b;
    });
    for (std::size_t i = 1; i < n; ++i) {
      if (p[order[i]] == p[order[i - 1]]) target[order[i]] = target[order[i - 1]];
    }
  } else {
    // Grid of cell size epsilon: a duplicate lies in one of the 27 cells around a vertex.
    auto cell = [&](double x) {
      return static_cast<std::int64_t>(std::clamp(std::floor(x / epsilon), -1e15, 1e15));
    };
    auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
      std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull;
      h ^= static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
      h ^= static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
      return h;
    };
    std::unordered_multimap<std::uint64_t, int> grid;
    grid.reserve(n);
    for (std::size_t v = 0; v < n; ++v) {
      const std::int64_t cx = cell(p[v][0]), cy = cell(p[v][1]), cz = cell(p[v][2]);
      int found = -1;
      for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx) {
        for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy) {
          for (std::int64_t dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto range = grid.equal_range(key(cx + dx, cy + dy, cz + dz));
            for (auto it = range.first; it != range.second; ++it) {
              const Vec3d d = p[it->second] - p[v];
              if (std::fabs(d[0]) <= epsilon && std::fabs(d[1]) <= epsilon &&
                  std::fabs(d[2]) <= epsilon && (found < 0 || it->second < found)) {
                found = it->second;
              }
            }
          }
        }
      }
      if (found >= 0) {
        target[v] = found;
      } else {
        grid.emplace(key(cx, cy, cz), static_cast<int>(v));
      }
    }
  }
  std::size_t merged = 0;
  for (std::size_t v = 0; v < n; ++v) merged += target[v] != static_cast<int>(v);
  if (merged > 0) compact_vertices(soup, target);
  return merged;
}

void check_degenerate_triangles(const Soup& soup, const LoadOptions& options,
                                const std::string& file) {
  std::uint64_t degenerate = 0;
  std::size_t first = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const Triangle3& tri = soup.triangles[t];
    bool bad = tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
    if (!bad) {
      const Vec3d& a = soup.positions[tri[0]];
      const Vec3d& b = soup.positions[tri[1]];
      const Vec3d& c = soup.positions[tri[2]];
      const double twice_area = cross(b - a, c - a).norm();
      const double longest = std::max({(b - a).sqrnorm(), (c - b).sqrnorm(), (a - c).sqrnorm()});
      bad = twice_area <= options.degenerate_area_ratio * longest;
    }
    if (bad && degenerate++ == 0) first = t;
  }
  if (degenerate > 0) {
    throw_invalid(
        file,
        "mesh has " +
            counted(degenerate, "degenerate (zero-area) face", "degenerate (zero-area) faces") +
            ", first face " + std::to_string(soup.source_face[first]) + " (vertices " +
            vertex_list(soup.source_vertex, soup.triangles[first]) + ")");
  }
}

void check_duplicate_triangles(const Soup& soup, const std::string& file) {
  struct Key {
    Triangle3 sorted;
    int triangle;
  };
  std::vector<Key> keys(soup.triangles.size());
  for (std::size_t t = 0; t < keys.size(); ++t) {
    keys[t].sorted = soup.triangles[t];
    std::sort(keys[t].sorted.begin(), keys[t].sorted.end());
    keys[t].triangle = static_cast<int>(t);
  }
  tbb::parallel_sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return a.sorted != b.sorted ? a.sorted < b.sorted : a.triangle < b.triangle;
  });
  std::uint64_t duplicates = 0;
  std::size_t first = 0;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (keys[i].sorted == keys[i - 1].sorted && duplicates++ == 0) first = i;
  }
  if (duplicates > 0) {
    const Key& original = keys[first - 1];
    const Key& copy = keys[first];
    throw_invalid(file, "mesh has " + counted(duplicates, "duplicate face", "duplicate faces") +
                            " (the same vertices as another face), first face " +
                            std::to_string(soup.source_face[copy.triangle]) + " repeats face " +
                            std::to_string(soup.source_face[original.triangle]) + " (vertices " +
                            vertex_list(soup.source_vertex, soup.triangles[copy.triangle]) + ")");
  }
}

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

int corner_of(const Triangle3& t, int vertex) {
  return t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2);
}

// Checks manifoldness; with `repair`, makes the orientation consistent and closed components face
// outwards. neighbor[3 t + k] is the triangle across edge k (t[k] -> t[k+1]) or -1.
void check_topology_and_orient(Soup& soup, bool repair, const std::string& file,
                               std::vector<std::string>& repairs) {
  const std::size_t triangles = soup.triangles.size();
  struct EdgeUse {
    std::uint64_t key;
    std::uint32_t slot;  // 3 * triangle + k
  };
  std::vector<EdgeUse> uses(3 * triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(soup.triangles[t][k]);
      const auto b = static_cast<std::uint32_t>(soup.triangles[t][(k + 1) % 3]);
      uses[3 * t + k] = {(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b),
                         static_cast<std::uint32_t>(3 * t + k)};
    }
  }
  tbb::parallel_sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.key != y.key ? x.key < y.key : x.slot < y.slot;
  });

  auto edge_vertices = [&](std::uint64_t key) {
    return std::to_string(soup.source_vertex[key >> 32]) + "-" +
           std::to_string(soup.source_vertex[key & 0xffffffffu]);
  };
  auto face_of_slot = [&](std::uint32_t slot) {
    return std::to_string(soup.source_face[slot / 3]);
  };
  std::vector<int> neighbor(3 * triangles, -1);
  UnionFind fans(3 * triangles);
  std::uint64_t non_manifold = 0, inconsistent = 0;
  std::size_t first_non_manifold = 0, first_inconsistent = 0;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i >= 3) {
      if (non_manifold++ == 0) first_non_manifold = i;
    } else if (j - i == 2) {
      const std::uint32_t s1 = uses[i].slot, s2 = uses[i + 1].slot;
      const std::uint32_t t1 = s1 / 3, t2 = s2 / 3;
      neighbor[s1] = static_cast<int>(t2);
      neighbor[s2] = static_cast<int>(t1);
      const Triangle3& a = soup.triangles[t1];
      const Triangle3& b = soup.triangles[t2];
      const int from = a[s1 % 3];
      const int to = a[(s1 % 3 + 1) % 3];
      if (b[s2 % 3] == from && inconsistent++ == 0) first_inconsistent = i;
      // The two faces are neighbours in the fans of both edge ends.
      fans.unite(s1 - s1 % 3 + corner_of(a, from), s2 - s2 % 3 + corner_of(b, from));
      fans.unite(s1 - s1 % 3 + corner_of(a, to), s2 - s2 % 3 + corner_of(b, to));
    }
    i = j;
  }
  if (non_manifold > 0) {
    std::string faces;
    for (std::size_t k = first_non_manifold;
         k < uses.size() && uses[k].key == uses[first_non_manifold].key; ++k) {
      faces += (faces.empty() ? "" : ", ") + face_of_slot(uses[k].slot);
    }
    throw_invalid(file, "mesh has " +
                            counted(non_manifold, "non-manifold edge", "non-manifold edges") +
                            " (shared by 3 or more faces), first at vertices " +
                            edge_vertices(uses[first_non_manifold].key) + " (faces " + faces + ")");
  }

  const std::size_t vertices = soup.positions.size();
  std::vector<std::int64_t> fan_of_vertex(vertices, -1);
  std::vector<char> bad_vertex(vertices, 0);
  for (std::size_t slot = 0; slot < 3 * triangles; ++slot) {
    const int v = soup.triangles[slot / 3][slot % 3];
    const std::uint32_t root = fans.find(static_cast<std::uint32_t>(slot));
    if (fan_of_vertex[v] < 0) {
      fan_of_vertex[v] = root;
    } else if (fan_of_vertex[v] != root) {
      bad_vertex[v] = 1;
    }
  }
  const auto non_manifold_vertices =
      static_cast<std::uint64_t>(std::count(bad_vertex.begin(), bad_vertex.end(), 1));
  if (non_manifold_vertices > 0 && repair) {
    // Every fan of a vertex after its first gets a copy of the vertex (same position, same
    // input vertex): the surface is unchanged and becomes manifold, pieces merely touch there.
    // A fan root is a slot, so it names one fan of one vertex.
    std::unordered_map<std::uint32_t, int> copy_of_fan;
    for (std::size_t slot = 0; slot < 3 * triangles; ++slot) {
      int& corner = soup.triangles[slot / 3][slot % 3];
      const int v = corner;
      if (!bad_vertex[v]) continue;
      const std::uint32_t root = fans.find(static_cast<std::uint32_t>(slot));
      if (fan_of_vertex[v] == root) continue;
      const auto [it, added] =
          copy_of_fan.try_emplace(root, static_cast<int>(soup.positions.size()));
      if (added) {
        soup.positions.push_back(soup.positions[v]);
        soup.source_vertex.push_back(soup.source_vertex[v]);
      }
      corner = it->second;
    }
    repairs.push_back("split " +
                      counted(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") +
                      " into one vertex per fan (" +
                      counted(copy_of_fan.size(), "copy", "copies") + " added)");
  } else if (non_manifold_vertices > 0) {
    int first = INT_MAX;
    for (std::size_t v = 0; v < vertices; ++v) {
      if (bad_vertex[v]) first = std::min(first, soup.source_vertex[v]);
    }
    throw_invalid(
        file, "mesh has " +
                  counted(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") +
                  " (their faces form more than one fan), first vertex " + std::to_string(first));
  }

  if (inconsistent > 0 && !repair) {
    throw_invalid(file, "mesh is not consistently oriented: " +
                            counted(inconsistent, "edge is", "edges are") +
                            " traversed in the same direction by both of its faces, first at "
                            "vertices " +
                            edge_vertices(uses[first_inconsistent].key) + " (faces " +
                            face_of_slot(uses[first_inconsistent].slot) + ", " +
                            face_of_slot(uses[first_inconsistent + 1].slot) + ")");
  }
  if (!repair) return;

  // Components through manifold edges; flip[t] makes every neighbour pair agree (paper-free
  // standard breadth-first propagation), keeping each component's majority orientation.
  std::vector<int> component(triangles, -1);
  std::vector<char> flip(triangles, 0);
  std::vector<std::uint32_t> members;
  std::vector<std::uint32_t> stack;
  std::uint64_t reoriented = 0, flipped_components = 0, flipped_faces = 0;
  int components = 0;
  for (std::size_t seed = 0; seed < triangles; ++seed) {
    if (component[seed] >= 0) continue;
    members.clear();
    component[seed] = components;
    stack.push_back(static_cast<std::uint32_t>(seed));
    bool closed = true;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      members.push_back(t);
      const Triangle3& tri = soup.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const int u = neighbor[3 * t + k];
        if (u < 0) {
          closed = false;
          continue;
        }
        const Triangle3& other = soup.triangles[u];
        const int from = tri[k];
        const int ku = corner_of(other, from);
        const bool same_direction = other[(ku + 1) % 3] == tri[(k + 1) % 3];
        const char wanted = static_cast<char>(flip[t] ^ (same_direction ? 1 : 0));
        if (component[u] < 0) {
          component[u] = components;
          flip[u] = wanted;
          stack.push_back(static_cast<std::uint32_t>(u));
        } else if (flip[u] != wanted) {
          throw_invalid(file,
                        "mesh has a non-orientable component (like a Moebius strip), "
                        "containing face " +
                            std::to_string(soup.source_face[t]));
        }
      }
    }
    std::size_t flips = 0;
    for (std::uint32_t t : members) flips += flip[t];
    if (2 * flips > members.size()) {
      for (std::uint32_t t : members) flip[t] ^= 1;
      flips = members.size() - flips;
    }
    reoriented += flips;
    if (closed) {
      // Signed volume (divergence theorem), relative to a point of the component for precision.
      const Vec3d origin = soup.positions[soup.triangles[members.front()][0]];
      double volume = 0.0;
      for (std::uint32_t t : members) {
        const Triangle3& tri = soup.triangles[t];
        const Vec3d a = soup.positions[tri[0]] - origin;
        Vec3d b = soup.positions[tri[1]] - origin;
        Vec3d c = soup.positions[tri[2]] - origin;
        if (flip[t]) std::swap(b, c);
        volume += OpenMesh::dot(a, cross(b, c));
      }
      if (volume < 0.0) {
        for (std::uint32_t t : members) flip[t] ^= 1;
        ++flipped_components;
        flipped_faces += members.size();
        reoriented -= flips;
      }
    }
    ++components;
  }
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!flip[t]) continue;
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
    if (!soup.corner_uv.empty()) std::swap(soup.corner_uv[t][1], soup.corner_uv[t][2]);
  }
  if (reoriented > 0) {
    repairs.push_back("reoriented " + counted(reoriented, "face", "faces") +
                      " to agree with their neighbours");
  }
  if (flipped_components > 0) {
    repairs.push_back(
        "flipped " +
        counted(flipped_components, "closed component that faced", "closed components that faced") +
        " inwards (" + counted(flipped_faces, "face", "faces") + ")");
  }
}

std::string texture_of(const RawMesh& raw, const Prescan& scan, const std::filesystem::path& path) {
  if (scan.format == Format::ply && !scan.ply_texture.empty()) {
    return (path.parent_path() / scan.ply_texture).lexically_normal().string();
  }
  if (scan.format != Format::obj || raw.textures.empty()) return {};
  int best = raw.textures.begin()->first;
  std::size_t best_faces = 0;
  for (const auto& [texture, faces] : raw.faces_per_texture) {
    if (faces > best_faces && raw.textures.count(texture) > 0) {
      best = texture;
      best_faces = faces;
    }
  }
  std::string_view name = trim(raw.textures.at(best));
  if (!name.empty() && name.front() == '-') {
    // map_Kd options ("-s 1 1 1 wood.png"): the file name comes last.
    const std::size_t last = name.find_last_of(" \t");
    if (last != std::string_view::npos) name = name.substr(last + 1);
  }
  return (scan.material_library.parent_path() / std::string(name)).lexically_normal().string();
}

LoadedMesh validate_and_build(RawMesh& raw, const Prescan& scan, const LoadOptions& options,
                              const std::string& file, const std::filesystem::path& path) {
  LoadedMesh loaded;
  loaded.input_vertices = scan.vertices;
  loaded.input_faces = scan.faces;
  const bool vertices_match = scan.format == Format::stl ? raw.positions.size() <= scan.vertices
                                                         : raw.positions.size() == scan.vertices;
  if (!vertices_match || raw.n_faces() != scan.faces || raw.corners.size() != scan.corners) {
    throw_io(file, "OpenMesh's reader returned " + declared(raw.positions.size(), raw.n_faces()) +
                       " (" + std::to_string(raw.corners.size()) + " corners), but the file has " +
                       declared(scan.vertices, scan.faces) + " (" + std::to_string(scan.corners) +
                       " corners): it misread the file");
  }
  if (scan.format == Format::stl && raw.positions.size() < scan.vertices) {
    loaded.repairs.push_back("merged " +
                             counted(scan.vertices - raw.positions.size(),
                                     "exactly duplicate vertex", "exactly duplicate vertices") +
                             " (an STL stores every triangle corner separately)");
  }
  check_raw_faces(raw, file);

  // Texture coordinates: per corner (OBJ) when every face has them, else per vertex (PLY, OFF)
  // when every vertex has them.
  const std::size_t faces_with_uv =
      static_cast<std::size_t>(std::count(raw.face_has_uv.begin(), raw.face_has_uv.end(), 1));
  const std::size_t vertices_with_uv =
      static_cast<std::size_t>(std::count(raw.vertex_has_uv.begin(), raw.vertex_has_uv.end(), 1));
  bool with_uvs = false;
  if (scan.off_face_extras > 0) {
    loaded.repairs.push_back("ignored the values after the vertex indices of " +
                             counted(scan.off_face_extras, "face", "faces") +
                             " (face colors need a COFF header)");
  }
  if (faces_with_uv > 0) {
    with_uvs = faces_with_uv == raw.n_faces();
    if (!with_uvs) {
      loaded.repairs.push_back("ignored texture coordinates: only " +
                               std::to_string(faces_with_uv) + " of " +
                               counted(raw.n_faces(), "face has", "faces have") + " them");
    }
  } else if (vertices_with_uv > 0) {
    with_uvs = vertices_with_uv == raw.positions.size();
    if (with_uvs) {
      raw.corner_uv.resize(raw.corners.size());
      for (std::size_t c = 0; c < raw.corners.size(); ++c) {
        raw.corner_uv[c] = raw.vertex_uv[raw.corners[c]];
      }
    } else {
      loaded.repairs.push_back(
          "ignored texture coordinates: only " + std::to_string(vertices_with_uv) + " of " +
          counted(raw.positions.size(), "vertex has", "vertices have") + " them");
    }
  }
  loaded.texture_path = texture_of(raw, scan, path);

  Soup soup = triangulate(raw, with_uvs, options, file, loaded.repairs);
  raw = RawMesh();

  if (options.repair) {
    if (const std::size_t removed = remove_unreferenced_vertices(soup); removed > 0) {
      loaded.repairs.push_back("removed " +
                               counted(removed, "unreferenced vertex", "unreferenced vertices"));
    }
    const double epsilon = std::max(0.0, options.duplicate_vertex_epsilon);
    if (const std::size_t merged = merge_duplicate_vertices(soup, epsilon); merged > 0) {
      std::ostringstream what;
      what << "merged "
           << counted(merged, epsilon > 0.0 ? "duplicate vertex" : "exactly duplicate vertex",
                      epsilon > 0.0 ? "duplicate vertices" : "exactly duplicate vertices");
      if (epsilon > 0.0) what << " (within " << epsilon << ")";
      loaded.repairs.push_back(what.str());
    }
  }
  check_degenerate_triangles(soup, options, file);
  check_duplicate_triangles(soup, file);
  check_topology_and_orient(soup, options.repair, file, loaded.repairs);

  Mesh& mesh = loaded.mesh;
  const std::size_t vertices = soup.positions.size();
  mesh.reserve(vertices, soup.triangles.size() * 3 / 2 + 3, soup.triangles.size());
  std::vector<Mesh::VertexHandle> handles(vertices);
  for (std::size_t v = 0; v < vertices; ++v) handles[v] = mesh.add_vertex(soup.positions[v]);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const Triangle3& tri = soup.triangles[t];
    if (!mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid()) {
      throw_invalid(file, "OpenMesh refused face " + std::to_string(soup.source_face[t]) +
                              " (vertices " + vertex_list(soup.source_vertex, tri) +
                              ") as non-manifold");
    }
  }
  auto input_vertex =
      OpenMesh::getOrMakeProperty<OpenMesh::VertexHandle, int>(mesh, kInputVertexProperty);
  for (auto v : mesh.vertices()) input_vertex[v] = soup.source_vertex[v.idx()];

  if (with_uvs) {
    loaded.has_uvs = true;
    mesh.request_vertex_texcoords2D();
    std::vector<char> assigned(vertices, 0);
    std::vector<char> seam(vertices, 0);
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const int v = soup.triangles[t][k];
        const Vec2d& uv = soup.corner_uv[t][k];
        if (!assigned[v]) {
          mesh.set_texcoord2D(handles[v], uv);
          assigned[v] = 1;
        } else if (mesh.texcoord2D(handles[v]) != uv) {
          seam[v] = 1;
        }
      }
    }
    loaded.uv_seam_vertices = static_cast<std::size_t>(std::count(seam.begin(), seam.end(), 1));
    if (loaded.uv_seam_vertices > 0) {
      mesh.request_halfedge_texcoords2D();
      for (auto f : mesh.faces()) {
        const Triangle3& tri = soup.triangles[f.idx()];
        for (auto h : f.halfedges()) {
          mesh.set_texcoord2D(h, soup.corner_uv[f.idx()][corner_of(tri, h.to().idx())]);
        }
      }
    }
  }
  return loaded;
}

Format format_of(const std::filesystem::path& path, const std::string& file) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return Format::obj;
  if (extension == ".off") return Format::off;
  if (extension == ".ply") return Format::ply;
  if (extension == ".stl") return Format::stl;
  throw_invalid(file, (extension.empty() ? std::string("no file extension")
                                         : "unknown extension " + in_quotes(extension)) +
                          " (supported: .obj, .off, .ply, .stl)");
}

}  // namespace

LoadedMesh load_mesh(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string file = path.string();
  const Format format = format_of(path, file);
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw_io(file, "no such file");
  if (!std::filesystem::is_regular_file(status)) throw_io(file, "not a regular file");
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error) throw_io(file, "cannot read the file size: " + error.message());
  if (size == 0) throw_invalid(file, "the file is empty");

  Prescan scan;
  {
    FileScanner in(path, file, size);
    switch (format) {
      case Format::obj:
        scan = prescan_obj(in, file, path, options);
        break;
      case Format::off:
        scan = prescan_off(in, file, options);
        break;
      case Format::ply:
        scan = prescan_ply(in, file, options);
        break;
      case Format::stl:
        scan = prescan_stl(in, file, options);
        break;
    }
  }
  RawMesh raw = read_with_openmesh(path, file, scan);
  return validate_and_build(raw, scan, options, file, path);
}

}  // namespace papercraft
