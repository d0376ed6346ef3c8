#include "nodes/segment/straighten.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <queue>
#include <set>
#include <unordered_map>

#include "core/edge_map.h"
#include "core/laplacian.h"
#include "core/union_find.h"

namespace papercraft {
namespace {

// Number of connected components (through edges) of the triangles labelled `label`.
int label_components(const LabelledSoup& surface, const EdgeTriangles& edges, int label) {
  const std::size_t n = surface.triangles.size();
  UnionFind components(n);
  for (const auto& [key, triangles] : edges) {
    for (std::size_t i = 1; i < triangles.size(); ++i) {
      if (surface.labels[triangles[0]] != label || surface.labels[triangles[i]] != label) continue;
      components.unite(triangles[i], triangles[0]);
    }
  }
  int count = 0;
  for (std::size_t f = 0; f < n; ++f)
    if (surface.labels[f] == label && components.find(f) == f) ++count;
  return count;
}

OpenMesh::Vec3d unit_normal(const LabelledSoup& surface, int triangle) {
  const Triangle& t = surface.triangles[triangle];
  const OpenMesh::Vec3d n = OpenMesh::cross(surface.points[t[1]] - surface.points[t[0]],
                                            surface.points[t[2]] - surface.points[t[0]]);
  const double norm = n.norm();
  return norm > 0 ? OpenMesh::Vec3d(n / norm) : OpenMesh::Vec3d(0, 0, 0);
}

// Angle between the normals of two triangles, radians.
double normal_angle(const LabelledSoup& surface, int a, int b) {
  const double cosine = OpenMesh::dot(unit_normal(surface, a), unit_normal(surface, b));
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// Edge-path distances (Dijkstra) from the vertices marked in `sources` over `neighbours`
// (vertex, edge length); infinity where none is reached.
std::vector<double> distances_from(
    const std::vector<char>& sources,
    const std::vector<std::vector<std::pair<int, double>>>& neighbours) {
  const int n = static_cast<int>(sources.size());
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int i = 0; i < n; ++i) {
    if (sources[i]) {
      distance[i] = 0;
      queue.emplace(0.0, i);
    }
  }
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > distance[i]) continue;
    for (const auto& [j, length] : neighbours[i]) {
      if (d + length < distance[j]) {
        distance[j] = d + length;
        queue.emplace(distance[j], j);
      }
    }
  }
  return distance;
}

// The harmonic field over the union of labels a and b (`local`: union vertex of each point)
// with the Dirichlet values in `field` where free_index is -1, solved for the free vertices
// (Meyer et al. 2003 cotangent weights, raised to a small positive floor) and clamped to
// [0, 1]. False where the system cannot be solved.
bool solve_band_field(const LabelledSoup& surface, int a, int b, const std::vector<int>& local,
                      const std::vector<int>& free_index, Eigen::VectorXd& field) {
  auto in_union = [&](int f) { return surface.labels[f] == a || surface.labels[f] == b; };
  const int n = static_cast<int>(field.size());
  // Meyer et al. 2003, eq. (8), raised to a small positive floor.
  std::map<std::uint64_t, double> weight;
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    if (!in_union(static_cast<int>(f))) continue;
    const Triangle& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto& corner = surface.points[t[k]];
      const int u = t[(k + 1) % 3], w = t[(k + 2) % 3];
      weight[undirected_edge_key(u, w)] +=
          0.5 * clamped_cotangent(surface.points[u] - corner, surface.points[w] - corner, 1e5);
    }
  }
  std::vector<double> raw;
  raw.reserve(weight.size());
  for (const auto& [key, w] : weight) raw.push_back(w);
  const std::vector<double> floored = floored_weights(raw);
  std::vector<WeightedEdge> weighted;
  weighted.reserve(weight.size());
  for (const auto& [key, w] : weight) {
    const auto [lo, hi] = edge_key_vertices(key);
    weighted.push_back({local[lo], local[hi], floored[weighted.size()]});
  }
  const auto solved = solve_dirichlet(assemble_dirichlet(weighted, free_index, field));
  if (!solved) return false;
  const Eigen::VectorXd& solution = *solved;
  for (int i = 0; i < n; ++i)
    if (free_index[i] >= 0) field[i] = std::clamp(solution[free_index[i]], 0.0, 1.0);
  return true;
}

