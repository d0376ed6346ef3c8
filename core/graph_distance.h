#pragma once
// Shortest paths along a mesh's edges (Dijkstra, Euclidean edge lengths): the approximation of
// geodesic distance that boundary selection and the cut's across-field use (paper 3.2.1).

#include <utility>
#include <vector>

#include "core/mesh.h"

namespace papercraft {

/// Distances along mesh edges from the nearest of `sources` to every vertex; +infinity for
/// vertices not connected to any source.
/// \pre mesh has no deleted elements. \throws InvalidInputException if `sources` is empty or
/// holds an index out of range.
std::vector<double> edge_graph_distances(const Mesh& mesh, const std::vector<int>& sources);

/// The vertex of largest finite distance (the lowest index on ties), or -1 if none is finite.
int farthest_vertex(const std::vector<double>& distances);

/// Two vertices approximately farthest apart: `sweeps` farthest-point sweeps, each from the
/// previous sweep's farthest vertex, the first from vertex 0; the farthest pair seen is kept
/// (the first on ties). {0, 0} for a mesh whose vertex 0 reaches nothing.
/// \pre mesh has a vertex and no deleted elements; sweeps >= 1.
std::pair<int, int> farthest_vertex_pair(const Mesh& mesh, int sweeps);

}  // namespace papercraft
