#pragma once
// Shared by the hausdorff node adapters: the engine's decision (engine/refine/refine.h) on
// one (part, strip), emitted as an accept or a reject with the witness the cut needs.

#include "engine/refine/refine.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/node.h"
#include "graph/param_table.h"

namespace papercraft {

inline std::vector<OutputPort> hausdorff_ports() {
  return {{"accept", MessageType::of<AcceptedStrip>()},
          {"reject", MessageType::of<RejectedStrip>()}};
}

/// The spec of a hausdorff node deciding with `table`'s parameters and `sampled`.
inline NodeSpec hausdorff_spec(std::string name, std::string summary, bool sampled,
                               const ParamTable<RefineOptions>& table) {
  return refinement_stage(
      {.name = std::move(name),
       .summary = std::move(summary),
       .input = MessageType::of<StripCandidate>(),
       .outputs = hausdorff_ports(),
       .params = table.specs()},
      [sampled, &table](const Params& params, RefineOptions& refine) {
        refine = table.read(params, refine);
        refine.decide.sampled = sampled;
      },
      [](const RefineOptions& refine) {
        return make_body([refine](const Envelope& in, Emitter& out) {
          const StripCandidate& candidate = in.get<StripCandidate>();
          const StripVerdict verdict =
              decide_strip(*candidate.candidate->part.mesh, *candidate.candidate, *candidate.strip,
                           at_tolerance(refine, in.model->refinement_tolerance()));
          if (verdict.accept) {
            AcceptedStrip accepted;
            accepted.candidate = candidate.candidate;
            accepted.strip = candidate.strip;
            accepted.upper_bound = verdict.upper_bound;
            accepted.certified = verdict.certified;
            out.emit("accept", std::move(accepted));
            return;
          }
          RejectedStrip rejected;
          rejected.candidate = candidate.candidate;
          rejected.strip = candidate.strip;
          rejected.verdict = verdict;
          out.emit("reject", std::move(rejected));
        });
      });
}

}  // namespace papercraft