// The surface with the union of labels a and b cut along the iso-line of `field` at kValue:
// each crossed edge (in `crossing`, with its parameter from its lower-numbered end) gets a
// point, each union triangle is split there and labelled a or b by its side (`side` of each
// union vertex: -1, 0 on the line, 1); other triangles are kept.
LabelledSoup refined_along_isoline(const LabelledSoup& surface, int a, int b,
                                   const std::vector<int>& local, const std::vector<int>& side,
                                   const Eigen::VectorXd& field,
                                   const std::vector<std::uint64_t>& union_edges,
                                   const std::map<std::uint64_t, double>& crossing) {
  constexpr double kValue = 0.5;
  auto in_union = [&](int f) { return surface.labels[f] == a || surface.labels[f] == b; };
  LabelledSoup refined;
  refined.points = surface.points;
  refined.texcoords = surface.texcoords;
  refined.input_vertex = surface.input_vertex;
  std::unordered_map<std::uint64_t, int> crossing_point;
  for (std::uint64_t key : union_edges) {
    auto it = crossing.find(key);
    if (it == crossing.end()) continue;
    const int lo = edge_key_vertices(key).first, hi = edge_key_vertices(key).second;
    const double t = it->second;
    crossing_point.emplace(key, static_cast<int>(refined.points.size()));
    refined.points.push_back((1.0 - t) * surface.points[lo] + t * surface.points[hi]);
    if (!refined.texcoords.empty())
      refined.texcoords.push_back((1.0 - t) * surface.texcoords[lo] + t * surface.texcoords[hi]);
    refined.input_vertex.push_back(-1);
  }
  refined.triangles.reserve(surface.triangles.size() + 2 * crossing_point.size());
  auto emit = [&](int p, int q, int r, int s, int origin) {
    refined.triangles.push_back({p, q, r});
    refined.origin_face.push_back(origin);
    refined.labels.push_back(s < 0 ? a : b);
  };
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const Triangle& t = surface.triangles[f];
    const int origin = surface.origin_face[f];
    if (!in_union(static_cast<int>(f))) {
      refined.triangles.push_back(t);
      refined.origin_face.push_back(origin);
      refined.labels.push_back(surface.labels[f]);
      continue;
    }
    int corner_side[3], crossing[3];  // crossing[k]: new point on the edge opposite corner k
    for (int k = 0; k < 3; ++k) {
      corner_side[k] = side[local[t[k]]];
      auto it = crossing_point.find(undirected_edge_key(t[(k + 1) % 3], t[(k + 2) % 3]));
      crossing[k] = it == crossing_point.end() ? -1 : it->second;
    }
    const int n_crossings = (crossing[0] >= 0) + (crossing[1] >= 0) + (crossing[2] >= 0);
    if (n_crossings == 0) {
      int s = 0;
      for (int k = 0; k < 3; ++k) s = s != 0 ? s : corner_side[k];
      if (s == 0) {
        const double sum = field[local[t[0]]] + field[local[t[1]]] + field[local[t[2]]];
        s = sum > 3.0 * kValue ? 1 : -1;
      }
      emit(t[0], t[1], t[2], s, origin);
    } else if (n_crossings == 1) {
      // Corner r lies on the iso-line; the opposite edge is crossed.
      const int r = crossing[0] >= 0 ? 0 : (crossing[1] >= 0 ? 1 : 2);
      const int p = t[r], q = t[(r + 1) % 3], s = t[(r + 2) % 3], x = crossing[r];
      emit(p, q, x, corner_side[(r + 1) % 3], origin);
      emit(p, x, s, corner_side[(r + 2) % 3], origin);
    } else {
      // Corner r is alone on its side; the edges r-(r+1) and (r+2)-r are crossed.
      const int r = crossing[0] < 0 ? 0 : (crossing[1] < 0 ? 1 : 2);
      const int p = t[r], q = t[(r + 1) % 3], s = t[(r + 2) % 3];
      const int x = crossing[(r + 2) % 3];  // on p-q
      const int y = crossing[(r + 1) % 3];  // on s-p
      const int other = corner_side[(r + 1) % 3];
      emit(p, x, y, corner_side[r], origin);
      if ((refined.points[x] - refined.points[s]).sqrnorm() <=
          (refined.points[q] - refined.points[y]).sqrnorm()) {
        emit(x, q, s, other, origin);
        emit(x, s, y, other, origin);
      } else {
        emit(x, q, y, other, origin);
        emit(y, q, s, other, origin);
      }
    }
  }
  return refined;
}

