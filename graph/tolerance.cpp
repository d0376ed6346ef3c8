#include "graph/tolerance.h"

#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "graph/params.h"

namespace papercraft {

std::string ToleranceSpec::to_string() const {
  std::ostringstream out;
  if (relative) {
    out << value * 100.0 << "%";
  } else {
    out << value;
  }
  return out.str();
}

ToleranceSpec parse_tolerance(const std::string& raw) {
  std::string text = raw;
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  ToleranceSpec spec;
  spec.relative = !text.empty() && text.back() == '%';
  if (spec.relative) text.pop_back();
  double value = 0.0;
  const std::size_t used = parse_number_prefix(text, value);
  if (used == 0 || used != text.size() || !std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument("expected a positive tolerance like 2% or 0.004, got '" + raw +
                                "'");
  }
  spec.value = spec.relative ? value / 100.0 : value;
  return spec;
}

double parse_length_mm(const std::string& raw) {
  double value = 0.0;
  const std::size_t used = parse_number_prefix(raw, value);
  std::string unit;
  for (std::size_t i = used; i < raw.size(); ++i) {
    if (!std::isspace(static_cast<unsigned char>(raw[i]))) {
      unit += static_cast<char>(std::tolower(static_cast<unsigned char>(raw[i])));
    }
  }
  double mm_per_unit = 0.0;
  if (unit.empty() || unit == "mm") mm_per_unit = 1.0;
  if (unit == "cm") mm_per_unit = 10.0;
  if (unit == "m") mm_per_unit = 1000.0;
  if (unit == "in" || unit == "\"") mm_per_unit = 25.4;
  if (used == 0 || mm_per_unit == 0.0 || !std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument("expected a positive length like 200, 200mm, 20cm or 8in, got '" +
                                raw + "'");
  }
  return value * mm_per_unit;
}

}  // namespace papercraft
