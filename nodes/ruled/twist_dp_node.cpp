// ruled.twist_dp — the triangulated ruled surface between the candidate's two boundaries
// minimising the twist of the paper (section 3.2.2; the engine's second step).
//
//   ruled: {impl: ruled.twist_dp, to: [hausdorff]}

#include "engine/refine/refine.h"
#include "graph/messages.h"
#include "graph/param_table.h"
#include "graph/registry.h"

namespace papercraft {

void register_ruled_twist_dp(Registry& registry) {
  using O = RefineOptions;
  static const auto table = ParamTable<O>().add(
      "ruling_length_weight", [](O & o) -> auto& { return o.twist.ruling_length_weight; },
      "weight of ruling length (relative) added to the twist cost to break ties", at_least(0));
  registry.add(refinement_stage(
      {.name = "ruled.twist_dp",
       .summary = "twist-minimising ruled strip (cyclic DP, O(n m log n))",
       .input = MessageType::of<Candidate>(),
       .outputs = {{"out", MessageType::of<StripCandidate>()}},
       .params = table.specs()},
      [](const Params& params, RefineOptions& refine) { refine = table.read(params, refine); },
      [](const RefineOptions& refine) {
        return make_body([refine](const Envelope& in, Emitter& out) {
          auto candidate = in.get_shared<Candidate>();
          StripCandidate result;
          result.candidate = candidate;
          result.strip = std::make_shared<const RuledStrip>(
              build_strip(*candidate->part.mesh, *candidate, refine));
          out.emit("out", std::move(result));
        });
      }));
}

}  // namespace papercraft
