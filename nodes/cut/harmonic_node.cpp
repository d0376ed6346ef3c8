// cut.harmonic — cut a rejected part along the iso-line, through the worst error point, of
// the harmonic field that is 0 on the strip's first boundary and 1 on its second (paper
// section 3.2.2); a part with holes is cut through a hole. The pieces go back to `select`.
//
//   cut: {impl: cut.harmonic, params: {max_depth: 64}, back: [select]}

#include <algorithm>
#include <sstream>

#include "core/errors.h"
#include "graph/messages.h"
#include "graph/model_run.h"
#include "graph/registry.h"
#include "nodes/cut/harmonic.h"

namespace papercraft {

namespace {

struct CutNodeOptions {
  CutOptions cut;
  int max_depth = 64;
  long min_faces = 1;
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
            << rejected.witness.x() << ", " << rejected.witness.y() << ", "
            << rejected.witness.z()
            << "). The tolerance may be below the mesh's resolution: try a larger --tolerance.";
    throw ApproximationException(message.str());
  };
  if (candidate.part.depth >= options.max_depth) {
    fail("reached " + std::to_string(options.max_depth) + " nested cuts (max_depth)");
  }
  const Eigen::VectorXd field = harmonic_field(part, candidate.first, candidate.second);
  std::vector<double> values;
  if (rejected.hole >= 0) {
    values.push_back(hole_split_value(field, candidate.holes[rejected.hole]));
  } else {
    values.push_back(field_value_at(part, field, rejected.witness));
  }
  // A witness next to a strip boundary gives a sliver or no cut at all: move inwards.
  values.push_back(std::clamp(values.front(), 0.1, 0.9));
  values.push_back(0.5);
  for (double value : values) {
    std::vector<Mesh> pieces = cut_along_isoline(part, field, value, options.cut);
    if (pieces.size() >= 2) return pieces;
  }
  fail("no iso-line of the harmonic field splits it");
}

}  // namespace

void register_cut_harmonic(Registry& registry) {
  registry.add(
      {"cut.harmonic", "cut along an iso-line of the cotangent harmonic field (paper 3.2.2)",
       MessageType::of<RejectedStrip>(), false, {{"out", MessageType::of<Part>()}},
       {{"snap_fraction", ParamType::Number, "0.05",
         "snap an iso-line crossing to a vertex within this fraction of the edge length"},
        {"max_depth", ParamType::Integer, "64",
         "nested cuts allowed below one segment before the model fails with a message"}},
       [](const Params& params) {
         CutNodeOptions options;
         options.cut.snap_fraction = params.number("snap_fraction");
         options.max_depth = static_cast<int>(params.integer("max_depth"));
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
