// cut.harmonic — cut a rejected part along the iso-line, through the worst error point, of
// the harmonic field that is 0 on the strip's first boundary and 1 on its second (paper
// section 3.2.2; the engine's fourth step, with its maximal-strip search); a part with holes
// is cut through a hole. The pieces go back to `select`.
//
//   cut: {impl: cut.harmonic, params: {max_depth: 64}, back: [select]}

#include <optional>
#include <vector>

#include "engine/refine/refine.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/param_table.h"
#include "graph/registry.h"

namespace papercraft {

void register_cut_harmonic(Registry& registry) {
  using O = RefineOptions;
  static const auto table =
      ParamTable<O>()
          .add(
              "snap_fraction", [](O & o) -> auto& { return o.cut.cut.cut.snap_fraction; },
              "snap an iso-line crossing to a vertex within this fraction of the edge length",
              ParamRange{0.0, 0.5, false, true})
          .add(
              "straighten_passes", [](O & o) -> auto& { return o.cut.cut.cut.straighten_passes; },
              "passes sliding each sharply turning crossing along its edge to shorten a cut that "
              "zig-zags across thin triangles (0: the exact iso-line)",
              between(0, 100))
          .add(
              "straighten_turn_degrees",
              [](O & o) -> auto& { return o.cut.cut.cut.straighten_turn_degrees; },
              "only crossings where the cut turns by more than this slide (0: every crossing)",
              between(0, 180))
          .add(
              "snap_tolerance", [](O & o) -> auto& { return o.cut.snap_tolerance; },
              "also snap crossings within this fraction of the tolerance of a vertex (no "
              "edges far shorter than the tolerance where cuts meet)",
              at_least(0))
          .add(
              "positive_weights",
              [](O & o) -> auto& { return o.cut.cut.harmonic.clamp_negative_weights; },
              "clamp negative cotangent weights so the field obeys the maximum principle (no "
              "spurious iso-line loops on obtuse triangles)")
          .add(
              "margin", [](O & o) -> auto& { return o.cut.cut.margin; },
              "keep the iso-value at least this far from the strip boundaries (0 and 1)",
              ParamRange{0.0, 0.5, false, true})
          .add(
              "min_piece_fraction", [](O & o) -> auto& { return o.cut.cut.min_piece_fraction; },
              "a cut must leave every piece at least this fraction of the part's area",
              ParamRange{0.0, 0.5, false, true})
          .add(
              "search_steps", [](O & o) -> auto& { return o.cut.search_steps; },
              "bisection steps searching the cut that leaves the largest strip next to a "
              "boundary (0: cut through the worst point, as the paper)",
              at_least(0))
          .add(
              "search_max_faces", [](O & o) -> auto& { return o.cut.search_max_faces; },
              "larger parts are cut through the worst point without the search (each probe "
              "costs a cut, a strip and a certified decision)",
              at_least(0))
          .add(
              "search_min_fraction", [](O & o) -> auto& { return o.cut.search_min_fraction; },
              "the search keeps a strip only if it covers at least this fraction of the part's "
              "area; else the cut goes through the worst point (no thin layers peeled off)",
              between(0, 1))
          .add(
              "max_depth", [](O & o) -> auto& { return o.max_depth; },
              "nested cuts allowed below one segment before the model fails with a message",
              at_least(1));
  registry.add(refinement_stage(
      {.name = "cut.harmonic",
       .summary = "cut along an iso-line of the cotangent harmonic field (paper 3.2.2)",
       .input = MessageType::of<RejectedStrip>(),
       .outputs = {{"out", MessageType::of<Part>()}},
       .params = table.specs()},
      [](const Params& params, RefineOptions& refine) { refine = table.read(params, refine); },
      [](const RefineOptions& refine) {
        return make_body([refine](const Envelope& in, Emitter& out) {
          const RejectedStrip& rejected = in.get<RejectedStrip>();
          const Part& parent = rejected.candidate->part;
          // The segment stage may have made this very cut already (CutMemo).
          std::optional<std::vector<Mesh>> kept;
          if (in.model->cut_memo)
            kept = in.model->cut_memo->take(*parent.mesh, *rejected.candidate, rejected.verdict);
          std::vector<Mesh> pieces =
              kept ? std::move(*kept)
                   : cut_rejected_piece(*parent.mesh, *rejected.candidate, rejected.verdict,
                                        parent.depth,
                                        at_tolerance(refine, in.model->refinement_tolerance()),
                                        parent.path, in.model->piece_limits());
          in.model->update([](ModelRecord& record) { ++record.cuts; });
          for (std::size_t i = 0; i < pieces.size(); ++i) {
            Part part;
            part.mesh = std::make_shared<const Mesh>(std::move(pieces[i]));
            part.path = parent.path + "." + std::to_string(i);
            part.depth = parent.depth + 1;
            part.model = parent.model;
            out.emit("out", std::move(part));
          }
        });
      }));
}

}  // namespace papercraft
