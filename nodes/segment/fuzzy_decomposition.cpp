// One k-way fuzzy decomposition of a region (fuzzy_decomposition.h).
#include "nodes/segment/fuzzy_decomposition.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <numeric>
#include <queue>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>

#include "core/errors.h"
#include "engine/refine/refine.h"
#include "nodes/segment/face_regions.h"
#include "nodes/segment/labelled_surface.h"
#include "nodes/segment/straighten.h"

namespace papercraft::fuzzy_internal {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Faces whose distance sums approximate the centre (the first representative).
constexpr int kCentreSamples = 32;

}  // namespace

RegionGraph region_graph(const FaceGraph& graph, const std::vector<int>& faces,
                         const FuzzySegmentOptions& options) {
  RegionGraph region;
  region.faces = faces;
  std::vector<int> local(graph.areas.size(), -1);
  for (std::size_t i = 0; i < faces.size(); ++i) local[faces[i]] = static_cast<int>(i);
  auto angular = [&](const FaceArc& arc) {
    return (arc.concave ? 1.0 : options.convex_eta) * (1.0 - std::cos(arc.angle));
  };
  double geodesic_sum = 0, angular_sum = 0;
  int count = 0;
  for (int f : faces) {
    for (int a : graph.face_arcs[f]) {
      if (local[graph.other_face(a, f)] < 0) continue;
      geodesic_sum += graph.arcs[a].centroid_distance;
      angular_sum += angular(graph.arcs[a]);
      ++count;
    }
  }
  const double mean_geodesic = count > 0 ? geodesic_sum / count : 1.0;
  const double mean_angular = count > 0 ? angular_sum / count : 0.0;
  const double w = mean_angular > 0 ? options.angular_weight : 0.0;
  region.offsets.push_back(0);
  for (int f : faces) {
    for (int a : graph.face_arcs[f]) {
      const int g = local[graph.other_face(a, f)];
      if (g < 0) continue;
      const FaceArc& arc = graph.arcs[a];
      const double angle_term = mean_angular > 0 ? angular(arc) / mean_angular : 0.0;
      region.targets.push_back(g);
      region.geodesics.push_back(arc.centroid_distance);
      // Katz & Tal eq. (1); if mean_geodesic is 0 the region is degenerate anyway.
      region.distances.push_back(
          (1.0 - w) * arc.centroid_distance / std::max(mean_geodesic, 1e-300) + w * angle_term);
      region.angulars.push_back(angular(arc));
      region.edge_lengths.push_back(arc.length);
    }
    region.offsets.push_back(static_cast<int>(region.targets.size()));
  }
  return region;
}

namespace {

// Dijkstra on the dual graph with Katz & Tal's arc lengths, or with the geodesic term alone.
std::vector<double> shortest_distances(const RegionGraph& region, int source, bool geodesic) {
  const std::vector<double>& lengths = geodesic ? region.geodesics : region.distances;
  std::vector<double> distance(region.size(), kInfinity);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  distance[source] = 0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, f] = queue.top();
    queue.pop();
    if (d > distance[f]) continue;
    for (int k = region.offsets[f]; k < region.offsets[f + 1]; ++k) {
      const int g = region.targets[k];
      const double next = d + lengths[k];
      if (next < distance[g]) {
        distance[g] = next;
        queue.emplace(next, g);
      }
    }
  }
  return distance;
}

int argmax(const std::vector<double>& values) {
  return static_cast<int>(std::max_element(values.begin(), values.end()) - values.begin());
}

