// The pre-scan of an OFF file, ascii or "OFF BINARY".

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string_view>

#include "nodes/load/messages.h"
#include "nodes/load/parse_values.h"
#include "nodes/load/prescan.h"

namespace papercraft::load_internal {
namespace {

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

// What the first line of an OFF file says.
struct OffKeyword {
  bool normals = false, colors = false;
  bool native = false;  // a plain OFF the pre-scan reads itself
  bool binary = false;
  std::size_t prefix = 0;                   // characters before "OFF" (ST, C, N)
  std::string_view counts_on_keyword_line;  // the counts, where they follow the keyword
};

// The keyword line, after the comment and blank lines before it (which set scan.off_comments):
// OpenMesh's [ST][C][N][4][n]OFF[ BINARY], looser for a plain OFF read here.
OffKeyword read_off_keyword(FileScanner& in, const std::string& file, bool collect, Prescan& scan) {
  OffKeyword k;
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
  std::string_view keyword = next_token(rest);
  // OpenMesh checks the first line for [ST][C][N][4][n]OFF[ BINARY].
  std::size_t prefix = 0;
  const bool texcoords = keyword.substr(0, 2) == "ST";
  if (texcoords) prefix += 2;
  const bool colors = keyword.substr(prefix, 1) == "C";
  if (colors) ++prefix;
  const bool normals = keyword.substr(prefix, 1) == "N";
  if (normals) ++prefix;
  if (keyword.substr(prefix, 1) == "4" || keyword.substr(prefix, 1) == "n") {
    throw_invalid(file,
                  first_line + "only 3-dimensional OFF is supported, got " + in_quotes(keyword));
  }
  // A plain OFF is read here, not by OpenMesh's reader, so its header may be looser: blanks
  // before the keyword, and the counts on the keyword's line, even glued to it ("OFF8 6 12").
  const bool native = collect && prefix == 0;
  std::string_view counts_on_keyword_line;
  if (native && keyword.size() > 3 && keyword.substr(0, 3) == "OFF" &&
      std::all_of(keyword.begin() + 3, keyword.end(),
                  [](char c) { return c >= '0' && c <= '9'; })) {
    counts_on_keyword_line =
        trim(line.substr(static_cast<std::size_t>(keyword.data() + 3 - line.data())));
    keyword = keyword.substr(0, 3);
    rest = {};
  }
  const bool leading_blank = !line.empty() && is_space(line.front());
  if (line.empty() || (leading_blank && !native) || keyword.substr(prefix) != "OFF") {
    throw_invalid(file, first_line +
                            "expected 'OFF' (optionally prefixed by ST, C, N) at the start of "
                            "the first line, got " +
                            in_quotes(line));
  }
  const std::string_view after = next_token(rest);
  const bool binary = after == "BINARY";
  if (binary &&
      (leading_blank || line.substr(keyword.size(), 7) != " BINARY" || !trim(rest).empty())) {
    throw_invalid(file, first_line + "write the binary OFF header exactly as '" +
                            std::string(keyword) + " BINARY'");
  }
  if (!after.empty() && !binary && native) {
    counts_on_keyword_line =
        trim(line.substr(static_cast<std::size_t>(after.data() - line.data())));
  } else if (!after.empty() && !binary) {
    throw_invalid(file, first_line + "unexpected " + in_quotes(after) +
                            " after 'OFF' (OpenMesh's reader expects the counts on the next line)");
  }
  k.normals = normals;
  k.colors = colors;
  k.native = native;
  k.binary = binary;
  k.prefix = prefix;
  k.counts_on_keyword_line = counts_on_keyword_line;
  return k;
}

// A binary OFF: its counts, and its face records walked past to count their corners.
void scan_binary_off(FileScanner& in, const std::string& file, const LoadOptions& options,
                     const OffKeyword& k, Prescan& scan) {
  if (k.prefix != 0) {
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
}

// The vertex lines: positions checked (and normals with the N prefix), kept in `raw` where
// given.
void read_off_vertices(FileScanner& in, const std::string& file, std::uint64_t vertices,
                       std::uint64_t faces, const OffKeyword& k, RawMesh* raw, Prescan& scan) {
  std::string_view line;
  const bool normals = k.normals;
  for (std::uint64_t vertex = 0; vertex < vertices; ++vertex) {
    if (!next_off_line(in, line, scan.off_comments)) {
      throw_invalid(file, "truncated: the header declares " + declared(vertices, faces) +
                              ", but the file ends after " +
                              counted(vertex, "vertex line", "vertex lines"));
    }
    std::string_view tokens = line;
    double position[3];
    for (int value = 0; value < (normals ? 6 : 3); ++value) {
      const std::string_view token = next_token(tokens);
      const NumberKind kind =
          classify_float(token, nullptr, value < 3 ? &position[value] : nullptr);
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
    if (raw != nullptr) raw->positions.emplace_back(position[0], position[1], position[2]);
  }
}

// The face lines: counts and indices checked (over several lines for a plain OFF), kept in
// `raw` where given; trailing values counted in scan.off_face_extras.
void read_off_faces(FileScanner& in, const std::string& file, std::uint64_t vertices,
                    std::uint64_t faces, const OffKeyword& k, RawMesh* raw, Prescan& scan) {
  std::string_view line;
  const bool native = k.native, colors = k.colors;
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
      std::string_view token = next_token(tokens);
      // The format is free: a face's indices may go on over the next lines (libigl writes
      // one value a line). Only where the pre-scan reads the file itself: OpenMesh's reader
      // takes a face from its line, and read on, a count from the next was once taken for a
      // face of four billion corners.
      while (token.empty() && native && next_off_line(in, line, scan.off_comments)) {
        tokens = line;
        token = next_token(tokens);
      }
      if (token.empty()) {
        throw_invalid(file, at_line(in.line_number()) + "face " + std::to_string(face) +
                                " declares " + std::to_string(count) + " vertices but lists " +
                                std::to_string(corner));
      }
      if (!parse_integer(token, index)) {
        throw_invalid(file, at_line(in.line_number()) + "expected a vertex index in face " +
                                std::to_string(face) + ", got " + in_quotes(token));
      }
      // An index is kept as an int vertex handle (one beyond int is out of range anyway).
      if (raw != nullptr)
        raw->corners.push_back(static_cast<int>(std::clamp<std::int64_t>(
            index, std::numeric_limits<int>::min(), std::numeric_limits<int>::max())));
    }
    if (raw != nullptr) raw->face_start.push_back(raw->corners.size());
    // Without the C prefix OpenMesh reads faces token by token, so trailing values (colors)
    // would be taken for the next face.
    // They are dropped before OpenMesh reads the file (`Prescan::off_face_extras`).
    if (!colors && !trim(tokens).empty()) ++scan.off_face_extras;
    scan.corners += static_cast<std::uint64_t>(count);
  }
}

}  // namespace

Prescan prescan_off(FileScanner& in, const std::string& file, const LoadOptions& options,
                    RawMesh* raw) {
  Prescan scan;
  scan.format = Format::off;
  const OffKeyword k = read_off_keyword(in, file, raw != nullptr, scan);
  if (k.binary) {
    scan_binary_off(in, file, options, k, scan);
    return scan;
  }
  std::string_view line;
  const bool native = k.native;
  if (!k.counts_on_keyword_line.empty()) {
    line = k.counts_on_keyword_line;
  } else if (!next_off_line(in, line, scan.off_comments)) {
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
  // A plain OFF is read here; with prefixes OpenMesh's reader reads the extra values.
  if (!native) raw = nullptr;
  if (raw != nullptr) {
    *raw = RawMesh();
    raw->positions.reserve(vertices);
    raw->face_start.reserve(faces + 1);
    raw->corners.reserve(3 * faces);
  }

  read_off_vertices(in, file, vertices, faces, k, raw, scan);
  read_off_faces(in, file, vertices, faces, k, raw, scan);
  if (next_off_line(in, line, scan.off_comments)) {
    throw_invalid(file, "the header declares " + declared(vertices, faces) +
                            ", but more data follows at line " + std::to_string(in.line_number()) +
                            " (wrong counts?)");
  }
  scan.read_natively = raw != nullptr;
  return scan;
}

}  // namespace papercraft::load_internal