// Straightens the boundary between labels a and b; returns false if it was left as it was.
bool straighten_pair(LabelledSoup& surface, int a, int b, const StraightenOptions& options) {
  const EdgeTriangles edges = edge_triangles(surface.triangles);
  const std::size_t n_points = surface.points.size();
  auto in_union = [&](int f) { return surface.labels[f] == a || surface.labels[f] == b; };

  std::vector<char> touches_a(n_points, 0), touches_b(n_points, 0), touches_other(n_points, 0);
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const int label = surface.labels[f];
    for (int v : surface.triangles[f]) {
      if (label == a)
        touches_a[v] = 1;
      else if (label == b)
        touches_b[v] = 1;
      else
        touches_other[v] = 1;
    }
  }

  // Union vertices, their edges (with lengths), and the a-b boundary.
  std::vector<int> local(n_points, -1);
  std::vector<int> vertices;
  for (int v = 0; v < static_cast<int>(n_points); ++v) {
    if (touches_a[v] || touches_b[v]) {
      local[v] = static_cast<int>(vertices.size());
      vertices.push_back(v);
    }
  }
  const int n = static_cast<int>(vertices.size());
  std::vector<std::vector<std::pair<int, double>>> neighbours(n);
  std::vector<std::uint64_t> union_edges;
  std::vector<char> on_boundary(n, 0);
  double boundary_length = 0, boundary_angle = 0;
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    if (!in_union(static_cast<int>(f))) continue;
    const Triangle& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int u = t[k], w = t[(k + 1) % 3];
      const std::uint64_t key = undirected_edge_key(u, w);
      const std::vector<int>& beside = edges.at(key);
      const int first = in_union(beside[0]) ? beside[0] : beside[1];
      if (first != static_cast<int>(f)) continue;  // each edge once, from its first union triangle
      union_edges.push_back(key);
      const double length = (surface.points[u] - surface.points[w]).norm();
      neighbours[local[u]].emplace_back(local[w], length);
      neighbours[local[w]].emplace_back(local[u], length);
      if (beside.size() == 2 && in_union(beside[0]) && in_union(beside[1]) &&
          surface.labels[beside[0]] != surface.labels[beside[1]]) {
        on_boundary[local[u]] = on_boundary[local[w]] = 1;
        boundary_length += length;
        boundary_angle += length * normal_angle(surface, beside[0], beside[1]);
      }
    }
  }
  // A boundary along a crease is where it belongs, and as smooth as the crease.
  if (boundary_angle >= options.crease_degrees * std::numbers::pi / 180.0 * boundary_length)
    return false;

  // Geodesic (edge-path) distance from the a-b boundary.
  if (std::find(on_boundary.begin(), on_boundary.end(), 1) == on_boundary.end()) return false;
  const std::vector<double> distance = distances_from(on_boundary, neighbours);
  // Each side keeps a core even when it is narrower than the band.
  double farthest_a = 0, farthest_b = 0;
  for (int i = 0; i < n; ++i) {
    const int v = vertices[i];
    if (!std::isfinite(distance[i]) || touches_other[v]) continue;
    if (touches_a[v] && !touches_b[v]) farthest_a = std::max(farthest_a, distance[i]);
    if (touches_b[v] && !touches_a[v]) farthest_b = std::max(farthest_b, distance[i]);
  }
  const double band = std::min({options.band_width, 0.5 * farthest_a, 0.5 * farthest_b});
  if (!(band > 0)) return false;

  // Dirichlet values; -1 marks a free vertex.
  Eigen::VectorXd field(n);
  std::vector<int> free_index(n, -1);
  int n_free = 0;
  for (int i = 0; i < n; ++i) {
    const int v = vertices[i];
    if (touches_other[v]) {
      field[i] = touches_a[v] && touches_b[v] ? 0.5 : (touches_a[v] ? 0.0 : 1.0);
    } else if (distance[i] >= band) {
      field[i] = touches_a[v] ? 0.0 : 1.0;
    } else {
      free_index[i] = n_free++;
    }
  }
  if (n_free == 0) return false;
  {
    // Every free vertex must reach a fixed one, or its field is undefined.
    std::vector<char> reached(n, 0);
    std::vector<int> stack;
    for (int i = 0; i < n; ++i)
      if (free_index[i] < 0) reached[i] = 1, stack.push_back(i);
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (const auto& [j, length] : neighbours[i])
        if (!reached[j]) reached[j] = 1, stack.push_back(j);
    }
    if (std::find(reached.begin(), reached.end(), 0) != reached.end()) return false;
  }

  if (!solve_band_field(surface, a, b, local, free_index, field)) return false;

  // Sides of the iso-line f = 1/2 (0: on it, exactly or snapped), as in cut_along_isoline.
  constexpr double kValue = 0.5;
  std::vector<int> side(n);
  for (int i = 0; i < n; ++i) side[i] = field[i] < kValue ? -1 : (field[i] > kValue ? 1 : 0);
  const double snap = std::max(options.snap_fraction, 1e-12);
  auto parameter = [&](std::uint64_t key) {
    const int i = local[edge_key_vertices(key).first], j = local[edge_key_vertices(key).second];
    return (kValue - field[i]) / (field[j] - field[i]);
  };
  std::vector<char> snapped(n, 0);
  for (std::uint64_t key : union_edges) {
    const int i = local[edge_key_vertices(key).first], j = local[edge_key_vertices(key).second];
    if (side[i] * side[j] >= 0) continue;
    const double t = parameter(key);
    if (t <= snap) snapped[i] = 1;
    if (t >= 1.0 - snap) snapped[j] = 1;
  }
  for (int i = 0; i < n; ++i)
    if (snapped[i]) side[i] = 0;

  // The iso-line crosses each crossed edge once, at parameter t from its lower-numbered end.
  std::map<std::uint64_t, double> crossing;
  for (std::uint64_t key : union_edges) {
    const int lo = edge_key_vertices(key).first, hi = edge_key_vertices(key).second;
    if (side[local[lo]] * side[local[hi]] < 0) crossing.emplace(key, parameter(key));
  }

  LabelledSoup refined =
      refined_along_isoline(surface, a, b, local, side, field, union_edges, crossing);

  const EdgeTriangles refined_edges = edge_triangles(refined.triangles);
  const int after_a = label_components(refined, refined_edges, a);
  const int after_b = label_components(refined, refined_edges, b);
  if (after_a == 0 || after_b == 0 || after_a > label_components(surface, edges, a) ||
      after_b > label_components(surface, edges, b)) {
    return false;
  }
  surface = std::move(refined);
  return true;
}

}  // namespace

void straighten_boundaries(LabelledSoup& surface, const StraightenOptions& options) {
  if (!(options.band_width > 0)) return;
  std::set<std::pair<int, int>> pairs;
  for (const auto& [key, triangles] : edge_triangles(surface.triangles)) {
    if (triangles.size() != 2) continue;
    const int a = surface.labels[triangles[0]], b = surface.labels[triangles[1]];
    if (a != b) pairs.emplace(std::min(a, b), std::max(a, b));
  }
  for (const auto& [a, b] : pairs) straighten_pair(surface, a, b, options);
}

}  // namespace papercraft
