#pragma once
// The exhaustive boundary selection of the paper (section 3.2.1): build the strip for every
// candidate pair (geodesic.h, candidate_selections) and keep the pair with the lowest
// Hausdorff error (certified, or sampled when the refinement decides by sampling). Locally optimal
// and slower than select_geodesic: one strip and one Hausdorff distance per pair, evaluated in
// parallel.

#include <vector>

#include "core/mesh.h"
#include "engine/refine/decide.h"
#include "engine/ruled/twist_dp.h"
#include "engine/select/geodesic.h"

namespace papercraft {

struct ExhaustiveSelectOptions {
  /// Gap allowed between the lower and upper bound of each pair's Hausdorff distance
  /// (model units). 0: 1% of the part's bounding-box diagonal.
  double error_bound = 0.0;
  TwistOptions twist;
  DecideOptions decide;
};

/// A candidate selection with the certified bounds of H(part, strip).
struct ScoredSelection {
  BoundarySelection selection;
  double lower = 0.0;
  double upper = 0.0;
  /// False when a cap of the Hausdorff computation tripped (upper is then still an upper
  /// bound, but looser than error_bound allows).
  bool certified = true;
};

/// Every candidate_selections(part) entry, in that order, with its strip's Hausdorff bounds.
/// Runs the pairs in parallel (TBB); the result does not depend on the thread count.
/// \pre as select_geodesic. \throws InvalidInputException if the part has no face or
/// error_bound is negative or not finite.
std::vector<ScoredSelection> score_selections(const Mesh& part,
                                              const ExhaustiveSelectOptions& options = {});

/// The candidate whose strip has the lowest Hausdorff upper bound (the first on ties); with
/// a single candidate (0 or 1 boundary loops) that one, without building anything.
/// \pre and \throws as score_selections.
BoundarySelection select_exhaustive(const Mesh& part, const ExhaustiveSelectOptions& options = {});

}  // namespace papercraft
