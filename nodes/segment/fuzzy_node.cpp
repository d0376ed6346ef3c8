// segment.fuzzy — hierarchical fuzzy clustering with minimum cuts (Katz & Tal 2003), the
// boundaries straightened along harmonic iso-lines; with strip_estimate, each level judged by
// what the pipeline's own refinement (NodeContext::refine) makes of it.
//
//   segment: {impl: segment.fuzzy, params: {parts: 0, max_depth: 3}, to: [select]}

#include "core/errors.h"
#include "graph/param_table.h"
#include "graph/registry.h"
#include "nodes/segment/fuzzy.h"
#include "nodes/segment/none.h"
#include "nodes/segment/parts_node.h"

namespace papercraft {

namespace {

struct FuzzyNodeOptions {
  FuzzySegmentOptions segment;
  bool strip_estimate = true;
  bool parts_ply = true;
};

std::vector<FuzzyAlternative> alternatives_of(const ParamValue& value) {
  std::vector<FuzzyAlternative> alternatives;
  for (const std::string& text : std::get<std::vector<std::string>>(value)) {
    try {
      alternatives.push_back(parse_fuzzy_alternative(text));
    } catch (const InvalidInputException& e) {
      throw std::invalid_argument(e.what());
    }
  }
  return alternatives;
}

std::string alternatives_text(const std::vector<FuzzyAlternative>& alternatives) {
  std::vector<std::string> texts;
  for (const auto& alternative : alternatives)
    texts.push_back(format_fuzzy_alternative(alternative));
  return format_param_value(ParamValue(texts));
}

}  // namespace

void register_segment_fuzzy(Registry& registry) {
  using O = FuzzyNodeOptions;
  static const auto table =
      ParamTable<O>()
          .add(
              "parts", [](O & o) -> auto& { return o.segment.parts; },
              "parts per level; 0 chooses automatically", at_least(0))
          .add(
              "max_parts", [](O & o) -> auto& { return o.segment.max_parts; },
              "upper bound when choosing automatically", at_least(2))
          .add(
              "max_depth", [](O & o) -> auto& { return o.segment.max_depth; },
              "levels of the hierarchy", at_least(1))
          .add(
              "angular_weight", [](O & o) -> auto& { return o.segment.angular_weight; },
              "weight of the angular term in the dual-graph distance (1 - delta of Katz-Tal)",
              between(0, 1))
          .convert(
              "alternatives", ParamType::StringList,
              [](O & o) -> auto& { return o.segment.alternatives; }, alternatives_text,
              alternatives_of,
              "with strip_estimate, also build the hierarchy with each of these settings "
              "(angular_weight, convex_eta, fuzzy_epsilon; several separated by spaces) and "
              "keep the decomposition that makes the fewest strips; [] for none")
          .add(
              "fuzzy_epsilon", [](O & o) -> auto& { return o.segment.fuzzy_epsilon; },
              "width of the fuzzy region", ParamRange{0.0, 0.5, false, true})
          .add(
              "convex_eta", [](O & o) -> auto& { return o.segment.convex_eta; },
              "angular distance factor of convex edges (concave ones get 1)",
              ParamRange{0.0, 1.0, true, false})
          .add(
              "neck_ratio", [](O & o) -> auto& { return o.segment.neck_ratio; },
              "a boundary stays if its size squared / smaller part area is at most this",
              greater_than(0))
          .add(
              "crease_angle_degrees", [](O & o) -> auto& { return o.segment.crease_angle_degrees; },
              "a boundary stays if the surface folds concavely across it by this much",
              between(0, 180))
          .add(
              "straighten_width", [](O & o) -> auto& { return o.segment.straighten_width; },
              "half-width of the band a boundary may move in, in mean edge lengths",
              greater_than(0))
          .add(
              "straighten", [](O & o) -> auto& { return o.segment.straighten; },
              "straighten cut boundaries along harmonic iso-lines")
          .add(
              "min_area_fraction", [](O & o) -> auto& { return o.segment.min_area_fraction; },
              "parts smaller than this fraction of the area join a neighbour",
              ParamRange{0.0, 1.0, false, true})
          .add(
              "strip_estimate", [](O & o) -> auto& { return o.strip_estimate; },
              "keep a decomposition only if the refinement makes fewer strips of its parts "
              "(estimated at the model's tolerance)")
          .add(
              "two_way_candidate", [](O & o) -> auto& { return o.segment.two_way_candidate; },
              "with strip_estimate, also judge each region's two-way farthest-faces split")
          .add(
              "single_part_candidates",
              [](O & o) -> auto& { return o.segment.single_part_candidates; },
              "with strip_estimate, also judge each part of a decomposition split off alone")
          .add(
              "merge_neighbours", [](O & o) -> auto& { return o.segment.merge_neighbours; },
              "with strip_estimate, then merge adjacent parts whose union makes fewer strips")
          .add(
              "parts_ply", [](O & o) -> auto& { return o.parts_ply; },
              "write the parts, faces coloured by part, to <output>/parts.ply");
  registry.add({.name = "segment.fuzzy",
                .summary = "Katz-Tal hierarchical fuzzy decomposition with straightened cuts",
                .input = MessageType::of<Model>(),
                .outputs = {{"out", MessageType::of<Part>()}},
                .params = table.specs(),
                .create = [](const Params& params, const NodeContext& context) {
                  FuzzyNodeOptions options = table.read(params);
                  options.segment.refine = context.refine;
                  return make_body([options](const Envelope& in, Emitter& out) {
                    FuzzySegmentOptions run = options.segment;
                    if (options.strip_estimate) {
                      run.strip_tolerance = in.model->refinement_tolerance();
                      run.strip_limits = in.model->piece_limits();
                    }
                    Mesh mesh = in.get<Model>().refined_mesh();
                    tag_input_vertices(mesh);
                    emit_parts(in, out, segment_fuzzy(mesh, run), options.parts_ply);
                  });
                }});
}

}  // namespace papercraft
