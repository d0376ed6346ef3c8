#pragma once
// Metro-style sampled Hausdorff distance (Cignoni, Rocchini, Scopigno 1998), the method of
// the paper and the uncertified baseline behind `hausdorff.sampled`: both surfaces are
// sampled (vertices, points along edges, stratified points inside triangles) and each sample
// is measured exactly against the other surface. The result is only a lower bound of H.

#include <cstddef>

#include "core/triangle_mesh.h"
#include "engine/hausdorff/bounded.h"

namespace papercraft {

struct SampledHausdorffOptions {
  /// Samples inside triangles per surface, spread by area; edges get about the square root
  /// of the same density per unit length.
  std::size_t face_samples = 100'000;
  /// Sample every vertex and every edge (Metro's vertex and edge sampling).
  bool sample_vertices = true;
  bool sample_edges = true;
};

/// Sampled decision "H(a, b) <= tau?". Returns certified == false, lower == upper == the
/// largest sampled distance (a lower bound of H, not an upper one), within == (lower <= tau),
/// the worst sample as witness and the number of samples as evaluations.
/// \pre a and b have at least one triangle, valid indices, finite coordinates; tau > 0.
/// \throws InvalidInputException otherwise.
HausdorffResult sampled_hausdorff_within(const TriangleMesh& a, const TriangleMesh& b, double tau,
                                         const SampledHausdorffOptions& options = {});

/// The sampled estimate alone (within is always true).
/// \pre as sampled_hausdorff_within. \throws InvalidInputException.
HausdorffResult sampled_hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                           const SampledHausdorffOptions& options = {});

}  // namespace papercraft
