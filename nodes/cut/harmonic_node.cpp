// cut.harmonic — cut a rejected part along the iso-line, through the worst error point, of
// the harmonic field that is 0 on the strip's first boundary and 1 on its second (paper
// section 3.2.2); a part with holes is cut through a hole. The pieces go back to `select`.
//
//   cut: {impl: cut.harmonic, params: {max_depth: 64}, back: [select]}

#include <spdlog/spdlog.h>

#include <algorithm>
#include <sstream>

#include "core/errors.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"
#include "nodes/cut/rejected.h"

namespace papercraft {

namespace {

struct CutNodeOptions {
  RejectedCutOptions cut;
  int max_depth = 64;
};

std::vector<Mesh> cut_part(const RejectedStrip& rejected, const CutNodeOptions& options,
                           const ModelRun& model) {
  const Candidate& candidate = *rejected.candidate;
  const Mesh& part = *candidate.part.mesh;
  auto fail = [&](const std::string& why) {
    std::ostringstream message;
    message << "part " << candidate.part.path << " (" << part.n_faces()
            << " faces) cannot be approximated within the tolerance " << model.tolerance.load()
            << ": " << why << "; worst error " << rejected.witness_error << " at ("
            << rejected.witness.x() << ", " << rejected.witness.y() << ", " << rejected.witness.z()
            << "). The tolerance may be below the mesh's resolution: try a larger --tolerance.";
    throw ApproximationException(message.str());
  };
  if (candidate.part.depth >= options.max_depth) {
    fail("reached " + std::to_string(options.max_depth) + " nested cuts (max_depth)");
  }
  WitnessCut cut = cut_rejected_part(
      part, candidate.first, candidate.first_closed, candidate.second, candidate.second_closed,
      rejected.hole >= 0 ? &candidate.holes[rejected.hole] : nullptr, rejected.witness,
      model.tolerance.load(), options.cut);
  spdlog::debug("cut part {} ({} faces, {} holes, hole {}, error {:.4g}) at {} = {:.4f} into {}",
                candidate.part.path, part.n_faces(), candidate.holes.size(), rejected.hole,
                rejected.witness_error, cut.across ? "g" : "f", cut.value, cut.pieces.size());
  if (cut.pieces.empty()) fail("no iso-line through the worst point splits it");
  return std::move(cut.pieces);
}

}  // namespace

void register_cut_harmonic(Registry& registry) {
  registry.add({"cut.harmonic",
                "cut along an iso-line of the cotangent harmonic field (paper 3.2.2)",
                MessageType::of<RejectedStrip>(),
                false,
                {{"out", MessageType::of<Part>()}},
                {{"snap_fraction", ParamType::Number, "0.05",
                  "snap an iso-line crossing to a vertex within this fraction of the edge length"},
                 {"snap_tolerance", ParamType::Number, "0.01",
                  "also snap crossings within this fraction of the tolerance of a vertex (no "
                  "edges far shorter than the tolerance where cuts meet)"},
                 {"positive_weights", ParamType::Boolean, "true",
                  "clamp negative cotangent weights so the field obeys the maximum principle (no "
                  "spurious iso-line loops on obtuse triangles)"},
                 {"margin", ParamType::Number, "0.05",
                  "keep the iso-value at least this far from the strip boundaries (0 and 1)"},
                 {"min_piece_fraction", ParamType::Number, "0.01",
                  "a cut must leave every piece at least this fraction of the part's area"},
                 {"search_steps", ParamType::Integer, "4",
                  "bisection steps searching the cut that leaves the largest strip next to a "
                  "boundary (0: cut through the worst point, as the paper)"},
                 {"search_max_faces", ParamType::Integer, "4000",
                  "larger parts are cut through the worst point without the search (each probe "
                  "costs a cut, a strip and a certified decision)"},
                 {"search_min_fraction", ParamType::Number, "0.1",
                  "the search keeps a strip only if it covers at least this fraction of the part's "
                  "area; else the cut goes through the worst point (no thin layers peeled off)"},
                 {"max_depth", ParamType::Integer, "64",
                  "nested cuts allowed below one segment before the model fails with a message"}},
                [](const Params& params) {
                  CutNodeOptions options;
                  options.cut.cut.cut.snap_fraction = params.number("snap_fraction");
                  options.cut.snap_tolerance = params.number("snap_tolerance");
                  options.max_depth = static_cast<int>(params.integer("max_depth"));
                  options.cut.search_steps = static_cast<int>(params.integer("search_steps"));
                  options.cut.search_max_faces = params.integer("search_max_faces");
                  options.cut.search_min_fraction = params.number("search_min_fraction");
                  options.cut.cut.harmonic.clamp_negative_weights =
                      params.boolean("positive_weights");
                  options.cut.cut.margin = params.number("margin");
                  options.cut.cut.min_piece_fraction = params.number("min_piece_fraction");
                  return make_body([options](const Envelope& in, Emitter& out) {
                    const RejectedStrip& rejected = in.get<RejectedStrip>();
                    const Part& parent = rejected.candidate->part;
                    std::vector<Mesh> pieces = cut_part(rejected, options, *in.model);
                    in.model->add_result("cuts", 1);
                    for (std::size_t i = 0; i < pieces.size(); ++i) {
                      Part part;
                      part.mesh = std::make_shared<const Mesh>(std::move(pieces[i]));
                      part.path = parent.path + "." + std::to_string(i);
                      part.depth = parent.depth + 1;
                      part.model = parent.model;
                      out.emit(0, std::move(part));
                    }
                  });
                }});
}

}  // namespace papercraft
