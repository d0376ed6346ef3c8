#pragma once
// What the merge node says of the pieces it leaves: the notes in report.json and on stderr
// about pieces a person cannot handle and triangles dropped, and the count of pieces left short
// of the limits that the joins in 3D try to lower.

#include <cstddef>
#include <vector>

#include "core/piece_limits.h"
#include "core/strip.h"
#include "graph/model_run.h"
#include "nodes/merge/merge_model_node.h"

namespace papercraft {

/// The pieces a person cannot handle, named in report.json and on stderr: those too small that
/// no neighbour takes (`small`: their ids), and those narrower than min_width_mm over more than
/// their tips. A piece glued to no other is a whole separate part of the model (a tooth, a
/// claw, a button): no join can grow or widen it, only a larger print scale, and the note says
/// so. One that no fold onto a neighbour lays flat is said to be so, naming the neighbour whose
/// seam with it runs round the widest saddle of the surface.
void note_unbuildable_pieces(ModelRun& model, const std::vector<FlatStrip>& strips,
                             const std::vector<int>& small);

/// Says how many triangles drop_double_covered_triangles dropped (`twice`), where any were.
void note_double_cover(ModelRun& model, std::size_t twice);

/// A piece glued to another that is too small, or too narrow (over more than the share past
/// which the merge hinges a narrow piece on).
struct Short {
  std::size_t source;  // its 3D strip
  bool small;
  double narrow;  // share of its area narrower than min_width
  double area_mm2;
};

/// The pieces of `merged` glued to another that are too small, or narrower than min_width over
/// more than `narrow_bound` of their area.
std::vector<Short> short_pieces(const Merged& merged, const PieceLimits& limits,
                                double narrow_bound, double mm_per_unit);

/// Each limit a short piece misses counts once.
int shortfalls(const std::vector<Short>& shorts, double narrow_bound);

/// What `merged`'s pieces cost a person (local_effort over all of them, core/piece_effort.h, at
/// options.mm_per_unit with options.weights), each piece narrower than min_width over more than
/// limits.max_narrow_share counted as assembly_effort counts it on the pages. What the node's
/// choices between whole merges compare.
double model_effort(const Merged& merged, const PieceLimits& limits, const MergeOptions& options);

}  // namespace papercraft
