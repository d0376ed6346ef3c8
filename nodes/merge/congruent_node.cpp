// merge.congruent — join flat strips whose shared boundary is congruent in the plane and
// whose union does not overlap (paper 3.4). merge.none keeps the strips as unfolded.
// Both need the whole model, so their input gathers every unfolded strip of it.
//
//   merge: {impl: merge.congruent, to: [layout]}

#include <algorithm>

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"
#include "nodes/merge/collect.h"
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
  model.set_result("strips_3d", static_cast<double>(strips.strips3d.size()));
  model.set_result("flat_strips_before_merge", static_cast<double>(strips.flat_before_merge));
  model.set_result("flat_strips", static_cast<double>(strips.flat.size()));
  model.set_result("hausdorff_bound", bound);
  model.set_result("certified", certified ? 1.0 : 0.0);
}

}  // namespace

void register_merge_congruent(Registry& registry) {
  registry.add({"merge.congruent",
                "join flat strips along congruent shared boundaries",
                MessageType::of<UnfoldedStrip>(),
                true,
                {{"out", MessageType::of<ModelStrips>()}},
                {{"congruence_tolerance", ParamType::Number, "1e-6",
                  "rigid-fit residual (relative to the strip size) below which two images of a "
                  "boundary are congruent"}},
                [](const Params& params) {
                  MergeOptions options;
                  options.congruence_tolerance = params.number("congruence_tolerance");
                  return make_body([options](const Envelope& in, Emitter& out) {
                    ModelStrips strips =
                        collect_model_strips(in.get<Gathered>().as<UnfoldedStrip>());
                    strips.flat = merge_congruent(std::move(strips.flat), options);
                    record(*in.model, strips);
                    out.emit(0, std::move(strips));
                  });
                }});
  registry.add({"merge.none",
                "keep every flat strip as unfolded (seams labelled)",
                MessageType::of<UnfoldedStrip>(),
                true,
                {{"out", MessageType::of<ModelStrips>()}},
                {},
                [](const Params&) {
                  return make_body([](const Envelope& in, Emitter& out) {
                    ModelStrips strips =
                        collect_model_strips(in.get<Gathered>().as<UnfoldedStrip>());
                    record(*in.model, strips);
                    out.emit(0, std::move(strips));
                  });
                }});
}

}  // namespace papercraft
