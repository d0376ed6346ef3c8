// proxy.none — no proxy: the input is refined as it is (the pipeline's output is exactly that
// of a config without a proxy stage).
//
//   proxy: {impl: proxy.none, to: [segment]}

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"

namespace papercraft {

void register_proxy_none(Registry& registry) {
  registry.add({.name = "proxy.none",
                .summary = "no proxy: the input is refined as it is",
                .input = MessageType::of<Model>(),
                .outputs = {{"out", MessageType::of<Model>()}},
                .create = [](const Params&, const NodeContext&) {
                  return make_body([](const Envelope& in, Emitter& out) {
                    in.model->update([](ModelRecord& record) {
                      record.proxy = {};
                      record.proxy.reason = "proxy.none";
                    });
                    out.emit("out", in.get_shared<Model>());
                  });
                }});
}

}  // namespace papercraft
