#include "core/graph_distance.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>

#include "core/errors.h"

namespace papercraft {

std::vector<double> edge_graph_distances(const Mesh& mesh, const std::vector<int>& sources) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (sources.empty()) throw InvalidInputException("edge_graph_distances: no source vertex");
  const int count = static_cast<int>(mesh.n_vertices());
  std::vector<double> distances(count, kInfinity);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int source : sources) {
    if (source < 0 || source >= count) {
      throw InvalidInputException("edge_graph_distances: source vertex " + std::to_string(source) +
                                  " is not in the mesh (" + std::to_string(count) + " vertices)");
    }
    if (distances[source] > 0.0) {
      distances[source] = 0.0;
      queue.emplace(0.0, source);
    }
  }
  while (!queue.empty()) {
    const auto [distance, v] = queue.top();
    queue.pop();
    if (distance > distances[v]) continue;
    const auto vertex = mesh.vertex_handle(v);
    const auto& point = mesh.point(vertex);
    for (auto halfedge : mesh.voh_range(vertex)) {
      const auto neighbour = halfedge.to();
      const double through = distance + (mesh.point(neighbour) - point).norm();
      if (through < distances[neighbour.idx()]) {
        distances[neighbour.idx()] = through;
        queue.emplace(through, neighbour.idx());
      }
    }
  }
  return distances;
}

int farthest_vertex(const std::vector<double>& distances) {
  int best = -1;
  for (int v = 0; v < static_cast<int>(distances.size()); ++v) {
    if (std::isfinite(distances[v]) && (best < 0 || distances[v] > distances[best])) best = v;
  }
  return best;
}

std::pair<int, int> farthest_vertex_pair(const Mesh& mesh, int sweeps) {
  int current = 0;
  std::pair<int, int> best{0, 0};
  double best_distance = -1.0;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const auto distances = edge_graph_distances(mesh, {current});
    const int far = farthest_vertex(distances);
    if (distances[far] > best_distance) {
      best_distance = distances[far];
      best = {current, far};
    }
    if (far == current) break;
    current = far;
  }
  return best;
}

}  // namespace papercraft
