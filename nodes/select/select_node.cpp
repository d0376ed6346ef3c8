// select.geodesic and select.exhaustive — choose the two boundaries of the strip for a part
// (paper 3.2.1; the engine's first step, engine/refine/refine.h): a closed part gets two
// far-apart vertices, a part with one boundary gets it and its farthest vertex, a part with
// several boundaries gets the pair farthest apart (geodesic) or the pair whose strip has the
// lowest certified error (exhaustive).
//
//   select: {impl: select.geodesic, to: [ruled]}

#include "engine/refine/refine.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"

namespace papercraft {

namespace {

NodeSpec select_spec(std::string name, std::string summary, bool exhaustive,
                     const ParamTable<RefineOptions>& table) {
  return refinement_stage(
      {.name = std::move(name),
       .summary = std::move(summary),
       .input = MessageType::of<Part>(),
       .outputs = {{"out", MessageType::of<Candidate>()}},
       .params = table.specs()},
      [exhaustive, &table](const Params& params, RefineOptions& refine) {
        refine = table.read(params, refine);
        refine.select.exhaustive = exhaustive;
      },
      [](const RefineOptions& refine) {
        return make_body([refine](const Envelope& in, Emitter& out) {
          const Part& part = in.get<Part>();
          Candidate candidate;
          static_cast<StripBoundaries&>(candidate) = select_strip_boundaries(
              *part.mesh, at_tolerance(refine, in.model->refinement_tolerance()));
          candidate.part = part;
          out.emit("out", std::move(candidate));
        });
      });
}

}  // namespace

void register_select_nodes(Registry& registry) {
  using O = RefineOptions;
  static const auto geodesic = ParamTable<O>().add(
      "sweeps", [](O & o) -> auto& { return o.select.geodesic.sweeps; },
      "farthest-point sweeps for the two far vertices of a closed part", at_least(1));
  static const auto exhaustive = ParamTable<O>().add(
      "precision", [](O & o) -> auto& { return o.select.precision; },
      "error bound of each pair's Hausdorff value, as a fraction of the tolerance",
      greater_than(0));
  registry.add(select_spec("select.geodesic", "strip boundaries farthest apart (Dijkstra sweeps)",
                           false, geodesic));
  registry.add(select_spec(
      "select.exhaustive",
      "every boundary pair built and measured in parallel; the lowest certified error wins", true,
      exhaustive));
}

}  // namespace papercraft
