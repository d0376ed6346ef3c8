#pragma once
// Internal to the segment stage: how many strips the default refinement loop (select.geodesic,
// ruled.twist_dp, hausdorff.bounded, cut.harmonic, all with their default parameters) makes of
// one part, run sequentially here so that a segmentation can be judged by what it costs.

#include "core/mesh.h"

namespace papercraft {

/// Strips the default refinement makes of `part` at the absolute `tolerance`; stops counting
/// above `cap` (returns cap + 1) and returns cap + 1 as well if the refinement fails (a part
/// that cannot be approximated is no better choice than any other). Deterministic.
int estimate_strips(const Mesh& part, double tolerance, int cap);

}  // namespace papercraft
