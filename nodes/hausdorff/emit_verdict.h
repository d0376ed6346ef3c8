#pragma once
// Shared by hausdorff.bounded and hausdorff.sampled: port 0 accept, port 1 reject.

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/node.h"
#include "nodes/hausdorff/decision.h"

namespace papercraft {

inline std::vector<OutputPort> hausdorff_ports() {
  return {{"accept", MessageType::of<AcceptedStrip>()},
          {"reject", MessageType::of<RejectedStrip>()}};
}

template <class Decide>
void decide_and_emit(const Envelope& in, Emitter& out, const Decide& decide) {
  const StripCandidate& candidate = in.get<StripCandidate>();
  const double tolerance = in.model->tolerance.load();
  const StripVerdict verdict =
      judge_strip(*candidate.candidate->part.mesh, *candidate.strip,
                  static_cast<int>(candidate.candidate->holes.size()), tolerance, decide);
  if (verdict.accept) {
    AcceptedStrip accepted;
    accepted.candidate = candidate.candidate;
    accepted.strip = candidate.strip;
    accepted.upper_bound = verdict.upper_bound;
    accepted.certified = verdict.certified;
    out.emit(0, std::move(accepted));
    return;
  }
  RejectedStrip rejected;
  rejected.candidate = candidate.candidate;
  rejected.strip = candidate.strip;
  rejected.witness = verdict.witness;
  rejected.witness_error = verdict.witness_error;
  rejected.witness_side = verdict.witness_side;
  rejected.witness_triangle = verdict.witness_triangle;
  rejected.hole = verdict.hole;
  out.emit(1, std::move(rejected));
}

}  // namespace papercraft
