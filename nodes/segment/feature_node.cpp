// segment.feature — parts separated by sharp edges; nearly closed feature chains are
// closed and tiny regions merged into a neighbour.
//
//   segment: {impl: segment.feature, params: {angle_degrees: 40}, to: [select]}

#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "graph/registry.h"
#include "nodes/segment/emit_parts.h"
#include "nodes/segment/feature.h"
#include "nodes/segment/none.h"
#include "nodes/segment/strip_estimate.h"

namespace papercraft {

void register_segment_feature(Registry& registry) {
  registry.add(
      {"segment.feature",
       "parts separated by sharp edges (dihedral angle above a threshold)",
       MessageType::of<Model>(),
       false,
       {{"out", MessageType::of<Part>()}},
       {{"angle_degrees", ParamType::Number, "40", "edges bent more than this separate parts"},
        {"min_area_fraction", ParamType::Number, "0.01",
         "regions smaller than this fraction of the area join a neighbour"},
        {"close_gap_fraction", ParamType::Number, "0.05",
         "feature chains whose ends are this close (of the bounding-box diagonal) are closed"},
        {"strip_estimate", ParamType::Boolean, "true",
         "emit the model whole unless the refinement makes fewer strips of the parts "
         "(estimated at the model's tolerance)"},
        {"parts_ply", ParamType::Boolean, "true",
         "write the parts, faces coloured by part, to <output>/parts.ply"}},
       [](const Params& params) {
         FeatureSegmentOptions options;
         options.angle_degrees = params.number("angle_degrees");
         options.min_area_fraction = params.number("min_area_fraction");
         options.close_gap_fraction = params.number("close_gap_fraction");
         const bool parts_ply = params.boolean("parts_ply");
         const bool strip_estimate = params.boolean("strip_estimate");
         return make_body([options, parts_ply, strip_estimate](const Envelope& in, Emitter& out) {
           Mesh mesh = *in.get<Model>().mesh;
           tag_input_vertices(mesh);
           std::vector<Mesh> parts = segment_feature(mesh, options);
           std::vector<Mesh> whole = segment_none(mesh);
           if (strip_estimate && parts.size() > whole.size()) {
             // Paper folds along a crease inside a strip as well: a crease is only worth a
             // boundary if the parts cost fewer strips than the model whole. The parts are
             // counted first, side by side; the model whole only up to their total (so the
             // usual loser on creased models stops early).
             const double tolerance = in.model->tolerance.load();
             std::vector<int> counts(parts.size());
             tbb::parallel_for(std::size_t{0}, parts.size(), [&](std::size_t i) {
               counts[i] = estimate_strips(parts[i], tolerance, 1 << 20);
             });
             long part_strips = 0;
             for (int count : counts) part_strips += count;
             long whole_strips = 0;
             for (const Mesh& part : whole) {
               const long cap = std::min(part_strips - whole_strips, long{1} << 20);  // >= 0
               whole_strips += estimate_strips(part, tolerance, static_cast<int>(cap));
               if (whole_strips > part_strips) break;
             }
             if (part_strips >= whole_strips) parts = std::move(whole);
           }
           emit_parts(in, out, std::move(parts), parts_ply);
         });
       }});
}

}  // namespace papercraft
