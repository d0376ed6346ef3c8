// merge.congruent — join flat strips whose shared boundary is congruent in the plane and
// whose union does not overlap (paper 3.4). merge.none keeps the strips as unfolded.
// Both need the whole model, so their input gathers every unfolded strip of it.
//
//   merge: {impl: merge.congruent, to: [layout]}

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "core/piece_width.h"
#include "engine/refine/rejoin.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/merge/collect_node.h"
#include "nodes/merge/congruent.h"

namespace papercraft {

namespace {

void record(ModelRun& model, const ModelStrips& strips) {
  double bound = 0.0;
  bool certified = true;
  for (const auto& s : strips.strips3d) {
    bound = std::max(bound, s->upper_bound);
    certified = certified && s->certified;
  }
  // H(strips, input) <= H(strips, proxy) + H(proxy, input); without a proxy the second is 0.
  const double proxy_distance = model.proxy_distance();
  model.update([&](ModelRecord& r) {
    r.strips_3d = static_cast<int>(strips.strips3d.size());
    r.flat_strips_before_merge = static_cast<int>(strips.flat_before_merge);
    r.flat_strips = static_cast<int>(strips.flat.size());
    r.strips_bound = bound;
    r.hausdorff_bound = bound + proxy_distance;
    r.certified = certified;
  });
}

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

// The pieces a person cannot handle, named in report.json and on stderr: those too small that
// no neighbour takes, and those narrower than min_width_mm over more than their tips. A piece
// glued to no other is a whole separate part of the model (a tooth, a claw, a button): no join
// can grow or widen it, only a larger print scale, and the note says so. One that no fold onto
// a neighbour lays flat is said to be so (why_no_hinge).
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

// One merge of a model's unfolded strips: the triangles printed twice dropped, congruent
// boundaries merged, crumbs and narrow pieces joined in the plane.
struct Merged {
  ModelStrips strips;
  std::vector<int> small;  // ids of the flat strips left under min_area
  std::size_t twice = 0;   // triangles printed twice, dropped
};

Merged merge_model(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded,
                   const MergeOptions& options, const PieceLimits& limits) {
  Merged merged;
  merged.strips = collect_model_strips(std::move(unfolded));
  merged.strips.flat = drop_double_covered_triangles(std::move(merged.strips.flat), &merged.twice);
  merged.strips.flat = merge_congruent(std::move(merged.strips.flat), options);
  merged.strips.flat = join_small_and_narrow_strips(std::move(merged.strips.flat), limits.min_area,
                                                    limits.min_width, options, &merged.small);
  return merged;
}

double narrow_share(const FlatStrip& strip, const PieceLimits& limits) {
  return limits.min_width > 0.0
             ? narrow_area_fraction(strip.vertices2d, strip.triangles, limits.min_width)
             : 0.0;
}

// A piece glued to another that is too small, or too narrow (over more than the share past
// which the merge hinges a narrow piece on).
struct Short {
  std::size_t source;  // its 3D strip
  bool small;
  double narrow;  // share of its area narrower than min_width
  double area_mm2;
};

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

// Each limit a short piece misses counts once.
int shortfalls(const std::vector<Short>& shorts, double narrow_bound) {
  int count = 0;
  for (const Short& piece : shorts) count += piece.small + (piece.narrow > narrow_bound);
  return count;
}

// Where a piece is left too small or too narrow beside a neighbour, its 3D part and a
// neighbouring part, glued back along the cut between them, may be one strip within the
// tolerance after all: the cut that parted them was made higher up, for a larger part that was
// not. Such a union, refined and certified as the graph refines a part, that unfolds in one
// piece replaces the two strips, and the model is merged again; the change is kept when fewer
// pieces are left too small or too narrow. At most kMostRejoins unions per model, and at most
// options.most_rejoin_trials merges of the whole model to judge them (a note says where that
// budget ran out). `unfolded` is left as the strips of the merge returned (the unions in place
// of the parts they join).
constexpr int kMostRejoins = 8;

Merged rejoin_in_3d(std::vector<std::shared_ptr<const UnfoldedStrip>>& unfolded, Merged merged,
                    ModelRun& model, const MergeOptions& options, const RefineOptions& refine) {
  const PieceLimits limits = model.piece_limits();
  const double scale = model.mm_per_unit();
  // The decision at the model's tolerance, not where the worst point lies.
  RefineOptions decide_only = at_tolerance(refine, model.refinement_tolerance());
  decide_only.decide.bounded.locate_maximum = false;
  std::set<std::pair<const AcceptedStrip*, const AcceptedStrip*>> tried;
  int trials = 0;  // whole-model merges judged
  bool out_of_budget = false;
  for (int round = 0; round < kMostRejoins && !out_of_budget; ++round) {
    const std::vector<Short> shorts =
        short_pieces(merged, limits, options.narrow_join_share, scale);
    const int before = shortfalls(shorts, options.narrow_join_share);
    if (before == 0) break;
    bool improved = false;
    const auto strips3d = merged.strips.strips3d;
    for (const Short& piece : shorts) {
      const auto& mine = strips3d[piece.source];
      for (std::size_t j = 0; j < strips3d.size() && !improved; ++j) {
        const auto& other = strips3d[j];
        if (j == piece.source || !tried.insert({mine.get(), other.get()}).second) continue;
        std::optional<Mesh> glued;
        std::optional<JoinedStrip> one;
        try {
          glued = glue_pieces(*mine->candidate->part.mesh, *other->candidate->part.mesh);
          if (glued) one = one_strip_of(*glued, decide_only);
        } catch (const InvalidInputException& e) {
          spdlog::debug("{}: parts {} and {} glued: {}", model.name, mine->candidate->part.path,
                        other->candidate->part.path, e.what());
        }
        if (!one) continue;
        if (trials == options.most_rejoin_trials) {
          out_of_budget = true;
          break;
        }
        ++trials;
        const std::size_t accepted_faces = glued->n_faces();
        // The union takes the place (the path) of the earlier of the two.
        const Part& first = (j < piece.source ? other : mine)->candidate->part;
        auto candidate = std::make_shared<Candidate>();
        static_cast<StripBoundaries&>(*candidate) = std::move(one->refined.boundaries);
        candidate->part = first;
        candidate->part.mesh = std::make_shared<const Mesh>(std::move(*glued));
        candidate->part.depth = std::min(mine->candidate->part.depth, other->candidate->part.depth);
        auto accepted = std::make_shared<AcceptedStrip>();
        accepted->candidate = std::move(candidate);
        accepted->strip = std::make_shared<const RuledStrip>(std::move(one->refined.strip));
        accepted->upper_bound = one->refined.verdict.upper_bound;
        accepted->certified = one->refined.verdict.certified;
        auto joined = std::make_shared<UnfoldedStrip>();
        joined->strip = std::move(accepted);
        joined->flat.push_back(std::move(one->flat));
        std::vector<std::shared_ptr<const UnfoldedStrip>> trial_unfolded;
        for (const auto& u : unfolded)
          if (u->strip != mine && u->strip != other) trial_unfolded.push_back(u);
        trial_unfolded.push_back(std::move(joined));
        Merged trial = merge_model(trial_unfolded, options, limits);
        const int after = shortfalls(short_pieces(trial, limits, options.narrow_join_share, scale),
                                     options.narrow_join_share);
        spdlog::debug("{}: parts {} and {} are one strip ({} faces); pieces left short {} -> {}",
                      model.name, mine->candidate->part.path, other->candidate->part.path,
                      accepted_faces, before, after);
        if (after >= before) continue;
        std::ostringstream text;
        text << "refined the part of a piece of " << std::lround(piece.area_mm2) << " mm^2"
             << (piece.narrow > options.narrow_join_share
                     ? ", narrower than min_width_mm over " +
                           std::to_string(std::lround(100 * piece.narrow)) + "% of its area,"
                     : std::string(","))
             << " together with its neighbour's: glued along their cut, the two are one strip "
                "within the tolerance (certified bound "
             << one->refined.verdict.upper_bound * scale << " mm), so they print as one piece";
        model.note(text.str());
        spdlog::info("{}: {}", model.name, text.str());
        unfolded = std::move(trial_unfolded);
        merged = std::move(trial);
        improved = true;
      }
      if (improved || out_of_budget) break;
    }
    if (!improved) break;
  }
  if (out_of_budget) {
    const std::string text =
        "joins in 3D: stopped after " + std::to_string(trials) +
        (trials == 1 ? " merge" : " merges") +
        " of the whole model to judge them (most_rejoin_trials); " +
        std::to_string(shortfalls(short_pieces(merged, limits, options.narrow_join_share, scale),
                                  options.narrow_join_share)) +
        " piece limits still missed";
    model.note(text);
    spdlog::info("{}: {}", model.name, text);
  }
  return merged;
}

}  // namespace

void register_merge_congruent(Registry& registry) {
  using O = MergeOptions;
  static const auto table =
      ParamTable<O>()
          .add(
              "congruence_tolerance", [](O & o) -> auto& { return o.congruence_tolerance; },
              "rigid-fit residual (relative to the strip size) below which two images of a "
              "boundary are congruent",
              at_least(0))
          .add(
              "narrow_join_share", [](O & o) -> auto& { return o.narrow_join_share; },
              "a piece narrower than min_width_mm over more than this share of its area is "
              "hinged onto a wider neighbour (1: never)",
              between(0, 1))
          .add(
              "modest_join_factor", [](O & o) -> auto& { return o.modest_join_factor; },
              "a piece under this times min_area_mm2 is hinged onto a neighbour where the union "
              "lies flat (<= 1: never)",
              at_least(0))
          .add(
              "most_rejoin_trials", [](O & o) -> auto& { return o.most_rejoin_trials; },
              "joins in 3D judged per model, each by a merge of the whole model (0: none)",
              at_least(0));
  registry.add({.name = "merge.congruent",
                .summary = "join flat strips along congruent shared boundaries",
                .input = MessageType::of<UnfoldedStrip>(),
                .gathers = true,
                .outputs = {{"out", MessageType::of<ModelStrips>()}},
                .params = table.specs(),
                .create = [](const Params& params, const NodeContext& context) {
                  const MergeOptions options = table.read(params);
                  const RefineOptions refine = context.refine;
                  return make_body([options, refine](const Envelope& in, Emitter& out) {
                    const PieceLimits limits = in.model->piece_limits();
                    auto unfolded = in.get<Gathered>().as<UnfoldedStrip>();
                    // Joins in 3D are tried against a merge that cuts a band in three at
                    // most: a band cut in four, each piece hinged onto a neighbour, leaves
                    // many seams of a piece with itself where a join in 3D leaves none
                    // (ChineseDragon-10kv: one piece with 101 such seams instead of 51). The
                    // full depth is then used where pieces are still left short, and kept
                    // unless it leaves more of them short.
                    MergeOptions shallow = options;
                    shallow.most_band_pieces = std::min(options.most_band_pieces, 3);
                    Merged merged = merge_model(unfolded, shallow, limits);
                    merged = rejoin_in_3d(unfolded, std::move(merged), *in.model, shallow, refine);
                    const auto short_of = [&](const Merged& m) {
                      return shortfalls(short_pieces(m, limits, options.narrow_join_share,
                                                     in.model->mm_per_unit()),
                                        options.narrow_join_share);
                    };
                    const int shallow_short = short_of(merged);
                    if (options.most_band_pieces > shallow.most_band_pieces && shallow_short > 0) {
                      Merged deep = merge_model(unfolded, options, limits);
                      const int deep_short = short_of(deep);
                      spdlog::debug("{}: pieces left short cutting bands in {}: {}, in {}: {}",
                                    in.model->name, shallow.most_band_pieces, shallow_short,
                                    options.most_band_pieces, deep_short);
                      if (deep_short <= shallow_short) merged = std::move(deep);
                    }
                    if (merged.twice > 0) {
                      const std::string text = "dropped " + std::to_string(merged.twice) +
                                               (merged.twice == 1 ? " triangle" : " triangles") +
                                               " that an earlier piece prints too (the same three "
                                               "points: the strips of two parts "
                                               "can both cover a stretch of surface between them)";
                      in.model->note(text);
                      spdlog::info("{}: {}", in.model->name, text);
                    }
                    ModelStrips strips = std::move(merged.strips);
                    note_unbuildable_pieces(*in.model, strips.flat, merged.small);
                    record(*in.model, strips);
                    out.emit("out", std::move(strips));
                  });
                }});
  registry.add({.name = "merge.none",
                .summary = "keep every flat strip as unfolded (seams labelled)",
                .input = MessageType::of<UnfoldedStrip>(),
                .gathers = true,
                .outputs = {{"out", MessageType::of<ModelStrips>()}},
                .create = [](const Params&, const NodeContext&) {
                  return make_body([](const Envelope& in, Emitter& out) {
                    ModelStrips strips =
                        collect_model_strips(in.get<Gathered>().as<UnfoldedStrip>());
                    record(*in.model, strips);
                    out.emit("out", std::move(strips));
                  });
                }});
}

}  // namespace papercraft
