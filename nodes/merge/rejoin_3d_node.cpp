// Joins in 3D: a short piece's part and a neighbour's glued along their cut and refined as one
// strip, each union judged by a merge of the whole model.
#include "nodes/merge/rejoin_3d_node.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "core/errors.h"
#include "engine/refine/rejoin.h"
#include "nodes/merge/piece_notes_node.h"

namespace papercraft {

namespace {

constexpr int kMostRejoins = 8;

}  // namespace

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
  std::optional<double> merged_effort;  // model_effort of `merged`, once measured
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
        const bool by_effort = options.mm_per_unit > 0.0;
        if (by_effort && !merged_effort) merged_effort = model_effort(merged, limits, options);
        const double effort_before = by_effort ? *merged_effort : 0.0;
        const double effort_after = by_effort ? model_effort(trial, limits, options) : 0.0;
        spdlog::debug(
            "{}: parts {} and {} are one strip ({} faces); pieces left short {} -> {}, effort "
            "{:.1f} -> {:.1f}",
            model.name, mine->candidate->part.path, other->candidate->part.path, accepted_faces,
            before, after, effort_before, effort_after);
        // Kept where it costs a person less (or, without a print scale, leaves fewer short).
        if (by_effort ? !(effort_after < effort_before) : after >= before) continue;
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
        merged_effort = effort_after;
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

Merged merge_with_rejoins(std::vector<std::shared_ptr<const UnfoldedStrip>> unfolded,
                          ModelRun& model, const MergeOptions& options,
                          const RefineOptions& refine) {
  const PieceLimits limits = model.piece_limits();
  MergeOptions shallow = options;
  shallow.most_band_pieces = std::min(options.most_band_pieces, 3);
  Merged merged = merge_model(unfolded, shallow, limits);
  merged = rejoin_in_3d(unfolded, std::move(merged), model, shallow, refine);
  const auto short_of = [&](const Merged& m) {
    return shortfalls(short_pieces(m, limits, options.narrow_join_share, model.mm_per_unit()),
                      options.narrow_join_share);
  };
  const int shallow_short = short_of(merged);
  if (options.most_band_pieces > shallow.most_band_pieces && shallow_short > 0) {
    Merged deep = merge_model(unfolded, options, limits);
    const int deep_short = short_of(deep);
    spdlog::debug("{}: pieces left short cutting bands in {}: {}, in {}: {}", model.name,
                  shallow.most_band_pieces, shallow_short, options.most_band_pieces, deep_short);
    const bool deeper = options.mm_per_unit > 0.0
                            ? model_effort(deep, limits, options) < model_effort(merged, limits, options)
                            : deep_short <= shallow_short;
    if (deeper) merged = std::move(deep);
  }
  return merged;
}

}  // namespace papercraft
