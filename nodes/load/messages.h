#pragma once
// The loader's error messages: each starts with the file's name, counts things in words ("3 faces")
// and quotes the offending text.

#include <cstdint>
#include <string>
#include <string_view>

namespace papercraft::load_internal {

/// Throws InvalidInputException("<file>: <what>").
[[noreturn]] void throw_invalid(const std::string& file, const std::string& what);
/// Throws IOException("<file>: <what>").
[[noreturn]] void throw_io(const std::string& file, const std::string& what);
/// "1 face", "3 faces": `n` with the singular or plural noun.
std::string counted(std::uint64_t n, std::string_view singular, std::string_view plural);
/// "line 12: ", the prefix of a message about one line of the file.
std::string at_line(std::uint64_t line);
/// The text in single quotes, cut after 40 characters with "...".
std::string in_quotes(std::string_view text);
/// "4 vertices and 4 faces", as a header declares them.
std::string declared(std::uint64_t vertices, std::uint64_t faces);

}  // namespace papercraft::load_internal
