#pragma once
// The merge passes' shared precondition check (congruent.h: "\pre as merge_congruent").

#include <vector>

#include "core/strip.h"
#include "nodes/merge/congruent.h"

namespace papercraft::merge_detail {

/// \throws InvalidInputException unless every strip has vertices2d and vertices3d of equal
///   size, uvs empty or of that size and triangle indices in range, and options' tolerances
///   are >= 0.
void validate(const std::vector<FlatStrip>& strips, const MergeOptions& options);

}  // namespace papercraft::merge_detail
