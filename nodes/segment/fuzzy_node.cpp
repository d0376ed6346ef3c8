// segment.fuzzy — hierarchical fuzzy clustering with minimum cuts (Katz & Tal 2003), the
// boundaries straightened along harmonic iso-lines.
//
//   segment: {impl: segment.fuzzy, params: {parts: 0, max_depth: 2}, to: [select]}

#include "graph/registry.h"
#include "nodes/segment/emit_parts.h"
#include "nodes/segment/fuzzy.h"
#include "nodes/segment/none.h"

namespace papercraft {

void register_segment_fuzzy(Registry& registry) {
  registry.add({"segment.fuzzy",
                "Katz-Tal hierarchical fuzzy decomposition with straightened cuts",
                MessageType::of<Model>(),
                false,
                {{"out", MessageType::of<Part>()}},
                {{"parts", ParamType::Integer, "0", "parts per level; 0 chooses automatically"},
                 {"max_parts", ParamType::Integer, "10", "upper bound when choosing automatically"},
                 {"max_depth", ParamType::Integer, "2", "levels of the hierarchy"},
                 {"angular_weight", ParamType::Number, "0.8",
                  "weight of the angular term in the dual-graph distance (1 - delta of Katz-Tal)"},
                 {"fuzzy_epsilon", ParamType::Number, "0.1", "width of the fuzzy region"},
                 {"straighten", ParamType::Boolean, "true",
                  "straighten cut boundaries along harmonic iso-lines"},
                 {"min_area_fraction", ParamType::Number, "0.01",
                  "parts smaller than this fraction of the area join a neighbour"}},
                [](const Params& params) {
                  FuzzySegmentOptions options;
                  options.parts = static_cast<int>(params.integer("parts"));
                  options.max_parts = static_cast<int>(params.integer("max_parts"));
                  options.max_depth = static_cast<int>(params.integer("max_depth"));
                  options.angular_weight = params.number("angular_weight");
                  options.fuzzy_epsilon = params.number("fuzzy_epsilon");
                  options.straighten = params.boolean("straighten");
                  options.min_area_fraction = params.number("min_area_fraction");
                  return make_body([options](const Envelope& in, Emitter& out) {
                    Mesh mesh = *in.get<Model>().mesh;
                    tag_input_vertices(mesh);
                    emit_parts(in, out, segment_fuzzy(mesh, options));
                  });
                }});
}

}  // namespace papercraft
