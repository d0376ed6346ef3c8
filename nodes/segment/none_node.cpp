// segment.none — the whole model is one part (one per connected component).
//
//   segment: {impl: segment.none, to: [select]}

#include "graph/registry.h"
#include "nodes/segment/none.h"
#include "nodes/segment/parts_node.h"

namespace papercraft {

void register_segment_none(Registry& registry) {
  registry.add({.name = "segment.none",
                .summary = "no segmentation: one part per connected component",
                .input = MessageType::of<Model>(),
                .outputs = {{"out", MessageType::of<Part>()}},
                .create = [](const Params&, const NodeContext&) {
                  return make_body([](const Envelope& in, Emitter& out) {
                    emit_parts(in, out, segment_none(in.get<Model>().refined_mesh()));
                  });
                }});
}

}  // namespace papercraft
