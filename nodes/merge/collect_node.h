#pragma once
// Collecting one model's unfolded strips into ModelStrips in a deterministic order, shared
// by the merge implementations.

#include <vector>

#include "graph/messages.h"

namespace papercraft {

/// Sorts by part path (numerically, "0.2" < "0.10"), numbers 3D strips 0.. in that order and
/// flat strips 0.. likewise, sets source_strip, and labels the seams.
ModelStrips collect_model_strips(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded);

}  // namespace papercraft
