#pragma once
// The refinement engine: one part of a model refined into strips that are each within the
// tolerance of their piece (Massarwi, Gotsman, Elber 2007, section 3.2):
//
//   select  the two boundaries of the strip (3.2.1)          select_strip_boundaries
//   ruled   the twist-minimising ruled strip between them    build_strip
//   decide  is H(piece, strip) <= tolerance?                  decide_strip (decide.h)
//   cut     split a rejected piece, refine each half (3.2.2) cut_rejected_piece
//
// The graph's select, ruled, hausdorff and cut nodes each call one of these steps on one
// message, so the graph stays the unit of parallelism and of swapping; refine_part runs the
// whole recursion in one call, for what must know what the refinement would make of a part
// before committing to it (the segmentation's strip estimates). Both use the same
// RefineOptions (built by the pipeline from the configured nodes' parameters, at each model's
// tolerance), so an estimate and the real run cannot disagree. The inner searches (exhaustive
// selection, the cut's maximal-strip search) build and decide strips through the same steps.

#include <climits>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/piece_limits.h"
#include "core/strip.h"
#include "engine/refine/cut_memo.h"
#include "engine/refine/decide.h"
#include "engine/refine/rejected_cut.h"
#include "engine/ruled/twist_dp.h"
#include "engine/select/geodesic.h"

namespace papercraft {

struct SelectOptions {
  /// Build the strip of every candidate pair and keep the lowest error (select.exhaustive)
  /// instead of the pair farthest apart (select.geodesic).
  bool exhaustive = false;
  GeodesicSelectOptions geodesic;
  /// Exhaustive: each pair's Hausdorff value is bounded to within this fraction of the
  /// tolerance.
  double precision = 0.05;
};

/// Everything the four steps need: the tolerance, and one field per stage.
struct RefineOptions {
  /// The absolute tolerance tau (model units): every strip is within it of its piece. Each
  /// model has its own (at_tolerance); the steps require tolerance > 0.
  double tolerance = 0.0;
  SelectOptions select;
  TwistOptions twist;
  DecideOptions decide;
  RejectedCutOptions cut;
  /// Nested cuts allowed below one part before its refinement fails with a message.
  int max_depth = 64;
};

/// `options` at the absolute `tolerance`: a pipeline configures the options once, each model
/// brings its tolerance.
RefineOptions at_tolerance(RefineOptions options, double tolerance);

/// The two boundaries of a part's strip (each a boundary loop, closed, or a single vertex)
/// as vertex indices and as polylines, and the part's boundary loops that are neither
/// (holes, which are always split off).
struct StripBoundaries {
  std::vector<int> first;
  std::vector<int> second;
  bool first_closed = false;
  bool second_closed = false;
  Polyline a;
  Polyline b;
  std::vector<std::vector<int>> holes;
};

/// Step 1. \pre part has a face and no deleted elements (see select_geodesic);
/// options.tolerance > 0. \throws InvalidInputException otherwise, or as select_geodesic does.
StripBoundaries select_strip_boundaries(const Mesh& part, const RefineOptions& options);

/// Step 2: the strip from boundary a to boundary b, its triangles facing the way `part`'s do
/// (judged on the part's boundary edges the strip shares; boundaries are `part`'s).
RuledStrip build_strip(const Mesh& part, const StripBoundaries& boundaries,
                       const RefineOptions& options);

/// Step 3: is `strip` within options.tolerance of `part`?
/// \throws InvalidInputException unless options.tolerance > 0.
StripVerdict decide_strip(const Mesh& part, const StripBoundaries& boundaries,
                          const RuledStrip& strip, const RefineOptions& options);

/// The area on paper (model units squared) of `piece`'s strip where it is one strip within
/// options.tolerance (select, ruled and decide accept it) that unfolds without overlapping itself
/// (unfold_strip gives one flat strip); nullopt otherwise. What the cut's look-ahead asks of a
/// piece too small to be cut again (rejected_cut.h): the unfolding would split an overlapping
/// strip into two pieces each under half its area, and the ruled strip over a curved cap is
/// smaller than the surface it approximates. Set options.decide.bounded.locate_maximum = false
/// where only the decision is needed.
std::optional<double> one_flat_strip_area(const Mesh& piece, const RefineOptions& options);

/// Step 4: the pieces of a part `depth` cuts below its segment whose strip was rejected,
/// each meeting `limits` where some cut allows it (rejected_cut.h).
/// \throws ApproximationException, naming `part_name`, the tolerance and the worst point, when
/// depth >= max_depth or no cut makes progress.
std::vector<Mesh> cut_rejected_piece(const Mesh& part, const StripBoundaries& boundaries,
                                     const StripVerdict& verdict, int depth,
                                     const RefineOptions& options, const std::string& part_name,
                                     const PieceLimits& limits = {});

/// One accepted strip of refine_part: the piece it covers and how it was made.
struct RefinedStrip {
  Mesh piece;
  std::string path;  // "" for the part itself, then ".<child>" per cut ("" -> ".1" -> ".1.0")
  int depth = 0;
  StripBoundaries boundaries;
  RuledStrip strip;
  StripVerdict verdict;
};

/// A piece refined as one strip, and that strip unfolded (`refined.piece` is left empty: the
/// caller has the piece).
struct JoinedStrip {
  RefinedStrip refined;
  FlatStrip flat;  // ids 0: the caller numbers it
};

/// The strip of `piece` where it is one strip within options.tolerance (select, ruled and
/// decide accept it; certified where the decision is) that unfolds into one flat strip without
/// overlapping itself, and has no hole left over; nullopt otherwise. one_flat_strip_area is
/// its flat strip's area.
std::optional<JoinedStrip> one_strip_of(const Mesh& piece, const RefineOptions& options);

/// The whole refinement of `part` at options.tolerance: every accepted strip, in the order of
/// their paths (depth first, pieces in cut order), as the graph would make them.
/// \throws ApproximationException as cut_rejected_piece, InvalidInputException as the steps.
std::vector<RefinedStrip> refine_part(const Mesh& part, const RefineOptions& options,
                                      const PieceLimits& limits = {});

/// How many strips refine_part would make of `part`, counting no further than `cap`: returns
/// cap + 1 once more would be needed, and also when the refinement fails (a part that cannot
/// be approximated is no better choice than any other). Deterministic. With `memo`, every cut
/// it makes is kept there (CutMemo::keep), for a later refinement of the same part to take.
/// \throws InvalidInputException unless options.tolerance > 0.
int count_strips(const Mesh& part, const RefineOptions& options, int cap = INT_MAX - 1,
                 const PieceLimits& limits = {}, CutMemo* memo = nullptr);

}  // namespace papercraft
