#pragma once
// Cutting a rejected part where the strip it leaves behind is as large as possible.
//
// The paper cuts through the worst point; the piece between a strip boundary and that cut
// is often still far from its limit, so it needs another cut later and the model ends with
// more strips than necessary. Here we search (bisection on the iso-value of the harmonic
// field f between the two boundaries) for the largest piece next to either boundary that
// one ruled strip approximates within the tolerance — a greedy sweep that yields maximal
// strips. Each probe is one cut, one twist DP and one certified decision.

#include <vector>

#include "core/mesh.h"
#include "engine/cut/through_witness.h"
#include "engine/refine/decide.h"
#include "engine/ruled/twist_dp.h"

namespace papercraft {

struct MaximalStripOptions {
  WitnessCutOptions cut;
  TwistOptions twist;
  DecideOptions decide;
  int steps = 4;  // bisection steps per side
  // A piece below this fraction of the part's area is not worth a strip of its own: peeling
  // thin layers off the side that already fits, while the error sits at the other end, only
  // multiplies strips and slivers. Below it the caller cuts through the worst point.
  double min_strip_fraction = 0.1;
};

/// Cuts `part` at the iso-value that leaves the largest piece next to `first` or `second`
/// approximable by one strip within `tolerance`. Returns no pieces if no probe succeeded
/// (the caller then cuts through the worst point). `first`/`second` as in harmonic_field.
WitnessCut cut_maximal_strip(const Mesh& part, const std::vector<int>& first, bool first_closed,
                             const std::vector<int>& second, bool second_closed, double tolerance,
                             const MaximalStripOptions& options = {},
                             const OneStrip& one_strip = {});

}  // namespace papercraft
