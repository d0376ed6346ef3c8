// The merge node's notes on the pieces it leaves, and its count of pieces left short.
#include "nodes/merge/piece_notes_node.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "core/flat_boundary.h"
#include "core/piece_effort.h"
#include "core/piece_width.h"

namespace papercraft {

namespace {

// Whether a seam glues the piece to another piece.
bool glued_to_another(const FlatStrip& strip) {
  return std::any_of(strip.boundary.begin(), strip.boundary.end(), [&](const BoundaryEdge& e) {
    return e.kind == EdgeKind::Seam && e.neighbour_strip != strip.id;
  });
}

// Why no hinge takes a piece glued to others: where, folded out of each neighbour over each
// edge they share, it lies over that neighbour, says so, and names the neighbour whose seam with
// it runs round the widest saddle of the surface (corners round a vertex of the seam summing to
// over 360 degrees), if any. Empty where some fold lies flat (a hinge failed for another
// reason: the union narrower, or over a third piece).
std::string why_no_hinge(const FlatStrip& strip, const std::vector<FlatStrip>& strips) {
  std::set<int> neighbours;
  for (const BoundaryEdge& e : strip.boundary)
    if (e.kind == EdgeKind::Seam && e.neighbour_strip != strip.id)
      neighbours.insert(e.neighbour_strip);
  int widest_with = -1;
  double widest = 360.5;  // below that, rounding
  for (int id : neighbours) {
    auto it = std::find_if(strips.begin(), strips.end(),
                           [&](const FlatStrip& other) { return other.id == id; });
    if (it == strips.end() || folds_flat_onto(strip, *it)) return "";
    const double degrees = widest_corner_round_a_seam_vertex(strip, *it);
    if (degrees > widest) widest = degrees, widest_with = id;
  }
  if (neighbours.empty()) return "";
  std::string text = ": folded out of a neighbour over any edge they share, it would lie over it";
  if (widest_with >= 0)
    text += " (its seam with flat strip " + std::to_string(widest_with) +
            " runs round a saddle of the surface: their corners round one vertex sum to " +
            std::to_string(std::lround(widest)) + " degrees)";
  return text;
}

double narrow_share(const FlatStrip& strip, const PieceLimits& limits) {
  return limits.min_width > 0.0
             ? narrow_area_fraction(strip.vertices2d, strip.triangles, limits.min_width)
             : 0.0;
}

}  // namespace

void note_unbuildable_pieces(ModelRun& model, const std::vector<FlatStrip>& strips,
                             const std::vector<int>& small) {
  const double scale = model.mm_per_unit();
  const PieceLimits limits = model.piece_limits();
  for (const FlatStrip& strip : strips) {
    const bool alone = !glued_to_another(strip);
    // Said only of a piece noted, once: the folds it tries cost a grid of each neighbour.
    std::optional<std::string> said;
    const auto why = [&]() -> const std::string& {
      if (!said)
        said = alone ? ": it is a separate part of the model by itself (a larger --height or "
                       "--scale prints it larger)"
                     : why_no_hinge(strip, strips);
      return *said;
    };
    if (std::find(small.begin(), small.end(), strip.id) != small.end()) {
      const std::string text = "flat strip " + std::to_string(strip.id) + " is " +
                               std::to_string(std::lround(flat_area(strip) * scale * scale)) +
                               " mm^2, below min_area_mm2" +
                               (alone ? why() : ", and no neighbour takes it" + why());
      model.note(text);
      spdlog::warn("{}: {}", model.name, text);
    }
    if (limits.min_width > 0.0) {
      const double narrow =
          narrow_area_fraction(strip.vertices2d, strip.triangles, limits.min_width);
      if (narrow > limits.max_narrow_share) {
        const std::string text = "flat strip " + std::to_string(strip.id) + " is narrower than " +
                                 "min_width_mm over " + std::to_string(std::lround(100 * narrow)) +
                                 "% of its area" + why();
        model.note(text);
        spdlog::warn("{}: {}", model.name, text);
      }
    }
  }
}

void note_double_cover(ModelRun& model, std::size_t twice) {
  if (twice == 0) return;
  const std::string text = "dropped " + std::to_string(twice) +
                           (twice == 1 ? " triangle" : " triangles") +
                           " that an earlier piece prints too (the same three points: the strips "
                           "of two parts can both cover a stretch of surface between them)";
  model.note(text);
  spdlog::info("{}: {}", model.name, text);
}

std::vector<Short> short_pieces(const Merged& merged, const PieceLimits& limits,
                                double narrow_bound, double mm_per_unit) {
  std::vector<Short> shorts;
  for (const FlatStrip& strip : merged.strips.flat) {
    if (!glued_to_another(strip)) continue;
    const bool small =
        std::find(merged.small.begin(), merged.small.end(), strip.id) != merged.small.end();
    const double narrow = narrow_share(strip, limits);
    if (small || narrow > narrow_bound)
      shorts.push_back({static_cast<std::size_t>(strip.source_strip), small, narrow,
                        flat_area(strip) * mm_per_unit * mm_per_unit});
  }
  return shorts;
}

int shortfalls(const std::vector<Short>& shorts, double narrow_bound) {
  int count = 0;
  for (const Short& piece : shorts) count += piece.small + (piece.narrow > narrow_bound);
  return count;
}

double model_effort(const Merged& merged, const PieceLimits& limits, const MergeOptions& options) {
  const std::vector<FlatStrip>& flat = merged.strips.flat;
  std::vector<int> all(flat.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const double scale = options.mm_per_unit;
  EffortTerms terms = local_effort_terms(flat, all,
                                         {.mm_per_unit = scale,
                                          .min_area_mm2 = limits.min_area * scale * scale,
                                          .weights = options.weights});
  for (const FlatStrip& strip : flat)
    terms.narrow_pieces += narrow_share(strip, limits) > limits.max_narrow_share;
  return effort_total(terms, options.weights);
}

}  // namespace papercraft
