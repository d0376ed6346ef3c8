#pragma once
// Joins in 3D: where the merge leaves a piece too small or too narrow beside a neighbour, their
// 3D parts refined together as one strip, kept where the model then merges into fewer short
// pieces.

#include <memory>
#include <vector>

#include "engine/refine/refine.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/merge_model_node.h"

namespace papercraft {

/// Where a piece is left too small or too narrow beside a neighbour, its 3D part and a
/// neighbouring part, glued back along the cut between them, may be one strip within the
/// tolerance after all: the cut that parted them was made higher up, for a larger part that was
/// not. Such a union, refined and certified as the graph refines a part, that unfolds in one
/// piece replaces the two strips, and the model is merged again; the change is kept when fewer
/// pieces are left too small or too narrow. At most 8 unions per model (kMostRejoins), and at most
/// options.most_rejoin_trials merges of the whole model to judge them (a note says where that
/// budget ran out). `unfolded` is left as the strips of the merge returned (the unions in place
/// of the parts they join).
Merged rejoin_in_3d(std::vector<std::shared_ptr<const UnfoldedStrip>>& unfolded, Merged merged,
                    ModelRun& model, const MergeOptions& options, const RefineOptions& refine);

/// The merge the merge node keeps. Joins in 3D are tried against a merge that cuts a band in
/// three at most: a band cut in four, each piece hinged onto a neighbour, leaves many seams of
/// a piece with itself where a join in 3D leaves none (ChineseDragon-10kv: one piece with 101
/// such seams instead of 51). The full depth (options.most_band_pieces) is then used where
/// pieces are still left short, and kept unless it leaves more of them short.
Merged merge_with_rejoins(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded,
                          ModelRun& model, const MergeOptions& options,
                          const RefineOptions& refine);

}  // namespace papercraft
