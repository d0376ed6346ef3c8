// select.geodesic and select.exhaustive — choose the two boundaries of the strip for a part
// (paper 3.2.1): a closed part gets two far-apart vertices, a part with one boundary gets it
// and its farthest vertex, a part with several boundaries gets the pair farthest apart
// (geodesic) or the pair whose strip has the lowest certified error (exhaustive).
//
//   select: {impl: select.geodesic, to: [ruled]}

#include <algorithm>

#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"
#include "nodes/select/exhaustive.h"
#include "nodes/select/geodesic.h"

namespace papercraft {

namespace {

Candidate make_candidate(const Part& part, const BoundarySelection& selection) {
  Candidate candidate;
  candidate.part = part;
  candidate.first = selection.first;
  candidate.second = selection.second;
  candidate.first_closed = selection.first_closed;
  candidate.second_closed = selection.second_closed;
  candidate.a = selection_polyline(*part.mesh, selection.first, selection.first_closed);
  candidate.b = selection_polyline(*part.mesh, selection.second, selection.second_closed);
  auto used = [&](const std::vector<int>& loop) {
    auto chosen = [&](const std::vector<int>& side, bool closed) {
      return closed && std::find(side.begin(), side.end(), loop.front()) != side.end();
    };
    return chosen(selection.first, selection.first_closed) ||
           chosen(selection.second, selection.second_closed);
  };
  for (auto& loop : boundary_loops(*part.mesh)) {
    if (!used(loop)) candidate.holes.push_back(std::move(loop));
  }
  return candidate;
}

}  // namespace

void register_select_nodes(Registry& registry) {
  registry.add({"select.geodesic",
                "strip boundaries farthest apart (Dijkstra sweeps)",
                MessageType::of<Part>(),
                false,
                {{"out", MessageType::of<Candidate>()}},
                {{"sweeps", ParamType::Integer, "4",
                  "farthest-point sweeps for the two far vertices of a closed part"}},
                [](const Params& params) {
                  GeodesicSelectOptions options;
                  options.sweeps = static_cast<int>(params.integer("sweeps"));
                  return make_body([options](const Envelope& in, Emitter& out) {
                    const Part& part = in.get<Part>();
                    out.emit(0, make_candidate(part, select_geodesic(*part.mesh, options)));
                  });
                }});
  registry.add(
      {"select.exhaustive",
       "every boundary pair built and measured in parallel; the lowest certified error wins",
       MessageType::of<Part>(),
       false,
       {{"out", MessageType::of<Candidate>()}},
       {{"precision", ParamType::Number, "0.05",
         "error bound of each pair's Hausdorff value, as a fraction of the tolerance"}},
       [](const Params& params) {
         const double precision = params.number("precision");
         return make_body([precision](const Envelope& in, Emitter& out) {
           const Part& part = in.get<Part>();
           ExhaustiveSelectOptions options;
           options.error_bound = precision * in.model->tolerance.load();
           out.emit(0, make_candidate(part, select_exhaustive(*part.mesh, options)));
         });
       }});
}

}  // namespace papercraft
