// unfold.sequential — isometric unfolding of an accepted strip, triangle after triangle; a
// new flat strip starts where the next triangle would overlap the placed ones.
//
//   unfold: {impl: unfold.sequential, to: [merge]}

#include "engine/unfold/sequential.h"
#include "graph/messages.h"
#include "graph/param_table.h"
#include "graph/registry.h"

namespace papercraft {

void register_unfold_sequential(Registry& registry) {
  using O = UnfoldOptions;
  static const auto table = ParamTable<O>().add(
      "overlap_tolerance", [](O& o) -> auto& { return o.overlap_tolerance; },
      "relative penetration below which touching triangles do not overlap", at_least(0));
  registry.add({.name = "unfold.sequential",
                .summary = "isometric unfolding with a 2D overlap test (grid)",
                .input = MessageType::of<AcceptedStrip>(),
                .outputs = {{"out", MessageType::of<UnfoldedStrip>()}},
                .params = table.specs(),
                .create = [](const Params& params, const NodeContext&) {
                  const UnfoldOptions options = table.read(params);
                  return make_body([options](const Envelope& in, Emitter& out) {
                    auto accepted = in.get_shared<AcceptedStrip>();
                    UnfoldedStrip unfolded;
                    unfolded.strip = accepted;
                    unfolded.flat = unfold_strip(*accepted->strip, -1, 0, options);
                    out.emit("out", std::move(unfolded));
                  });
                }});
}

}  // namespace papercraft
