// merge.congruent — join flat strips whose shared boundary is congruent in the plane and
// whose union does not overlap (paper 3.4). merge.none keeps the strips as unfolded.
// Both need the whole model, so their input gathers every unfolded strip of it.
//
//   merge: {impl: merge.congruent, to: [layout]}

#include <utility>

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/merge/collect_node.h"
#include "nodes/merge/congruent.h"
#include "nodes/merge/piece_notes_node.h"
#include "nodes/merge/rejoin_3d_node.h"

namespace papercraft {

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
                  const MergeOptions read = table.read(params);
                  const RefineOptions refine = context.refine;
                  return make_body([read, refine](const Envelope& in, Emitter& out) {
                    MergeOptions options = read;  // judged by the effort at the model's scale
                    options.mm_per_unit = in.model->mm_per_unit();
                    options.weights = in.model->settings->effort;
                    Merged merged = merge_with_rejoins(in.get<Gathered>().as<UnfoldedStrip>(),
                                                       *in.model, options, refine);
                    note_double_cover(*in.model, merged.twice);
                    ModelStrips strips = std::move(merged.strips);
                    note_unbuildable_pieces(*in.model, strips.flat, merged.small);
                    record_model_strips(*in.model, strips);
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
                    record_model_strips(*in.model, strips);
                    out.emit("out", std::move(strips));
                  });
                }});
}

}  // namespace papercraft
