// segment.feature — parts separated by sharp edges; nearly closed feature chains are
// closed and tiny regions merged into a neighbour. The parts are kept only if the refinement
// (the pipeline's own, NodeContext::refine) makes fewer strips of them than of the model whole.
//
//   segment: {impl: segment.feature, params: {angle_degrees: 40}, to: [select]}

#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "engine/refine/refine.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/segment/feature.h"
#include "nodes/segment/none.h"
#include "nodes/segment/parts_node.h"

namespace papercraft {

namespace {

struct FeatureNodeOptions {
  FeatureSegmentOptions segment;
  bool strip_estimate = true;
  bool parts_ply = true;
};

}  // namespace

void register_segment_feature(Registry& registry) {
  using O = FeatureNodeOptions;
  static const auto table =
      ParamTable<O>()
          .add(
              "angle_degrees", [](O & o) -> auto& { return o.segment.angle_degrees; },
              "edges bent more than this separate parts", ParamRange{0.0, 180.0, true, true})
          .add(
              "min_area_fraction", [](O & o) -> auto& { return o.segment.min_area_fraction; },
              "regions smaller than this fraction of the area join a neighbour",
              ParamRange{0.0, 1.0, false, true})
          .add(
              "close_gap_fraction", [](O & o) -> auto& { return o.segment.close_gap_fraction; },
              "feature chains whose ends are this close (of the bounding-box diagonal) are "
              "closed",
              at_least(0))
          .add(
              "strip_estimate", [](O & o) -> auto& { return o.strip_estimate; },
              "emit the model whole where the refinement makes fewer strips of it than of the "
              "parts (estimated at the model's tolerance)")
          .add(
              "parts_ply", [](O & o) -> auto& { return o.parts_ply; },
              "write the parts, faces coloured by part, to <output>/parts.ply");
  registry.add(
      {.name = "segment.feature",
       .summary = "parts separated by sharp edges (dihedral angle above a threshold)",
       .input = MessageType::of<Model>(),
       .outputs = {{"out", MessageType::of<Part>()}},
       .params = table.specs(),
       .create = [](const Params& params, const NodeContext& context) {
         const FeatureNodeOptions options = table.read(params);
         const RefineOptions refine = context.refine;
         return make_body([options, refine](const Envelope& in, Emitter& out) {
           Mesh mesh = in.get<Model>().refined_mesh();
           tag_input_vertices(mesh);
           std::vector<Mesh> parts = segment_feature(mesh, options.segment);
           std::vector<Mesh> whole = segment_none(mesh);
           if (options.strip_estimate && parts.size() > whole.size()) {
             // Paper folds along a crease inside a strip as well: a crease is only worth a
             // boundary if the parts cost no more strips than the model whole. The parts
             // are counted first, side by side; the model whole only below their total
             // (so the usual loser on creased models stops early).
             const RefineOptions at_model = at_tolerance(refine, in.model->refinement_tolerance());
             const PieceLimits limits = in.model->piece_limits();
             // Each side keeps its cuts, up to four times the model's faces in pieces:
             // the graph refines the winner again and takes them (CutMemo).
             const long kept = 4 * static_cast<long>(mesh.n_faces());
             auto parts_cuts = std::make_shared<CutMemo>(kept);
             auto whole_cuts = std::make_shared<CutMemo>(kept);
             std::vector<int> counts(parts.size());
             tbb::parallel_for(std::size_t{0}, parts.size(), [&](std::size_t i) {
               counts[i] = count_strips(parts[i], at_model, 1 << 20, limits, parts_cuts.get());
             });
             long part_strips = 0;
             for (int count : counts) part_strips += count;
             // A tie keeps the parts: the same strips, but with their boundaries on
             // the creases (a cube's six faces, not one strip folded round it). So the
             // model whole is counted only while it stays below the parts.
             long whole_strips = 0;
             for (const Mesh& part : whole) {
               const long cap = std::min(part_strips - 1 - whole_strips, long{1} << 20);
               if (cap < 0) {
                 whole_strips = part_strips;
                 break;
               }
               whole_strips +=
                   count_strips(part, at_model, static_cast<int>(cap), limits, whole_cuts.get());
               if (whole_strips >= part_strips) break;
             }
             const bool whole_wins = whole_strips < part_strips;
             if (whole_wins) parts = std::move(whole);
             in.model->cut_memo = whole_wins ? whole_cuts : parts_cuts;
           }
           emit_parts(in, out, std::move(parts), options.parts_ply);
         });
       }});
}

}  // namespace papercraft
