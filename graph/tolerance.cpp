#include "graph/tolerance.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

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
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument("expected a positive tolerance like 2% or 0.004, got '" + raw +
                                "'");
  }
  spec.value = spec.relative ? value / 100.0 : value;
  return spec;
}

}  // namespace papercraft
