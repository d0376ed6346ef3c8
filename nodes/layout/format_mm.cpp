// Lengths in millimetres as the layout prints them.
#include "nodes/layout/format_mm.h"

#include <ios>
#include <sstream>

namespace papercraft::layout_internal {

std::string format_mm(double value) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(0);
  out << value;
  return out.str();
}

}  // namespace papercraft::layout_internal
