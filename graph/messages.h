#pragma once
// The messages of the papercraft pipeline (DESIGN.md section 2). Payloads are immutable
// once sent and shared between nodes through shared_ptr<const T>.

#include <memory>
#include <string>
#include <vector>

#include "core/appearance.h"
#include "core/mesh.h"
#include "core/pattern.h"
#include "core/strip.h"
#include "engine/refine/refine.h"
#include "graph/model_record.h"

namespace papercraft {

/// A loaded, validated input mesh, and the surface the strips are refined on.
struct Model {
  static constexpr const char* kMessageName = "Model";
  /// The input, always: the approximation's certificate, error.ply and the bake refer to it.
  std::shared_ptr<const Mesh> mesh;
  /// The proxy stage's simplified copy of `mesh` within `proxy_distance` of it (certified
  /// two-sided Hausdorff bound), refined in its place; null when there is no proxy.
  std::shared_ptr<const Mesh> proxy;
  double proxy_distance = 0.0;
  MeshSummary summary;
  std::string texture_path;
  /// Materials, texture coordinates and colours per face of `mesh` (empty when it has none).
  std::shared_ptr<const SurfaceAppearance> appearance;

  /// The surface the segmentation and the refinement work on: the proxy, else the input.
  const Mesh& refined_mesh() const { return proxy ? *proxy : *mesh; }
};

/// A connected piece of the model being refined. Its vertices carry the int property
/// "v:input_vertex" (-1 where a cut created them).
struct Part {
  static constexpr const char* kMessageName = "Part";
  std::shared_ptr<const Mesh> mesh;
  std::string path;  // deterministic id: "<segment>" then ".<child>" per cut ("0.1.0")
  int depth = 0;     // number of cuts since the segment it came from
  std::shared_ptr<const Model> model;
};

/// A part with the two strip boundaries chosen and the part's remaining boundary loops.
struct Candidate : StripBoundaries {
  static constexpr const char* kMessageName = "Candidate";
  Part part;
};

/// A candidate with its triangulated ruled surface.
struct StripCandidate {
  static constexpr const char* kMessageName = "StripCandidate";
  std::shared_ptr<const Candidate> candidate;
  std::shared_ptr<const RuledStrip> strip;
};

/// A strip whose two-sided Hausdorff distance to its part is within the tolerance.
struct AcceptedStrip {
  static constexpr const char* kMessageName = "AcceptedStrip";
  std::shared_ptr<const Candidate> candidate;
  std::shared_ptr<const RuledStrip> strip;
  double upper_bound = 0.0;  // certified upper bound of the Hausdorff distance
  bool certified = true;     // false for sampled (uncertified) deciders
};

/// A strip that failed: the part must be cut through the witness (the located maximum
/// error) or, when verdict.hole >= 0, through that hole (paper 3.2.2: holes are always split).
struct RejectedStrip {
  static constexpr const char* kMessageName = "RejectedStrip";
  std::shared_ptr<const Candidate> candidate;
  std::shared_ptr<const RuledStrip> strip;
  StripVerdict verdict;
};

/// The flat strips unfolded from one accepted 3D strip.
struct UnfoldedStrip {
  static constexpr const char* kMessageName = "UnfoldedStrip";
  std::shared_ptr<const AcceptedStrip> strip;
  std::vector<FlatStrip> flat;
};

/// All strips of one model, after merging. 3D strip i is strips3d[i] (sorted by part path,
/// so ids do not depend on thread timing); FlatStrip::source_strip indexes it.
struct ModelStrips {
  static constexpr const char* kMessageName = "ModelStrips";
  std::vector<std::shared_ptr<const AcceptedStrip>> strips3d;
  std::vector<FlatStrip> flat;
  std::size_t flat_before_merge = 0;
  std::shared_ptr<const Model> model;  // the input (null only when there are no strips)
};

/// Strips laid out on pages, ready to export.
struct Pattern {
  static constexpr const char* kMessageName = "Pattern";
  std::shared_ptr<const ModelStrips> strips;
  std::shared_ptr<const PatternLayout> layout;  // null when the config has no layout
};

}  // namespace papercraft
