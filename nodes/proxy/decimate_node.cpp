// proxy.decimate — refine a decimated copy of the input, certified within
// distance_share * tolerance of it, at the tolerance less its certified distance; a mesh with
// fewer than min_faces faces goes on as it is.
//
//   proxy: {impl: proxy.decimate, params: {distance_share: 0.2, min_faces: 100000}, to: [segment]}

#include <spdlog/spdlog.h>

#include <chrono>

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/proxy/decimate.h"

namespace papercraft {

void register_proxy_decimate(Registry& registry) {
  using O = ProxyDecimateOptions;
  static const auto table =
      ParamTable<O>()
          .add(
              "distance_share", [](O & o) -> auto& { return o.distance_share; },
              "the proxy is certified within this share of the tolerance of the input; the strips "
              "are refined at the tolerance less the proxy's certified distance",
              between(0.01, 0.9))
          .add(
              "min_faces", [](O & o) -> auto& { return o.min_faces; },
              "inputs with fewer faces are refined as they are", at_least(0))
          .add(
              "max_face_share", [](O & o) -> auto& { return o.max_face_share; },
              "the proxy is used only when it has at most this share of the input's faces",
              between(0.01, 1))
          .add(
              "decimation_share", [](O & o) -> auto& { return o.decimation_share; },
              "collapses keep the root-mean-square distance to the merged input faces' planes "
              "under this "
              "share of the proxy's distance (a heuristic; the certificate decides)",
              between(0.01, 1))
          .add(
              "attempts", [](O & o) -> auto& { return o.attempts; },
              "decimations tried, each with half the decimation bound of the one before",
              between(1, 10));
  registry.add(
      {.name = "proxy.decimate",
       .summary = "refine a quadric decimation certified within a share of the tolerance",
       .input = MessageType::of<Model>(),
       .outputs = {{"out", MessageType::of<Model>()}},
       .params = table.specs(),
       .create = [](const Params& params, const NodeContext&) {
         const ProxyDecimateOptions options = table.read(params);
         return make_body([options](const Envelope& in, Emitter& out) {
           const auto start = std::chrono::steady_clock::now();
           const auto model = in.get_shared<Model>();
           CertifiedProxy proxy =
               certified_decimation(*model->mesh, in.model->tolerance(), options);
           const double seconds =
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
           ProxySummary summary;
           summary.method = "decimate";
           summary.used = proxy.used;
           summary.seconds = seconds;
           summary.reason = proxy.reason;
           if (!proxy.used) {
             spdlog::debug("{}: no proxy: {}", in.model->name, proxy.reason);
             in.model->update([&](ModelRecord& record) { record.proxy = summary; });
             out.emit("out", model);
             return;
           }
           summary.vertices = proxy.mesh.n_vertices();
           summary.faces = proxy.mesh.n_faces();
           summary.distance_bound = proxy.distance_bound;
           spdlog::info("{}: proxy of {} faces within {:.3g} of the input ({:.2f} s)",
                        in.model->name, summary.faces, summary.distance_bound, seconds);
           in.model->set_proxy_distance(proxy.distance_bound);
           in.model->update([&](ModelRecord& record) { record.proxy = summary; });
           Model refined = *model;
           refined.proxy = std::make_shared<const Mesh>(std::move(proxy.mesh));
           refined.proxy_distance = proxy.distance_bound;
           out.emit("out", std::move(refined));
         });
       }});
}

}  // namespace papercraft
