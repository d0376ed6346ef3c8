// segment.feature — parts separated by sharp edges; nearly closed feature chains are
// closed and tiny regions merged into a neighbour.
//
//   segment: {impl: segment.feature, params: {angle_degrees: 40}, to: [select]}

#include "graph/registry.h"
#include "nodes/segment/emit_parts.h"
#include "nodes/segment/feature.h"
#include "nodes/segment/none.h"

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
        {"parts_ply", ParamType::Boolean, "true",
         "write the parts, faces coloured by part, to <output>/parts.ply"}},
       [](const Params& params) {
         FeatureSegmentOptions options;
         options.angle_degrees = params.number("angle_degrees");
         options.min_area_fraction = params.number("min_area_fraction");
         options.close_gap_fraction = params.number("close_gap_fraction");
         const bool parts_ply = params.boolean("parts_ply");
                  return make_body([options, parts_ply](const Envelope& in, Emitter& out) {
           Mesh mesh = *in.get<Model>().mesh;
           tag_input_vertices(mesh);
           emit_parts(in, out, segment_feature(mesh, options), parts_ply);
         });
       }});
}

}  // namespace papercraft
