#include "engine/select/geodesic.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/graph_distance.h"

namespace papercraft {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A strip boundary candidate: a loop or one vertex, with the graph distances from it.
struct BoundaryCandidate {
  std::vector<int> vertices;
  bool closed = false;
  std::vector<double> distances;
};

void check_part(const Mesh& part) {
  if (part.n_faces() == 0) throw InvalidInputException("boundary selection: the part has no face");
}

double distance_to(const std::vector<double>& distances, const std::vector<int>& vertices) {
  double nearest = kInfinity;
  for (int v : vertices) nearest = std::min(nearest, distances[v]);
  return nearest;
}

BoundarySelection selection_of(const BoundaryCandidate& first, const BoundaryCandidate& second) {
  return {first.vertices, second.vertices, first.closed, second.closed};
}

BoundarySelection closed_part_selection(const Mesh& part, int sweeps) {
  const auto [from, to] = farthest_vertex_pair(part, sweeps);
  return {{from}, {to}, false, false};
}

// The loop and its farthest vertex; but where every vertex lies on the loop (a part one
// triangle wide: a band of quads, a fan, a polygon cut into triangles), the farthest vertex is
// on the loop itself and a strip from the loop to it would cover nothing. Then the loop is
// split into two open chains at the two of its vertices farthest apart over the part (the
// ends of a band), first from one to the other and second the rest, run the same way: the
// strip runs between the two sides, as the band's own triangles do.
BoundarySelection one_loop_selection(const Mesh& part, const std::vector<int>& loop) {
  const std::vector<double> from_loop = edge_graph_distances(part, loop);
  const int far = farthest_vertex(from_loop);
  if (far >= 0 && from_loop[far] > 0.0) return {loop, {far}, true, false};
  if (loop.size() < 3) return {loop, {far}, true, false};
  const int u = farthest_vertex(edge_graph_distances(part, {loop.front()}));
  const int v = u < 0 ? -1 : farthest_vertex(edge_graph_distances(part, {u}));
  const auto i = static_cast<std::size_t>(std::find(loop.begin(), loop.end(), u) - loop.begin());
  const auto j = static_cast<std::size_t>(std::find(loop.begin(), loop.end(), v) - loop.begin());
  if (i >= loop.size() || j >= loop.size() || i == j) return {loop, {far}, true, false};
  // first: loop[start..end] along the loop, second: the rest, never empty.
  const std::size_t n = loop.size();
  std::size_t start = std::min(i, j), end = std::max(i, j);
  if (start == 0 && end == n - 1) end = n - 2;
  std::vector<int> first(loop.begin() + static_cast<std::ptrdiff_t>(start),
                         loop.begin() + static_cast<std::ptrdiff_t>(end) + 1);
  std::vector<int> second;
  for (std::size_t k = end + 1; k % n != start; ++k) second.push_back(loop[k % n]);
  // Both sides from the same end: the strip pairs their points in order.
  std::reverse(second.begin(), second.end());
  return {first, second, false, false};
}

// Loops first (boundary_loops order), then each loop's farthest vertex that is not on a loop.
std::vector<BoundaryCandidate> boundary_candidates(const Mesh& part,
                                                   const std::vector<std::vector<int>>& loops) {
  std::vector<char> on_boundary(part.n_vertices(), 0);
  for (const auto& loop : loops) {
    for (int v : loop) on_boundary[v] = 1;
  }
  std::vector<BoundaryCandidate> candidates;
  for (const auto& loop : loops) {
    candidates.push_back({loop, true, edge_graph_distances(part, loop)});
  }
  const std::size_t loop_count = candidates.size();
  for (std::size_t k = 0; k < loop_count; ++k) {
    const int far = farthest_vertex(candidates[k].distances);
    if (far < 0 || on_boundary[far]) continue;
    on_boundary[far] = 1;  // each vertex once
    candidates.push_back({{far}, false, edge_graph_distances(part, {far})});
  }
  return candidates;
}

}  // namespace

BoundarySelection select_geodesic(const Mesh& part, const GeodesicSelectOptions& options) {
  check_part(part);
  if (options.sweeps < 1) {
    throw InvalidInputException("select.geodesic: sweeps must be at least 1, got " +
                                std::to_string(options.sweeps));
  }
  const auto loops = boundary_loops(part);
  if (loops.empty()) return closed_part_selection(part, options.sweeps);
  if (loops.size() == 1) return one_loop_selection(part, loops.front());

  const auto candidates = boundary_candidates(part, loops);
  std::size_t best_first = 0;
  std::size_t best_second = 1;
  double best_distance = -1.0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    for (std::size_t j = i + 1; j < candidates.size(); ++j) {
      const double distance = distance_to(candidates[i].distances, candidates[j].vertices);
      if (std::isfinite(distance) && distance > best_distance) {
        best_distance = distance;
        best_first = i;
        best_second = j;
      }
    }
  }
  return selection_of(candidates[best_first], candidates[best_second]);
}

std::vector<BoundarySelection> candidate_selections(const Mesh& part) {
  check_part(part);
  const auto loops = boundary_loops(part);
  if (loops.size() < 2) return {select_geodesic(part)};
  const auto candidates = boundary_candidates(part, loops);
  std::vector<BoundarySelection> selections;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    for (std::size_t j = i + 1; j < candidates.size(); ++j) {
      selections.push_back(selection_of(candidates[i], candidates[j]));
    }
  }
  return selections;
}

Polyline selection_polyline(const Mesh& part, const std::vector<int>& vertices, bool closed) {
  if (vertices.empty()) throw InvalidInputException("selection_polyline: no vertex");
  const bool with_uvs = part.has_vertex_texcoords2D();
  Polyline polyline;
  polyline.closed = closed;
  polyline.points.reserve(vertices.size());
  for (int v : vertices) {
    if (v < 0 || v >= static_cast<int>(part.n_vertices())) {
      throw InvalidInputException("selection_polyline: vertex " + std::to_string(v) +
                                  " is not in the part (" + std::to_string(part.n_vertices()) +
                                  " vertices)");
    }
    const auto vertex = part.vertex_handle(v);
    polyline.points.push_back(to_eigen(part.point(vertex)));
    if (with_uvs) {
      const auto& uv = part.texcoord2D(vertex);
      polyline.uvs.emplace_back(uv[0], uv[1]);
    }
  }
  return polyline;
}

}  // namespace papercraft
