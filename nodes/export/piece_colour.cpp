#include "nodes/export/piece_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace papercraft {

Rgb piece_colour(int index) {
  const double hue = std::fmod(index * 0.618033988749895, 1.0) * 6.0;
  const double s = 0.45, v = 0.95;
  const int sector = static_cast<int>(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (sector) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

std::string hex_colour(const Rgb& colour) {
  auto byte = [](double channel) {
    return static_cast<int>(std::lround(255.0 * std::clamp(channel, 0.0, 1.0)));
  };
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(colour.r), byte(colour.g), byte(colour.b));
  return text;
}

}  // namespace papercraft