// The representatives (Katz & Tal: the first is the face with the least sum of distances to
// all others, each next one the farthest from those chosen; the number of parts is where that
// farthest distance G(k) drops most; two parts take the farthest pair). Chosen on geodesic
// distances: with the angular term, a concave band is costly to move along as well as across,
// so the farthest faces would lie inside a neck rather than at the ends it separates.
std::vector<int> representatives(const RegionGraph& region, const FaceGraph& graph,
                                 const FuzzySegmentOptions& options) {
  const int n = region.size();
  auto farthest_pair = [&](int start) {
    const int a = argmax(shortest_distances(region, start, true));
    const int b = argmax(shortest_distances(region, a, true));
    return std::vector<int>{a, b};
  };
  if (options.parts == 2) return farthest_pair(0);

  // The centre from distance sums to samples spread by area (all pairs would cost n runs).
  const int n_samples = std::min(n, kCentreSamples);
  std::vector<int> samples;
  double total = 0;
  for (int f : region.faces) total += graph.areas[f];
  double cumulative = 0;
  for (int i = 0; i < n && static_cast<int>(samples.size()) < n_samples; ++i) {
    cumulative += graph.areas[region.faces[i]];
    if (cumulative >= (samples.size() + 0.5) / n_samples * total) samples.push_back(i);
  }
  if (samples.empty()) samples.push_back(0);
  std::vector<std::vector<double>> sample_distances(samples.size());
  tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t s) {
    sample_distances[s] = shortest_distances(region, samples[s], true);
  });
  std::vector<double> sums(n, 0.0);
  for (const auto& d : sample_distances)
    for (int f = 0; f < n; ++f) sums[f] += d[f];
  const int centre = static_cast<int>(std::min_element(sums.begin(), sums.end()) - sums.begin());

  const int wanted = std::min(options.parts > 0 ? options.parts : options.max_parts + 1, n);
  std::vector<int> chosen{centre};
  std::vector<double> nearest = shortest_distances(region, centre, true);
  std::vector<double> farthest_distance{0.0, 0.0};  // G(k) at index k >= 2
  while (static_cast<int>(chosen.size()) < wanted) {
    const int next = argmax(nearest);
    if (!(nearest[next] > 0) || std::isinf(nearest[next])) break;
    farthest_distance.push_back(nearest[next]);
    chosen.push_back(next);
    const std::vector<double> from_next = shortest_distances(region, next, true);
    for (int f = 0; f < n; ++f) nearest[f] = std::min(nearest[f], from_next[f]);
  }
  int k = static_cast<int>(chosen.size());
  if (options.parts == 0 && k >= 3) {
    double best_drop = -kInfinity;
    for (int j = 2; j + 1 < static_cast<int>(farthest_distance.size()); ++j) {
      const double drop = farthest_distance[j] - farthest_distance[j + 1];
      if (drop > best_drop) {
        best_drop = drop;
        k = j;
      }
    }
  }
  if (k <= 2) return farthest_pair(centre);
  chosen.resize(k);
  return chosen;
}

// Maximum flow by Dinic's algorithm on an undirected network; after run(), reachable() marks
// the source side of a minimum cut.
class MinimumCut {
 public:
  explicit MinimumCut(int nodes) : adjacent_(nodes) {}

  void add_edge(int u, int v, double capacity) {
    if (!(capacity > 0) || u == v) return;
    adjacent_[u].push_back(static_cast<int>(edges_.size()));
    edges_.push_back({v, capacity});
    adjacent_[v].push_back(static_cast<int>(edges_.size()));
    edges_.push_back({u, capacity});
    total_ += capacity;
  }

  void run(int source, int sink) {
    const double eps = 1e-12 * total_;
    const int n = static_cast<int>(adjacent_.size());
    std::vector<int> level(n), next_edge(n), path;
    for (;;) {
      std::fill(level.begin(), level.end(), -1);
      std::queue<int> queue;
      level[source] = 0;
      queue.push(source);
      while (!queue.empty()) {
        const int u = queue.front();
        queue.pop();
        for (int e : adjacent_[u]) {
          if (edges_[e].capacity > eps && level[edges_[e].to] < 0) {
            level[edges_[e].to] = level[u] + 1;
            queue.push(edges_[e].to);
          }
        }
      }
      if (level[sink] < 0) return;
      std::fill(next_edge.begin(), next_edge.end(), 0);
      // Augmenting paths in the level graph, found without recursion.
      int u = source;
      path.clear();
      for (;;) {
        if (u == sink) {
          double bottleneck = kInfinity;
          for (int e : path) bottleneck = std::min(bottleneck, edges_[e].capacity);
          for (int e : path) {
            edges_[e].capacity -= bottleneck;
            edges_[e ^ 1].capacity += bottleneck;
          }
          path.clear();
          u = source;
          continue;
        }
        bool advanced = false;
        for (int& k = next_edge[u]; k < static_cast<int>(adjacent_[u].size()); ++k) {
          const int e = adjacent_[u][k];
          if (edges_[e].capacity > eps && level[edges_[e].to] == level[u] + 1) {
            path.push_back(e);
            u = edges_[e].to;
            advanced = true;
            break;
          }
        }
        if (advanced) continue;
        level[u] = -1;  // dead end
        if (path.empty()) break;
        u = edges_[path.back() ^ 1].to;
        path.pop_back();
        ++next_edge[u];
      }
    }
  }

  std::vector<char> reachable(int source) const {
    const double eps = 1e-12 * total_;
    std::vector<char> seen(adjacent_.size(), 0);
    std::vector<int> stack{source};
    seen[source] = 1;
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (int e : adjacent_[u]) {
        if (edges_[e].capacity > eps && !seen[edges_[e].to]) {
          seen[edges_[e].to] = 1;
          stack.push_back(edges_[e].to);
        }
      }
    }
    return seen;
  }

 private:
  struct Edge {
    int to;
    double capacity;
  };
  std::vector<Edge> edges_;
  std::vector<std::vector<int>> adjacent_;
  double total_ = 0;
};

}  // namespace

