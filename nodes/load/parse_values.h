#pragma once
// Values as OpenMesh's readers see them: whitespace-separated tokens and numbers in text,
// little- and big-endian numbers in binary records, and saturating sizes for the size checks.

#include <cstdint>
#include <string_view>

namespace papercraft::load_internal {

/// Space, tab, carriage return, newline, form feed or vertical tab.
bool is_space(char c);
/// The text without leading and trailing whitespace.
std::string_view trim(std::string_view text);
/// Whether the line, trimmed, ends in a backslash (an OBJ statement going on on the next line).
bool ends_in_backslash(std::string_view line);
/// Takes the first whitespace-separated token off `rest` (empty when none is left).
std::string_view next_token(std::string_view& rest);
/// Whether `text` starts with `prefix`, ignoring ASCII case.
bool starts_with_ignoring_case(std::string_view text, std::string_view prefix);
/// Whether `a` and `b` are equal, ignoring ASCII case.
bool equals_ignoring_case(std::string_view a, std::string_view b);

enum class NumberKind { finite, non_finite, invalid };

/// Classifies a token as OpenMesh's `stream >> float` reads it: NaN, infinities and magnitudes
/// beyond single precision make its readers fail or drop the record, so they count as non-finite;
/// an underflow reads as zero, as it does for OpenMesh. A finite number is also stored in `*value`
/// when `value` is given, and in double precision in `*exact` when `exact` is given.
NumberKind classify_float(std::string_view token, float* value = nullptr,
                          double* exact = nullptr);
/// Reads the whole token (optionally signed) as an integer; false when it is not one.
bool parse_integer(std::string_view token, std::int64_t& value);
/// a * b, or UINT64_MAX when that overflows.
std::uint64_t multiply_saturating(std::uint64_t a, std::uint64_t b);
/// a + b, or UINT64_MAX when that overflows.
std::uint64_t add_saturating(std::uint64_t a, std::uint64_t b);
/// The `size`-byte (at most 8) integer at `bytes`, sign-extended when `is_signed`.
std::int64_t decode_integer(const unsigned char* bytes, int size, bool is_signed, bool big_endian);
/// The little-endian IEEE single-precision number at `bytes`.
float decode_float_little_endian(const unsigned char* bytes);

}  // namespace papercraft::load_internal
