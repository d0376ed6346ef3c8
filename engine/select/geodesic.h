#pragma once
// Choosing the two boundaries of a part's strip (paper section 3.2.1; DESIGN.md "Boundary
// selection"), with graph distances along the mesh edges (Dijkstra) as the paper's
// approximation of geodesic distances:
//   0 boundaries  two vertices approximately farthest apart (repeated farthest-point sweeps);
//   1 boundary    the loop and the vertex farthest from it (a part one triangle wide: the
//                 loop split into its two sides);
//   >= 2          candidates are the loops and, for each loop, its farthest vertex unless that
//                 vertex lies on a loop (the loop is then the better candidate); `geodesic`
//                 takes the candidate pair farthest apart, `exhaustive`
//                 (engine/refine/exhaustive_select.h) the pair whose strip has the lowest
//                 certified Hausdorff error.

#include <vector>

#include "core/graph_distance.h"
#include "core/mesh.h"
#include "core/strip.h"

namespace papercraft {

/// Two strip boundaries of a part: each a boundary loop (closed, vertex indices in
/// boundary_loops order: the part on the right) or a single vertex (open, one index).
/// A loop, when there is one, is `first`, so that a strip built from first to second
/// (twist_minimizing_strip) is oriented like the part.
struct BoundarySelection {
  std::vector<int> first;
  std::vector<int> second;
  bool first_closed = false;
  bool second_closed = false;
};

struct GeodesicSelectOptions {
  /// Farthest-point sweeps for a closed part: each runs Dijkstra from the last farthest
  /// vertex; the farthest pair seen is kept. The first sweep starts at vertex 0.
  int sweeps = 4;
};

/// The selection of the paper's geodesic scheme (see the file comment). Ties go to the
/// first candidate (loops in boundary_loops order, then vertices by loop) and to the lowest
/// vertex index, so the result is deterministic.
/// \pre part has at least one face and no deleted elements; it should be connected
///      (vertices in other components count as unreachable and are never chosen).
/// \throws InvalidInputException if the part has no face or options.sweeps < 1.
/// When every vertex lies on the single boundary loop (a part one triangle wide), the loop is
/// split instead into two open chains at the two vertices farthest apart over the part: first
/// runs along the loop from one to the other, second is the rest of the loop.
BoundarySelection select_geodesic(const Mesh& part, const GeodesicSelectOptions& options = {});

/// Every selection worth building a strip for: all pairs of candidates (each pair once,
/// first before second in candidate order) for >= 2 boundary loops; the one geodesic
/// selection (default options) otherwise.
/// \pre and \throws as select_geodesic.
std::vector<BoundarySelection> candidate_selections(const Mesh& part);

/// The polyline through the given part vertices: points, and uvs when the mesh has vertex
/// texture coordinates. A single vertex gives a point (is_point()).
/// \throws InvalidInputException if `vertices` is empty or holds an index out of range.
Polyline selection_polyline(const Mesh& part, const std::vector<int>& vertices, bool closed);

}  // namespace papercraft
