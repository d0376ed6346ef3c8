#pragma once
// One k-way fuzzy decomposition of a region of the model (Katz & Tal 2003), the step that
// segment_fuzzy (fuzzy.h) repeats down its hierarchy: the region's dual graph, representatives
// chosen far apart, fuzzy membership from their distances, and each fuzzy band between two
// parts assigned by a minimum cut.

#include <vector>

#include "nodes/segment/face_regions.h"
#include "nodes/segment/fuzzy.h"

namespace papercraft::fuzzy_internal {

/// Dual graph of one region in compressed rows, with Katz & Tal's arc lengths.
struct RegionGraph {
  std::vector<int> faces;  // local -> model face
  std::vector<int> offsets;
  std::vector<int> targets;       // local faces
  std::vector<double> distances;  // Katz & Tal eq. (1)
  std::vector<double> geodesics;  // its geodesic term alone
  std::vector<double> angulars;   // Katz & Tal's AngDist
  std::vector<double> edge_lengths;

  int size() const { return static_cast<int>(faces.size()); }
};

/// The dual graph of `faces` (model faces of `graph`), with Katz & Tal's arc lengths.
RegionGraph region_graph(const FaceGraph& graph, const std::vector<int>& faces,
                         const FuzzySegmentOptions& options);

/// One k-way decomposition of a region (Katz & Tal): fuzzy membership from the
/// representatives' distances, then each fuzzy region between two parts assigned by a minimum
/// cut. Returns a local label per face of the region.
std::vector<int> decompose(const RegionGraph& region, const FaceGraph& graph,
                           const FuzzySegmentOptions& options);

}  // namespace papercraft::fuzzy_internal
