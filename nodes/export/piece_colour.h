#pragma once
// The colour each printed piece has in the assembly guide and in assembly.html, so a piece
// looks the same in both.

#include <string>

namespace papercraft {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  // 0..1
};

/// The colour of the `index`-th piece (0-based, in page order): hues a golden-ratio step
/// apart, so neighbours in that order differ, light enough for black numbers on them.
Rgb piece_colour(int index);

/// "#rrggbb".
std::string hex_colour(const Rgb& colour);

}  // namespace papercraft
