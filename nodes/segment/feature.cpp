#include "nodes/segment/feature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <queue>
#include <string>

#include "core/errors.h"
#include "nodes/segment/face_regions.h"
#include "nodes/segment/labelled_surface.h"

namespace papercraft {
namespace {


// Dijkstra from one vertex over the edges accepted by `usable`, stopped at `limit`; `settle` is
// called with each vertex in order of distance and returns true to stop.
class BoundedDijkstra {
 public:
  explicit BoundedDijkstra(const Mesh& mesh)
      : mesh_(mesh),
        distance_(mesh.n_vertices(), std::numeric_limits<double>::infinity()),
        via_(mesh.n_vertices(), -1) {}

  template <typename Usable, typename Settle>
  void run(int source, double limit, Usable usable, Settle settle) {
    for (int v : touched_) {
      distance_[v] = std::numeric_limits<double>::infinity();
      via_[v] = -1;
    }
    touched_.clear();
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    distance_[source] = 0;
    touched_.push_back(source);
    queue.emplace(0.0, source);
    while (!queue.empty()) {
      const auto [d, v] = queue.top();
      queue.pop();
      if (d > distance_[v]) continue;
      if (settle(v, d)) return;
      for (auto h : mesh_.voh_range(Mesh::VertexHandle(v))) {
        if (!usable(h.edge())) continue;
        const int w = h.to().idx();
        const double next = d + mesh_.calc_edge_length(h);
        if (next <= limit && next < distance_[w]) {
          if (std::isinf(distance_[w])) touched_.push_back(w);
          distance_[w] = next;
          via_[w] = h.idx();
          queue.emplace(next, w);
        }
      }
    }
  }

  double distance(int v) const { return distance_[v]; }
  int via(int v) const { return via_[v]; }  ///< halfedge that reached v, or -1

 private:
  const Mesh& mesh_;
  std::vector<double> distance_;
  std::vector<int> via_;
  std::vector<int> touched_;
};

// Joins the interior ends of sharp-edge chains to a nearby sharp edge or to the surface's own
// boundary (see FeatureSegmentOptions::close_gap_fraction).
void close_gaps(const Mesh& mesh, double gap, std::vector<char>& sharp) {
  if (!(gap > 0)) return;
  std::vector<int> degree(mesh.n_vertices(), 0);
  for (auto e : mesh.edges()) {
    if (!sharp[e.idx()]) continue;
    ++degree[e.v0().idx()];
    ++degree[e.v1().idx()];
  }
  BoundedDijkstra along_chains(mesh);
  BoundedDijkstra across(mesh);
  for (auto v : mesh.vertices()) {
    if (degree[v.idx()] != 1 || v.is_boundary()) continue;
    // Distances along the sharp edges tell a stretch of the end's own chain (about as far
    // along the chain as across the surface) from a feature worth joining.
    along_chains.run(
        v.idx(), 3 * gap, [&](auto e) { return sharp[e.idx()] != 0; },
        [](int, double) { return false; });
    int target = -1;
    across.run(
        v.idx(), gap, [](auto) { return true; },
        [&](int u, double d) {
          if (u == v.idx() || along_chains.distance(u) <= 3 * d) return false;
          if (degree[u] == 0 && !mesh.is_boundary(Mesh::VertexHandle(u))) return false;
          target = u;
          return true;
        });
    if (target < 0) continue;
    for (int u = target; u != v.idx();) {
      const auto h = mesh.halfedge_handle(across.via(u));
      const int e = mesh.edge_handle(h).idx();
      if (!sharp[e]) {
        sharp[e] = 1;
        ++degree[mesh.from_vertex_handle(h).idx()];
        ++degree[mesh.to_vertex_handle(h).idx()];
      }
      u = mesh.from_vertex_handle(h).idx();
    }
  }
}

}  // namespace

std::vector<Mesh> segment_feature(const Mesh& mesh, const FeatureSegmentOptions& options) {
  require_segmentable(mesh, "segment_feature");
  if (!(options.angle_degrees > 0 && options.angle_degrees < 180)) {
    throw InvalidInputException("segment_feature: angle_degrees must be in (0, 180), got " +
                                std::to_string(options.angle_degrees));
  }
  if (!(options.min_area_fraction >= 0 && options.min_area_fraction < 1)) {
    throw InvalidInputException("segment_feature: min_area_fraction must be in [0, 1), got " +
                                std::to_string(options.min_area_fraction));
  }
  if (!(options.close_gap_fraction >= 0 && std::isfinite(options.close_gap_fraction))) {
    throw InvalidInputException("segment_feature: close_gap_fraction must be >= 0, got " +
                                std::to_string(options.close_gap_fraction));
  }

  const FaceGraph graph = face_graph(mesh);
  const double threshold = options.angle_degrees * std::numbers::pi / 180.0;
  std::vector<char> sharp(mesh.n_edges(), 0);
  for (const FaceArc& arc : graph.arcs) {
    if (arc.angle > threshold) {
      const auto h =
          mesh.find_halfedge(Mesh::VertexHandle(arc.vertex_a), Mesh::VertexHandle(arc.vertex_b));
      sharp[mesh.edge_handle(h).idx()] = 1;
    }
  }
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  for (auto v : mesh.vertices()) {
    low = low.cwiseMin(to_eigen(mesh.point(v)));
    high = high.cwiseMax(to_eigen(mesh.point(v)));
  }
  close_gaps(mesh, options.close_gap_fraction * (high - low).norm(), sharp);

  // Regions: faces joined across edges that are not sharp.
  std::vector<int> parent(mesh.n_faces());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (auto e : mesh.edges()) {
    if (e.is_boundary() || sharp[e.idx()]) continue;
    const int a = find(e.h0().face().idx()), b = find(e.h1().face().idx());
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  std::vector<int> labels(mesh.n_faces());
  for (std::size_t f = 0; f < labels.size(); ++f) labels[f] = find(static_cast<int>(f));
  labels = consolidate_regions(graph, labels, options.min_area_fraction * graph.total_area);
  return build_pieces(labelled_surface(mesh, labels));
}

}  // namespace papercraft
