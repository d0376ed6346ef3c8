// segment.none — the whole model is one part (one per connected component).
//
//   segment: {impl: segment.none, to: [select]}

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"
#include "nodes/segment/none.h"

namespace papercraft {

void register_segment_none(Registry& registry) {
  registry.add({"segment.none", "no segmentation: one part per connected component",
                MessageType::of<Model>(), false, {{"out", MessageType::of<Part>()}}, {},
                [](const Params&) {
                  return make_body([](const Envelope& in, Emitter& out) {
                    auto model = in.get_shared<Model>();
                    auto parts = segment_none(*model->mesh);
                    in.model->set_result("segments", static_cast<double>(parts.size()));
                    for (std::size_t i = 0; i < parts.size(); ++i) {
                      Part part;
                      part.mesh = std::make_shared<const Mesh>(std::move(parts[i]));
                      part.path = std::to_string(i);
                      part.model = model;
                      out.emit(0, std::move(part));
                    }
                  });
                }});
}

}  // namespace papercraft
