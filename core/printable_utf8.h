#pragma once
// Text from outside (file names, a loader's quote of a file's bytes) may hold bytes that are
// not UTF-8, which JSON writers refuse (nlohmann::json throws type_error.316 on dump), or
// control characters that a terminal would obey. Such text is made printable before it goes
// into a summary, a report, a message or a progress line.

#include <string>
#include <string_view>

namespace papercraft {

/// `text` with every byte that is not part of a well-formed UTF-8 sequence (Unicode 15,
/// table 3-7: no overlong forms, no surrogates, nothing above U+10FFFF), and every control
/// character but tab and newline (U+0000..U+001F, U+007F), written as the four characters
/// `\xNN` (NN: upper-case hex). Other text is kept as it is, so applying it twice changes
/// nothing more.
std::string printable_utf8(std::string_view text);

/// True when `text` is well-formed UTF-8 (control characters allowed).
bool is_valid_utf8(std::string_view text);

}  // namespace papercraft
