#pragma once
// Which side of each seam takes its glue tab: the layout's TabStyle (layout_types.h).

#include <string>
#include <vector>

#include "nodes/layout/layout_types.h"
#include "nodes/layout/pieces.h"
#include "nodes/layout/seam_pairing.h"

namespace papercraft::layout_internal {

/// Gives the seam pairs their tabs in options.tab_style:
/// - One: the side that comes first (strip id, piece index, loop, start) takes the flaps it
///   has room for; the other side takes the edges it left.
/// - Alternate: the seam is cut into runs of about alternate_run_mm (a seam shorter than 1.5
///   runs is one run), taken in turn by the first side and the other; a run's edges that
///   its side has no room for go to the other side.
/// - Both: each side takes the flaps it has room for, independently.
/// - None: nothing (the caller does not call this).
/// A seam whose sides have room for no flap at all gets a warning. A tab never covers its own
/// piece or another tab of it (TabPlanner).
/// \pre options.tab_width_mm > 0 and tab_style is not None.
void add_tabs(std::vector<Piece>& pieces, const std::vector<StripData>& strips,
              const std::vector<Chain>& chains, const std::vector<SeamPair>& pairs,
              const SeamEdges& seams, const LayoutOptions& options,
              std::vector<std::string>& warnings);

}  // namespace papercraft::layout_internal
