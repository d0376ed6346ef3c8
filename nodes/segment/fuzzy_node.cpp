// segment.fuzzy — hierarchical fuzzy clustering with minimum cuts (Katz & Tal 2003), the
// boundaries straightened along harmonic iso-lines.
//
//   segment: {impl: segment.fuzzy, params: {parts: 0, max_depth: 3}, to: [select]}

#include "core/errors.h"
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
                 {"max_depth", ParamType::Integer, "3", "levels of the hierarchy"},
                 {"angular_weight", ParamType::Number, "0.8",
                  "weight of the angular term in the dual-graph distance (1 - delta of Katz-Tal)"},
                 {"alternatives", ParamType::StringList, "[angular_weight=0.5, fuzzy_epsilon=0.2]",
                  "with strip_estimate, also build the hierarchy with each of these settings "
                  "(angular_weight, convex_eta, fuzzy_epsilon; several separated by spaces) and "
                  "keep the decomposition that makes the fewest strips; [] for none"},
                 {"fuzzy_epsilon", ParamType::Number, "0.1", "width of the fuzzy region"},
                 {"convex_eta", ParamType::Number, "0.1",
                  "angular distance factor of convex edges (concave ones get 1)"},
                 {"neck_ratio", ParamType::Number, "2",
                  "a boundary stays if its size squared / smaller part area is at most this"},
                 {"crease_angle_degrees", ParamType::Number, "20",
                  "a boundary stays if the surface folds concavely across it by this much"},
                 {"straighten_width", ParamType::Number, "3",
                  "half-width of the band a boundary may move in, in mean edge lengths"},
                 {"straighten", ParamType::Boolean, "true",
                  "straighten cut boundaries along harmonic iso-lines"},
                 {"min_area_fraction", ParamType::Number, "0.01",
                  "parts smaller than this fraction of the area join a neighbour"},
                 {"strip_estimate", ParamType::Boolean, "true",
                  "keep a decomposition only if the refinement makes fewer strips of its parts "
                  "(estimated at the model's tolerance)"},
                 {"two_way_candidate", ParamType::Boolean, "true",
                  "with strip_estimate, also judge each region's two-way farthest-faces split"},
                 {"single_part_candidates", ParamType::Boolean, "true",
                  "with strip_estimate, also judge each part of a decomposition split off alone"},
                 {"merge_neighbours", ParamType::Boolean, "true",
                  "with strip_estimate, then merge adjacent parts whose union makes fewer strips"},
                 {"parts_ply", ParamType::Boolean, "true",
                  "write the parts, faces coloured by part, to <output>/parts.ply"}},
                [](const Params& params) {
                  FuzzySegmentOptions options;
                  options.parts = static_cast<int>(params.integer("parts"));
                  options.max_parts = static_cast<int>(params.integer("max_parts"));
                  options.max_depth = static_cast<int>(params.integer("max_depth"));
                  options.angular_weight = params.number("angular_weight");
                  options.alternatives.clear();
                  for (const std::string& text : params.strings("alternatives")) {
                    try {
                      options.alternatives.push_back(parse_fuzzy_alternative(text));
                    } catch (const InvalidInputException& e) {
                      throw ConfigException("segment.fuzzy: alternatives: " +
                                            std::string(e.what()));
                    }
                  }
                  options.fuzzy_epsilon = params.number("fuzzy_epsilon");
                  options.convex_eta = params.number("convex_eta");
                  options.neck_ratio = params.number("neck_ratio");
                  options.crease_angle_degrees = params.number("crease_angle_degrees");
                  options.straighten_width = params.number("straighten_width");
                  options.straighten = params.boolean("straighten");
                  options.two_way_candidate = params.boolean("two_way_candidate");
                  options.single_part_candidates = params.boolean("single_part_candidates");
                  options.merge_neighbours = params.boolean("merge_neighbours");
                  options.min_area_fraction = params.number("min_area_fraction");
                  const bool parts_ply = params.boolean("parts_ply");
                  const bool strip_estimate = params.boolean("strip_estimate");
                  return make_body([options, parts_ply, strip_estimate](const Envelope& in,
                                                                        Emitter& out) {
                    FuzzySegmentOptions run_options = options;
                    if (strip_estimate) run_options.strip_tolerance = in.model->tolerance.load();
                    Mesh mesh = *in.get<Model>().mesh;
                    tag_input_vertices(mesh);
                    emit_parts(in, out, segment_fuzzy(mesh, run_options), parts_ply);
                  });
                }});
}

}  // namespace papercraft
