// hausdorff.bounded — certified decision "two-sided H(part, strip) <= tolerance?"; on reject
// the located maximum error is the witness where the part is cut (the engine's third step).
//
//   hausdorff: {impl: hausdorff.bounded, params: {precision: 0.05},
//               to: {accept: [unfold], reject: [cut]}}

#include "graph/registry.h"
#include "nodes/hausdorff/verdict_node.h"

namespace papercraft {

void register_hausdorff_bounded(Registry& registry) {
  using O = RefineOptions;
  static const auto table =
      ParamTable<O>()
          .add("precision", [](O& o) -> auto& { return o.decide.bounded.precision; },
               "on reject, locate the maximum error to within precision x tolerance",
               greater_than(0))
          .add("max_evaluations", [](O& o) -> auto& { return o.decide.bounded.max_evaluations; },
               "cap on exact distance queries per decision (a tripped cap rejects)", at_least(1));
  registry.add(hausdorff_spec("hausdorff.bounded",
                              "certified two-sided Hausdorff decision (BVH, bounds, subdivision)",
                              false, table));
}

}  // namespace papercraft