// One k-way decomposition of a region (Katz & Tal): fuzzy membership from the representatives'
// distances, then each fuzzy region between two parts assigned by a minimum cut.
// Returns a local label per face of the region.
std::vector<int> decompose(const RegionGraph& region, const FaceGraph& graph,
                           const FuzzySegmentOptions& options) {
  const int n = region.size();
  const std::vector<int> chosen = representatives(region, graph, options);
  const int k = static_cast<int>(chosen.size());
  std::vector<std::vector<double>> distances(k);
  tbb::parallel_for(0, k,
                    [&](int i) { distances[i] = shortest_distances(region, chosen[i], false); });
  std::vector<int> label(n, 0);
  if (k < 2) return label;

  // Probability of part i is proportional to 1 / distance to its representative, so the
  // normalised top two are p1 = d2 / (d1 + d2).
  std::vector<int> first(n), second(n);
  std::vector<char> fuzzy(n, 0);
  for (int f = 0; f < n; ++f) {
    int a = 0, b = 1;
    if (distances[b][f] < distances[a][f]) std::swap(a, b);
    for (int i = 2; i < k; ++i) {
      if (distances[i][f] < distances[a][f]) {
        b = a;
        a = i;
      } else if (distances[i][f] < distances[b][f]) {
        b = i;
      }
    }
    first[f] = a;
    second[f] = b;
    label[f] = a;
    const double sum = distances[a][f] + distances[b][f];
    const double p1 = sum > 0 ? distances[b][f] / sum : 0.5;
    fuzzy[f] = p1 <= 0.5 + options.fuzzy_epsilon;
  }

  // Each connected fuzzy region of one pair of parts: the cores beside it are contracted to
  // the source and the sink.
  std::vector<int> component(n, -1);
  for (int seed = 0; seed < n; ++seed) {
    if (!fuzzy[seed] || component[seed] >= 0) continue;
    const int a = std::min(first[seed], second[seed]);
    const int b = std::max(first[seed], second[seed]);
    auto same_pair = [&](int f) {
      return fuzzy[f] && std::min(first[f], second[f]) == a && std::max(first[f], second[f]) == b;
    };
    std::vector<int> members{seed};
    component[seed] = seed;
    for (std::size_t i = 0; i < members.size(); ++i) {
      const int f = members[i];
      for (int e = region.offsets[f]; e < region.offsets[f + 1]; ++e) {
        const int g = region.targets[e];
        if (component[g] < 0 && same_pair(g)) {
          component[g] = seed;
          members.push_back(g);
        }
      }
    }
    std::sort(members.begin(), members.end());
    const int m = static_cast<int>(members.size());
    // Katz & Tal's capacity 1 / (1 + AngDist / avg AngDist), with the average taken over this
    // fuzzy region so that the cut seeks the edges most concave relative to their surroundings,
    // and times the relative edge length so that among those it takes the shortest way.
    double angular_sum = 0, length_sum = 0;
    int arcs = 0;
    for (int f : members) {
      for (int e = region.offsets[f]; e < region.offsets[f + 1]; ++e) {
        angular_sum += region.angulars[e];
        length_sum += region.edge_lengths[e];
        ++arcs;
      }
    }
    const double mean_angular = angular_sum / std::max(arcs, 1);
    const double mean_length = std::max(length_sum / std::max(arcs, 1), 1e-300);
    auto capacity_of = [&](int e) {
      const double angle_term = mean_angular > 0 ? region.angulars[e] / mean_angular : 0.0;
      return region.edge_lengths[e] / mean_length / (1.0 + angle_term);
    };
    const int source = m, sink = m + 1;
    MinimumCut cut(m + 2);
    bool touches_a = false, touches_b = false;
    for (int i = 0; i < m; ++i) {
      const int f = members[i];
      for (int e = region.offsets[f]; e < region.offsets[f + 1]; ++e) {
        const int g = region.targets[e];
        const double capacity = capacity_of(e);
        if (component[g] == seed) {
          if (g > f) {
            const int j = static_cast<int>(std::lower_bound(members.begin(), members.end(), g) -
                                           members.begin());
            cut.add_edge(i, j, capacity);
          }
        } else if (!fuzzy[g] && label[g] == a) {
          cut.add_edge(source, i, capacity);
          touches_a = true;
        } else if (!fuzzy[g] && label[g] == b) {
          cut.add_edge(i, sink, capacity);
          touches_b = true;
        }
      }
    }
    if (touches_a && touches_b) {
      cut.run(source, sink);
      const std::vector<char> source_side = cut.reachable(source);
      for (int i = 0; i < m; ++i) label[members[i]] = source_side[i] ? a : b;
    } else if (touches_a != touches_b) {
      for (int f : members) label[f] = touches_a ? a : b;
    }
  }
  return label;
}

}  // namespace papercraft::fuzzy_internal
