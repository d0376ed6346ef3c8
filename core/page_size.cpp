#include "core/page_size.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <utility>

#include "core/errors.h"

namespace papercraft {

namespace {

constexpr std::pair<const char*, PageSize> kNamedPages[] = {
    {"A3", {297.0, 420.0}},     {"A4", {210.0, 297.0}},    {"A5", {148.0, 210.0}},
    {"Letter", {215.9, 279.4}}, {"Legal", {215.9, 355.6}}, {"Tabloid", {279.4, 431.8}},
};

std::string lower_case(std::string_view text) {
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

}  // namespace

PageSize page_size_from_name(std::string_view name) {
  const std::string lower = lower_case(name);
  for (const auto& [known, size] : kNamedPages) {
    if (lower == lower_case(known)) return size;
  }
  const std::size_t x = lower.find('x');
  if (x != std::string::npos) {
    double w = 0, h = 0;
    const char* begin = lower.data();
    const char* end = begin + lower.size();
    auto [wend, werr] = std::from_chars(begin, begin + x, w);
    auto [hend, herr] = std::from_chars(begin + x + 1, end, h);
    if (werr == std::errc() && herr == std::errc() && wend == begin + x && hend == end && w > 0 &&
        h > 0 && std::isfinite(w) && std::isfinite(h))
      return {w, h};
  }
  throw InvalidInputException("unknown page size '" + std::string(name) +
                              "': use A3, A4, A5, Letter, Legal, Tabloid or <width>x<height> in "
                              "mm (e.g. 200x300)");
}

std::string page_size_name(const PageSize& page) {
  for (const auto& [name, size] : kNamedPages) {
    if (size.width_mm == page.width_mm && size.height_mm == page.height_mm) return name;
  }
  std::ostringstream text;
  text << page.width_mm << "x" << page.height_mm;
  return text.str();
}

}  // namespace papercraft
