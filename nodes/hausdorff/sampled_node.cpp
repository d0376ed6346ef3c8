// hausdorff.sampled — Metro-like dense sampling (uncertified baseline, marked so in reports).
//
//   hausdorff: {impl: hausdorff.sampled, params: {face_samples: 100000},
//               to: {accept: [unfold], reject: [cut]}}

#include "graph/registry.h"
#include "nodes/hausdorff/emit_verdict.h"
#include "nodes/hausdorff/sampled.h"

namespace papercraft {

void register_hausdorff_sampled(Registry& registry) {
  registry.add(
      {"hausdorff.sampled",
       "sampled (Metro-like) Hausdorff decision; NOT certified",
       MessageType::of<StripCandidate>(),
       false,
       hausdorff_ports(),
       {{"face_samples", ParamType::Integer, "100000", "samples spread over each surface"}},
       [](const Params& params) {
         SampledHausdorffOptions options;
         options.face_samples = static_cast<std::size_t>(params.integer("face_samples"));
         return make_body([options](const Envelope& in, Emitter& out) {
           decide_and_emit(in, out, [&](const TriangleMesh& a, const TriangleMesh& b, double tau) {
             return sampled_hausdorff_within(a, b, tau, options);
           });
         });
       }});
}

}  // namespace papercraft
