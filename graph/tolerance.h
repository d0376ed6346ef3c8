#pragma once
// The user tolerance: relative ("2%" of the largest bounding-box side) or absolute (0.004);
// and paper lengths with units.

#include <string>

namespace papercraft {

/// The largest tolerance accepted without asking (a fraction of the largest side): beyond
/// it the strips no longer resemble the model.
inline constexpr double kLargestTolerance = 0.5;

struct ToleranceSpec {
  double value = 0.02;
  bool relative = true;  // value is a fraction of the largest side

  double absolute(double largest_side) const { return relative ? value * largest_side : value; }
  std::string to_string() const;
};

/// "2%" -> {0.02, relative}; "0.004" -> {0.004, absolute}. Throws std::invalid_argument
/// ("expected a tolerance like 2% or 0.004") on anything else or a value <= 0.
ToleranceSpec parse_tolerance(const std::string& text);

/// The print scale and the smallest piece a person can cut and glue, known before the
/// refinement so that every stage can reason in millimetres on paper.
struct PaperSpec {
  double height_mm = 200.0;  // the model's largest bounding-box side on paper
  double scale = 0.0;        // mm on paper per model unit; overrides height_mm when > 0
  double min_width_mm = 5.0;
  double min_area_mm2 = 100.0;

  /// mm on paper per model unit for a model whose largest side is `largest_side`.
  double mm_per_unit(double largest_side) const {
    return scale > 0.0 ? scale : largest_side > 0.0 ? height_mm / largest_side : 1.0;
  }
};

/// A length on paper in millimetres: "200", "200mm", "20 cm", "0.2m", "8in" (a bare number is
/// mm). Throws std::invalid_argument naming the text on anything else or a value <= 0.
double parse_length_mm(const std::string& text);

}  // namespace papercraft
