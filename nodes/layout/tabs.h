#pragma once
// Glue tabs: flaps along one side of every seam, shrunk or moved to the other side where
// they would cover a piece or another tab, textured with what continues across the seam.

#include <string>
#include <vector>

#include "nodes/layout/pages.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/seam_pairing.h"

namespace papercraft::layout_internal {

/// Gives each seam pair a tab: on the side that comes first (strip id, piece index, loop,
/// start) when its flaps cover at least half the seam, else on the side with the longer
/// flaps; a seam with room on neither side gets a warning and no tab.
void add_tabs(std::vector<Piece>& pieces, const std::vector<StripData>& strips,
              const std::vector<Chain>& chains, const std::vector<SeamPair>& pairs,
              const SeamEdges& seams, const LayoutOptions& options,
              std::vector<std::string>& warnings);

}  // namespace papercraft::layout_internal
