// merge.congruent — join flat strips whose shared boundary is congruent in the plane and
// whose union does not overlap (paper 3.4). merge.none keeps the strips as unfolded.
// Both need the whole model, so their input gathers every unfolded strip of it.
//
//   merge: {impl: merge.congruent, to: [layout]}

#include <algorithm>

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
  model.update([&](ModelRecord& r) {
    r.strips_3d = static_cast<int>(strips.strips3d.size());
    r.flat_strips_before_merge = static_cast<int>(strips.flat_before_merge);
    r.flat_strips = static_cast<int>(strips.flat.size());
    r.hausdorff_bound = bound;
    r.certified = certified;
  });
}

}  // namespace

void register_merge_congruent(Registry& registry) {
  using O = MergeOptions;
  static const auto table = ParamTable<O>().add(
      "congruence_tolerance", [](O& o) -> auto& { return o.congruence_tolerance; },
      "rigid-fit residual (relative to the strip size) below which two images of a boundary "
      "are congruent",
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
                    strips.flat = merge_congruent(std::move(strips.flat), options);
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
