// segment.none — the whole model is one part (one per connected component).
//
//   segment: {impl: segment.none, to: [select]}

#include "graph/registry.h"
#include "nodes/segment/emit_parts.h"
#include "nodes/segment/none.h"

namespace papercraft {

void register_segment_none(Registry& registry) {
  registry.add({"segment.none",
                "no segmentation: one part per connected component",
                MessageType::of<Model>(),
                false,
                {{"out", MessageType::of<Part>()}},
                {},
                [](const Params&) {
                  return make_body([](const Envelope& in, Emitter& out) {
                    emit_parts(in, out, segment_none(*in.get<Model>().mesh));
                  });
                }});
}

}  // namespace papercraft
