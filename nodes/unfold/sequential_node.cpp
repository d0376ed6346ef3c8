// unfold.sequential — isometric unfolding of an accepted strip, triangle after triangle; a
// new flat strip starts where the next triangle would overlap the placed ones.
//
//   unfold: {impl: unfold.sequential, to: [merge]}

#include "graph/messages.h"
#include "graph/registry.h"
#include "nodes/unfold/sequential.h"

namespace papercraft {

void register_unfold_sequential(Registry& registry) {
  registry.add({"unfold.sequential",
                "isometric unfolding with a 2D overlap test (grid)",
                MessageType::of<AcceptedStrip>(),
                false,
                {{"out", MessageType::of<UnfoldedStrip>()}},
                {{"overlap_tolerance", ParamType::Number, "1e-9",
                  "relative penetration below which touching triangles do not overlap"}},
                [](const Params& params) {
                  UnfoldOptions options;
                  options.overlap_tolerance = params.number("overlap_tolerance");
                  return make_body([options](const Envelope& in, Emitter& out) {
                    auto accepted = in.get_shared<AcceptedStrip>();
                    UnfoldedStrip unfolded;
                    unfolded.strip = accepted;
                    unfolded.flat = unfold_strip(*accepted->strip, -1, 0, options);
                    out.emit(0, std::move(unfolded));
                  });
                }});
}

}  // namespace papercraft
