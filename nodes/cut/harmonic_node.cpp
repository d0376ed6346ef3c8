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
#include "nodes/cut/maximal_strip.h"
#include "nodes/cut/through_witness.h"

namespace papercraft {

namespace {

struct CutNodeOptions {
  WitnessCutOptions cut;
  int search_steps = 4;
  long search_max_faces = 4000;
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
  WitnessCut cut;
  if (rejected.hole < 0 && options.search_steps > 0 &&
      static_cast<long>(part.n_faces()) <= options.search_max_faces) {
    MaximalStripOptions search;
    search.cut = options.cut;
    search.steps = options.search_steps;
    cut = cut_maximal_strip(part, candidate.first, candidate.first_closed, candidate.second,
                            candidate.second_closed, model.tolerance.load(), search);
  }
  if (cut.pieces.empty()) {
    cut = rejected.hole >= 0 ? cut_through_hole(part, candidate.first, candidate.second,
                                                candidate.holes[rejected.hole], options.cut)
                             : cut_through_witness(part, candidate.first, candidate.second,
                                                   rejected.witness, options.cut);
  }
  spdlog::debug("cut part {} ({} faces, {} holes, hole {}, error {:.4g}) at {} = {:.4f} into {}",
                candidate.part.path, part.n_faces(), candidate.holes.size(), rejected.hole,
                rejected.witness_error, cut.across ? "g" : "f", cut.value, cut.pieces.size());
  if (cut.pieces.empty()) fail("no iso-line through the worst point splits it");
  return cut.pieces;
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
                 {"max_depth", ParamType::Integer, "64",
                  "nested cuts allowed below one segment before the model fails with a message"}},
                [](const Params& params) {
                  CutNodeOptions options;
                  options.cut.cut.snap_fraction = params.number("snap_fraction");
                  options.max_depth = static_cast<int>(params.integer("max_depth"));
                  options.search_steps = static_cast<int>(params.integer("search_steps"));
                  options.search_max_faces = params.integer("search_max_faces");
                  options.cut.harmonic.clamp_negative_weights = params.boolean("positive_weights");
                  options.cut.margin = params.number("margin");
                  options.cut.min_piece_fraction = params.number("min_piece_fraction");
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
