// hausdorff.bounded — certified decision "two-sided H(part, strip) <= tolerance?"; on reject
// the located maximum error is the witness where the part is cut.
//
//   hausdorff: {impl: hausdorff.bounded, params: {precision: 0.05},
//               to: {accept: [unfold], reject: [cut]}}

#include "graph/registry.h"
#include "nodes/hausdorff/emit_verdict.h"

namespace papercraft {

void register_hausdorff_bounded(Registry& registry) {
  registry.add(
      {"hausdorff.bounded",
       "certified two-sided Hausdorff decision (BVH, bounds, subdivision)",
       MessageType::of<StripCandidate>(),
       false,
       hausdorff_ports(),
       {{"precision", ParamType::Number, "0.05",
         "on reject, locate the maximum error to within precision x tolerance"},
        {"max_evaluations", ParamType::Integer, "20000000",
         "cap on exact distance queries per decision (a tripped cap rejects)"}},
       [](const Params& params) {
         BoundedHausdorffOptions options;
         options.precision = params.number("precision");
         options.max_evaluations = static_cast<std::size_t>(params.integer("max_evaluations"));
         return make_body([options](const Envelope& in, Emitter& out) {
           decide_and_emit(in, out, [&](const TriangleMesh& a, const TriangleMesh& b, double tau) {
             return certified_hausdorff_within(a, b, tau, options);
           });
         });
       }});
}

}  // namespace papercraft
