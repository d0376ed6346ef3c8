// ruled.twist_dp — the triangulated ruled surface between the candidate's two boundaries
// minimising the twist of the paper (section 3.2.2).
//
//   ruled: {impl: ruled.twist_dp, to: [hausdorff]}

#include "graph/messages.h"
#include "graph/registry.h"
#include "nodes/ruled/twist_dp.h"

namespace papercraft {

void register_ruled_twist_dp(Registry& registry) {
  registry.add({"ruled.twist_dp",
                "twist-minimising ruled strip (cyclic DP, O(n m log n))",
                MessageType::of<Candidate>(),
                false,
                {{"out", MessageType::of<StripCandidate>()}},
                {{"ruling_length_weight", ParamType::Number, "0.0001",
                  "weight of ruling length (relative) added to the twist cost to break ties"}},
                [](const Params& params) {
                  TwistOptions options;
                  options.ruling_length_weight = params.number("ruling_length_weight");
                  return make_body([options](const Envelope& in, Emitter& out) {
                    auto candidate = in.get_shared<Candidate>();
                    StripCandidate result;
                    result.candidate = candidate;
                    result.strip = std::make_shared<const RuledStrip>(
                        twist_minimizing_strip(candidate->a, candidate->b, options));
                    out.emit(0, std::move(result));
                  });
                }});
}

}  // namespace papercraft
