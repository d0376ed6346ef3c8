// The merge passes' shared precondition check, with a message naming the strip at fault.
#include "nodes/merge/validate.h"

#include <string>

#include "core/errors.h"

namespace papercraft::merge_detail {

void validate(const std::vector<FlatStrip>& strips, const MergeOptions& options) {
  if (!(options.congruence_tolerance >= 0.0) || !(options.overlap_tolerance >= 0.0))
    throw InvalidInputException("merge: tolerances must be >= 0");
  for (const FlatStrip& strip : strips) {
    const std::size_t n = strip.vertices3d.size();
    std::string name = "merge: flat strip " + std::to_string(strip.id);
    if (strip.vertices2d.size() != n)
      throw InvalidInputException(name + " has " + std::to_string(strip.vertices2d.size()) +
                                  " 2D vertices for " + std::to_string(n) + " 3D vertices");
    if (!strip.uvs.empty() && strip.uvs.size() != n)
      throw InvalidInputException(name + " has " + std::to_string(strip.uvs.size()) + " uvs for " +
                                  std::to_string(n) + " vertices");
    for (const Triangle& t : strip.triangles)
      for (int v : t)
        if (v < 0 || static_cast<std::size_t>(v) >= n)
          throw InvalidInputException(name + " has a triangle vertex " + std::to_string(v) +
                                      " out of range [0, " + std::to_string(n) + ")");
  }
}

}  // namespace papercraft::merge_detail
