#pragma once
// Collecting one model's unfolded strips into ModelStrips in a deterministic order, and
// recording the result in the model's record, shared by the merge implementations.

#include <vector>

#include "graph/messages.h"
#include "graph/model_run.h"

namespace papercraft {

/// Sorts by part path (numerically, "0.2" < "0.10"), numbers 3D strips 0.. in that order and
/// flat strips 0.. likewise, sets source_strip, and labels the seams.
ModelStrips collect_model_strips(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded);

/// Sets the model record's strip counts (3D, flat before and after merge) and its bound: the
/// largest certified bound of the 3D strips, plus the proxy's distance to the input where the
/// model was approximated through a proxy.
void record_model_strips(ModelRun& model, const ModelStrips& strips);

}  // namespace papercraft
