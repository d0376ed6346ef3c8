#pragma once
// The "proxy" stage: a simplified copy of the input, certified close to it, refined in its
// place (DESIGN.md section 6, "A certified proxy").
//
// The input is decimated by halfedge collapses in passes of independent collapses
// (nodes/proxy/collapse.h) ordered by Garland and Heckbert's quadric error (1997) divided by the
// area it gathers: the mean squared distance of the kept vertex to the planes of the input faces
// merged into it, allowed up to d^2 with d = decimation_share * e; collapses that turn a face by
// more than 60 degrees are refused. Boundary vertices are locked, so boundaries and the topology
// stay as they are. That is a heuristic; the certificate is the two-sided bounded Hausdorff
// distance H(proxy, input), computed to within e / 10 (engine/hausdorff/bounded.h) over the
// triangles of both surfaces, and required <= e. A proxy that fails is made again with d
// halved, up to `attempts` times.
//
// With H(proxy, input) <= e and strips certified within tau - e of the proxy, the strips are
// within tau of the input: the Hausdorff distance obeys the triangle inequality.
//
// Known limit: the decimation is sequential (one thread).

#include <cstddef>
#include <string>

#include "core/mesh.h"

namespace papercraft {

struct ProxyDecimateOptions {
  /// e = distance_share * tolerance: the certified distance of the proxy to the input.
  double distance_share = 0.2;
  /// An input with fewer faces is refined as it is (no proxy).
  std::size_t min_faces = 100'000;
  /// The proxy is used only when it has at most this share of the input's faces.
  double max_face_share = 0.5;
  /// The decimation keeps every removed input vertex within decimation_share * e of the
  /// proxy (a one-sided heuristic; the certificate is two-sided).
  double decimation_share = 0.125;
  /// Decimations tried, each with half the decimation bound of the one before.
  int attempts = 3;
};

struct CertifiedProxy {
  /// False: no proxy (`reason` says why); the input is refined as it is.
  bool used = false;
  Mesh mesh;  // the proxy, when used (no deleted elements)
  /// Certified upper bound of the two-sided Hausdorff distance H(mesh, input), <= e; 0 when
  /// not used.
  double distance_bound = 0.0;
  std::string reason;
  int attempts = 0;  // decimations made
};

/// A decimated copy of `input` within distance_share * tolerance of it (certified), or
/// used == false when the input is small, the decimation gains too little or no attempt
/// certifies. Vertex properties (e.g. "v:input_vertex") are carried over for the vertices kept.
/// \pre `input` is a triangle mesh without deleted elements; tolerance > 0;
/// 0 < distance_share < 1. \throws InvalidInputException otherwise.
CertifiedProxy certified_decimation(const Mesh& input, double tolerance,
                                    const ProxyDecimateOptions& options = {});

}  // namespace papercraft
