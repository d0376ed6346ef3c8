#include "engine/refine/refine.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <exception>
#include <sstream>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "engine/refine/exhaustive_select.h"
#include "engine/ruled/part_strip.h"
#include "engine/unfold/sequential.h"

namespace papercraft {

namespace {

void require_tolerance(const RefineOptions& options, const char* step) {
  if (!(options.tolerance > 0.0)) {
    throw InvalidInputException(std::string(step) +
                                ": the refinement needs a positive tolerance (RefineOptions::"
                                "tolerance), got " +
                                std::to_string(options.tolerance));
  }
}

}  // namespace

RefineOptions at_tolerance(RefineOptions options, double tolerance) {
  options.tolerance = tolerance;
  return options;
}

StripBoundaries select_strip_boundaries(const Mesh& part, const RefineOptions& options) {
  require_tolerance(options, "select_strip_boundaries");
  BoundarySelection selection;
  if (options.select.exhaustive) {
    ExhaustiveSelectOptions exhaustive;
    exhaustive.error_bound = options.select.precision * options.tolerance;
    exhaustive.twist = options.twist;
    exhaustive.decide = options.decide;
    selection = select_exhaustive(part, exhaustive);
  } else {
    selection = select_geodesic(part, options.select.geodesic);
  }
  StripBoundaries boundaries;
  boundaries.first = std::move(selection.first);
  boundaries.second = std::move(selection.second);
  boundaries.first_closed = selection.first_closed;
  boundaries.second_closed = selection.second_closed;
  boundaries.a = selection_polyline(part, boundaries.first, boundaries.first_closed);
  boundaries.b = selection_polyline(part, boundaries.second, boundaries.second_closed);
  auto used = [&](const std::vector<int>& loop) {
    // A loop side, or one of the two open chains a loop is split into (more than a vertex).
    auto chosen = [&](const std::vector<int>& side, bool closed) {
      return (closed || side.size() > 1) &&
             std::find(side.begin(), side.end(), loop.front()) != side.end();
    };
    return chosen(boundaries.first, boundaries.first_closed) ||
           chosen(boundaries.second, boundaries.second_closed);
  };
  for (auto& loop : boundary_loops(part)) {
    if (!used(loop)) boundaries.holes.push_back(std::move(loop));
  }
  return boundaries;
}

RuledStrip build_strip(const Mesh& part, const StripBoundaries& boundaries,
                       const RefineOptions& options) {
  return part_strip(part, boundaries.first, boundaries.a, boundaries.second, boundaries.b,
                    options.twist);
}

StripVerdict decide_strip(const Mesh& part, const StripBoundaries& boundaries,
                          const RuledStrip& strip, const RefineOptions& options) {
  require_tolerance(options, "decide_strip");
  return judge_strip(part, strip, static_cast<int>(boundaries.holes.size()), options.tolerance,
                     options.decide);
}

std::optional<double> one_flat_strip_area(const Mesh& piece, const RefineOptions& options) {
  const std::optional<JoinedStrip> one = one_strip_of(piece, options);
  if (!one) return std::nullopt;
  return flat_area(one->flat);
}

std::optional<JoinedStrip> one_strip_of(const Mesh& piece, const RefineOptions& options) {
  JoinedStrip one;
  RefinedStrip& refined = one.refined;
  refined.boundaries = select_strip_boundaries(piece, options);
  // A hole left over is a rejection (judge_strip), known before the strip is built.
  if (!refined.boundaries.holes.empty()) return std::nullopt;
  refined.strip = build_strip(piece, refined.boundaries, options);
  if (refined.strip.mesh.empty()) return std::nullopt;
  std::vector<FlatStrip> flat = unfold_strip(refined.strip, 0, 0);
  if (flat.size() != 1) return std::nullopt;
  refined.verdict = decide_strip(piece, refined.boundaries, refined.strip, options);
  if (!refined.verdict.accept) return std::nullopt;
  one.flat = std::move(flat.front());
  return one;
}

std::vector<Mesh> cut_rejected_piece(const Mesh& part, const StripBoundaries& boundaries,
                                     const StripVerdict& verdict, int depth,
                                     const RefineOptions& options, const std::string& part_name,
                                     const PieceLimits& limits) {
  require_tolerance(options, "cut_rejected_piece");
  const double tolerance = options.tolerance;
  auto fail = [&](const std::string& why) {
    std::ostringstream message;
    message << "part " << part_name << " (" << part.n_faces()
            << " faces) cannot be approximated within the tolerance " << tolerance << ": " << why
            << "; worst error " << verdict.witness_error << " at (" << verdict.witness.x() << ", "
            << verdict.witness.y() << ", " << verdict.witness.z()
            << "). The tolerance may be below the mesh's resolution: try a larger --tolerance.";
    throw ApproximationException(message.str());
  };
  if (depth >= options.max_depth) {
    fail("reached " + std::to_string(options.max_depth) + " nested cuts (max_depth)");
  }
  const std::vector<int>* hole = verdict.hole >= 0 ? &boundaries.holes[verdict.hole] : nullptr;
  // Look ahead for pieces too small to be cut again: is one a strip within the tolerance
  // that lies flat in one piece, and how large is that piece on paper?
  RefineOptions quick = options;
  quick.decide.bounded.locate_maximum = false;  // the decision only
  auto one_strip = [&](const Mesh& piece) { return one_flat_strip_area(piece, quick); };
  // And how many holes would a piece have, each to be cut through again?
  auto holes = [&](const Mesh& piece) {
    return static_cast<int>(select_strip_boundaries(piece, quick).holes.size());
  };
  WitnessCut cut =
      cut_rejected_part(part, boundaries.first, boundaries.first_closed, boundaries.second,
                        boundaries.second_closed, hole, verdict.witness, tolerance, options.cut,
                        options.twist, options.decide, limits, one_strip, holes);
  if (spdlog::should_log(spdlog::level::debug)) {
    std::string shortfalls;
    for (const Mesh& piece : cut.pieces)
      shortfalls += " " + std::to_string(piece_shortfall_ahead(piece, limits, one_strip));
    spdlog::debug(
        "cut part {} ({} faces, {} holes, hole {}, error {:.4g}) at {} = {:.4f} into {} (limit "
        "shortfalls{})",
        part_name, part.n_faces(), boundaries.holes.size(), verdict.hole, verdict.witness_error,
        cut.across ? "g" : "f", cut.value, cut.pieces.size(), shortfalls);
  }
  if (cut.pieces.empty()) fail("no iso-line through the worst point splits it");
  return std::move(cut.pieces);
}

namespace {

struct Pending {
  Mesh piece;
  std::string path;
  int depth = 0;
};

// Depth first through the refinement of `root`. `accept(pending, boundaries, strip, verdict)`
// takes each accepted strip and returns false to stop; `room(pending_count)` is asked after
// each cut and returns false to stop; `memo`, where given, keeps every cut. Returns false when
// stopped.
template <class Accept, class Room>
bool refine_depth_first(const Mesh& root, const RefineOptions& options, const PieceLimits& limits,
                        Accept accept, Room room, CutMemo* memo = nullptr) {
  std::vector<Pending> stack;
  stack.push_back({root, "", 0});
  while (!stack.empty()) {
    Pending item = std::move(stack.back());
    stack.pop_back();
    StripBoundaries boundaries = select_strip_boundaries(item.piece, options);
    RuledStrip strip = build_strip(item.piece, boundaries, options);
    StripVerdict verdict = decide_strip(item.piece, boundaries, strip, options);
    if (verdict.accept) {
      if (!accept(std::move(item), std::move(boundaries), std::move(strip), verdict)) return false;
      continue;
    }
    std::vector<Mesh> pieces =
        cut_rejected_piece(item.piece, boundaries, verdict, item.depth, options,
                           item.path.empty() ? "(whole)" : item.path, limits);
    if (memo) memo->keep(item.piece, boundaries, verdict, pieces);
    if (!room(stack.size() + pieces.size())) return false;
    // Pushed last first, so the pieces are refined in cut order.
    for (std::size_t i = pieces.size(); i-- > 0;) {
      stack.push_back({std::move(pieces[i]), item.path + "." + std::to_string(i), item.depth + 1});
    }
  }
  return true;
}

}  // namespace

std::vector<RefinedStrip> refine_part(const Mesh& part, const RefineOptions& options,
                                      const PieceLimits& limits) {
  std::vector<RefinedStrip> strips;
  refine_depth_first(
      part, options, limits,
      [&](Pending&& item, StripBoundaries&& boundaries, RuledStrip&& strip,
          const StripVerdict& verdict) {
        strips.push_back({std::move(item.piece), std::move(item.path), item.depth,
                          std::move(boundaries), std::move(strip), verdict});
        return true;
      },
      [](std::size_t) { return true; });
  return strips;
}

int count_strips(const Mesh& part, const RefineOptions& options, int cap, const PieceLimits& limits,
                 CutMemo* memo) {
  require_tolerance(options, "count_strips");  // a caller's mistake, not a part's failure
  int strips = 0;
  try {
    const bool finished = refine_depth_first(
        part, options, limits,
        [&](Pending&&, StripBoundaries&&, RuledStrip&&, const StripVerdict&) {
          return ++strips <= cap;
        },
        // Every piece still to refine makes at least one strip.
        [&](std::size_t pending) { return strips + static_cast<long>(pending) <= cap; }, memo);
    return finished ? strips : cap + 1;
  } catch (const std::exception&) {
    return cap + 1;
  }
}

}  // namespace papercraft
