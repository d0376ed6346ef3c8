// merge.congruent — join flat strips whose shared boundary is congruent in the plane and
// whose union does not overlap (paper 3.4). merge.none keeps the strips as unfolded.
// Both need the whole model, so their input gathers every unfolded strip of it.
//
//   merge: {impl: merge.congruent, to: [layout]}

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/flat_boundary.h"
#include "core/piece_width.h"
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

// The pieces a person cannot handle, named in report.json and on stderr: those too small that
// no neighbour takes, and those narrower than min_width_mm over more than their tips. A piece
// glued to no other is a whole separate part of the model (a tooth, a claw, a button): no join
// can grow or widen it, only a larger print scale, and the note says so.
void note_unbuildable_pieces(ModelRun& model, const std::vector<FlatStrip>& strips,
                             const std::vector<int>& small) {
  const double scale = model.mm_per_unit();
  const PieceLimits limits = model.piece_limits();
  for (const FlatStrip& strip : strips) {
    const bool alone =
        std::none_of(strip.boundary.begin(), strip.boundary.end(), [&](const BoundaryEdge& e) {
          return e.kind == EdgeKind::Seam && e.neighbour_strip != strip.id;
        });
    const std::string why = alone ? ": it is a separate part of the model by itself (a larger "
                                    "--height or --scale prints it larger)"
                                  : "";
    if (std::find(small.begin(), small.end(), strip.id) != small.end()) {
      const std::string text = "flat strip " + std::to_string(strip.id) + " is " +
                               std::to_string(std::lround(flat_area(strip) * scale * scale)) +
                               " mm^2, below min_area_mm2" +
                               (alone ? why : ", and no neighbour takes it");
      model.note(text);
      spdlog::warn("{}: {}", model.name, text);
    }
    if (limits.min_width > 0.0) {
      const double narrow =
          narrow_area_fraction(strip.vertices2d, strip.triangles, limits.min_width);
      if (narrow > limits.max_narrow_share) {
        const std::string text = "flat strip " + std::to_string(strip.id) + " is narrower than " +
                                 "min_width_mm over " + std::to_string(std::lround(100 * narrow)) +
                                 "% of its area" + why;
        model.note(text);
        spdlog::warn("{}: {}", model.name, text);
      }
    }
  }
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
              at_least(0));
  registry.add({.name = "merge.congruent",
                .summary = "join flat strips along congruent shared boundaries",
                .input = MessageType::of<UnfoldedStrip>(),
                .gathers = true,
                .outputs = {{"out", MessageType::of<ModelStrips>()}},
                .params = table.specs(),
                .create = [](const Params& params, const NodeContext&) {
                  const MergeOptions options = table.read(params);
                  return make_body([options](const Envelope& in, Emitter& out) {
                    ModelStrips strips =
                        collect_model_strips(in.get<Gathered>().as<UnfoldedStrip>());
                    std::size_t twice = 0;
                    strips.flat = drop_double_covered_triangles(std::move(strips.flat), &twice);
                    if (twice > 0) {
                      const std::string text = "dropped " + std::to_string(twice) +
                                               (twice == 1 ? " triangle" : " triangles") +
                                               " that an earlier piece prints too (the same three "
                                               "points: the strips of two parts "
                                               "can both cover a stretch of surface between them)";
                      in.model->note(text);
                      spdlog::info("{}: {}", in.model->name, text);
                    }
                    strips.flat = merge_congruent(std::move(strips.flat), options);
                    const PieceLimits limits = in.model->piece_limits();
                    std::vector<int> small;
                    strips.flat = join_small_and_narrow_strips(
                        std::move(strips.flat), limits.min_area, limits.min_width, options, &small);
                    note_unbuildable_pieces(*in.model, strips.flat, small);
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
