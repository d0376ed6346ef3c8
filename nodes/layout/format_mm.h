#pragma once
// Lengths in millimetres as the layout prints them in messages and captions.

#include <string>

namespace papercraft::layout_internal {

/// `value` in fixed notation rounded to whole millimetres ("297").
std::string format_mm(double value);

}  // namespace papercraft::layout_internal
