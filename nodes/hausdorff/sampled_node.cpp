// hausdorff.sampled — Metro-like dense sampling (uncertified baseline, marked so in reports).
//
//   hausdorff: {impl: hausdorff.sampled, params: {face_samples: 100000},
//               to: {accept: [unfold], reject: [cut]}}

#include "graph/registry.h"
#include "nodes/hausdorff/verdict_node.h"

namespace papercraft {

void register_hausdorff_sampled(Registry& registry) {
  using O = RefineOptions;
  static const auto table = ParamTable<O>().add(
      "face_samples", [](O& o) -> auto& { return o.decide.sampling.face_samples; },
      "samples spread over each surface", at_least(1));
  registry.add(hausdorff_spec("hausdorff.sampled",
                              "sampled (Metro-like) Hausdorff decision; NOT certified", true,
                              table));
}

}  // namespace papercraft
