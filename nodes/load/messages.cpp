// The loader's error messages: the file's name first, counts in words, offending text quoted.

#include "nodes/load/messages.h"

#include "core/errors.h"

namespace papercraft::load_internal {

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
  // Appended rather than `"'" + std::string(...)`, which trips GCC 12's -Wrestrict out of line.
  std::string quoted(1, '\'');
  quoted.append(text.substr(0, 40));
  quoted.append(text.size() > 40 ? "...'" : "'");
  return quoted;
}

std::string declared(std::uint64_t vertices, std::uint64_t faces) {
  return counted(vertices, "vertex", "vertices") + " and " + counted(faces, "face", "faces");
}

}  // namespace papercraft::load_internal
