#pragma once
// segment.feature: parts separated by sharp edges (Massarwi, Gotsman, Elber 2007, section
// 3.1: "meaningful parts in a typical mesh are frequently separated by sharp edges").

#include <vector>

#include "core/mesh.h"

namespace papercraft {

struct FeatureSegmentOptions {
  /// An interior edge is sharp when the angle between its two face normals exceeds this
  /// (degrees, in (0, 180)).
  double angle_degrees = 40;
  /// A region smaller than this fraction of the total area is merged into the neighbour with
  /// which it shares the longest boundary, smallest region first. In [0, 1).
  double min_area_fraction = 0.01;
  /// A chain of sharp edges that ends inside the surface is extended along the shortest edge
  /// path to another sharp edge (of another chain, or of a distant stretch of its own, so that
  /// an almost closed loop closes) or to the surface's boundary, when that path is at most this
  /// fraction of the bounding-box diagonal. >= 0; 0 closes nothing.
  double close_gap_fraction = 0.05;
};

/// Splits `mesh` into the regions bounded by sharp edges (after closing near-gaps and merging
/// small regions). Every face of `mesh` is in exactly one part, unchanged; parts share their
/// boundary vertices (bit-identical coordinates) and carry "v:input_vertex" (the input's
/// property, or the input vertex index if it has none) and texture coordinates if `mesh` has
/// them. Each part is connected and a 2-manifold (a vertex where a part touches itself is
/// duplicated). Parts are ordered by their lowest input face. A connected component of the
/// input smaller than min_area_fraction stays a part of its own.
/// \pre mesh is a triangle mesh without deleted elements.
/// \throws InvalidInputException if mesh has no faces or deleted elements, or an option is out
///   of range.
std::vector<Mesh> segment_feature(const Mesh& mesh, const FeatureSegmentOptions& options = {});

}  // namespace papercraft
