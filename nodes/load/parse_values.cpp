// Tokens, numbers in text and numbers in binary records, read as OpenMesh's readers read them.

#include "nodes/load/parse_values.h"

#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

namespace papercraft::load_internal {

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

NumberKind classify_float(std::string_view token, float* value, double* exact) {
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
  if (exact != nullptr) *exact = number;
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

bool ends_in_backslash(std::string_view line) {
  const std::string_view body = trim(line);
  return !body.empty() && body.back() == '\\';
}

}  // namespace papercraft::load_internal
