#include "nodes/segment/straighten.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <unordered_map>

namespace papercraft {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

int key_low(std::uint64_t key) {
  return static_cast<int>(key >> 32);
}
int key_high(std::uint64_t key) {
  return static_cast<int>(key & 0xffffffffu);
}

using EdgeTriangles = std::unordered_map<std::uint64_t, std::vector<int>>;

EdgeTriangles edge_triangles(const LabelledSurface& surface) {
  EdgeTriangles map;
  map.reserve(3 * surface.triangles.size());
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const Triangle& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k) map[edge_key(t[k], t[(k + 1) % 3])].push_back(static_cast<int>(f));
  }
  return map;
}

// Number of connected components (through edges) of the triangles labelled `label`.
int label_components(const LabelledSurface& surface, const EdgeTriangles& edges, int label) {
  const std::size_t n = surface.triangles.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [key, triangles] : edges) {
    for (std::size_t i = 1; i < triangles.size(); ++i) {
      if (surface.labels[triangles[0]] != label || surface.labels[triangles[i]] != label) continue;
      parent[find(triangles[i])] = find(triangles[0]);
    }
  }
  int count = 0;
  for (std::size_t f = 0; f < n; ++f)
    if (surface.labels[f] == label && find(static_cast<int>(f)) == static_cast<int>(f)) ++count;
  return count;
}

double cotangent(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v) {
  constexpr double kLimit = 1e5;
  const double cross = OpenMesh::cross(u, v).norm();
  const double dot = OpenMesh::dot(u, v);
  if (cross > 0.0) return std::clamp(dot / cross, -kLimit, kLimit);
  return dot >= 0.0 ? kLimit : -kLimit;
}

OpenMesh::Vec3d unit_normal(const LabelledSurface& surface, int triangle) {
  const Triangle& t = surface.triangles[triangle];
  const OpenMesh::Vec3d n = OpenMesh::cross(surface.points[t[1]] - surface.points[t[0]],
                                            surface.points[t[2]] - surface.points[t[0]]);
  const double norm = n.norm();
  return norm > 0 ? OpenMesh::Vec3d(n / norm) : OpenMesh::Vec3d(0, 0, 0);
}

// Angle between the normals of two triangles, radians.
double normal_angle(const LabelledSurface& surface, int a, int b) {
  const double cosine = OpenMesh::dot(unit_normal(surface, a), unit_normal(surface, b));
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// Straightens the boundary between labels a and b; returns false if it was left as it was.
bool straighten_pair(LabelledSurface& surface, int a, int b, const StraightenOptions& options) {
  const EdgeTriangles edges = edge_triangles(surface);
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
      const std::uint64_t key = edge_key(u, w);
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
  if (boundary_angle >= options.crease_degrees * kPi / 180.0 * boundary_length) return false;

  // Geodesic (edge-path) distance from the a-b boundary.
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int i = 0; i < n; ++i) {
    if (on_boundary[i]) {
      distance[i] = 0;
      queue.emplace(0.0, i);
    }
  }
  if (queue.empty()) return false;
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

  // Meyer et al. 2003, eq. (8), raised to a small positive floor.
  std::map<std::uint64_t, double> weight;
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    if (!in_union(static_cast<int>(f))) continue;
    const Triangle& t = surface.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto& corner = surface.points[t[k]];
      const int u = t[(k + 1) % 3], w = t[(k + 2) % 3];
      weight[edge_key(u, w)] +=
          0.5 * cotangent(surface.points[u] - corner, surface.points[w] - corner);
    }
  }
  double positive_sum = 0;
  int positive_count = 0;
  for (const auto& [key, w] : weight) {
    if (w > 0) {
      positive_sum += w;
      ++positive_count;
    }
  }
  const double floor = 1e-6 * (positive_count > 0 ? positive_sum / positive_count : 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_free);
  for (const auto& [key, raw] : weight) {
    const double w = std::max(raw, floor);
    const int i = local[key_low(key)], j = local[key_high(key)];
    const int fi = free_index[i], fj = free_index[j];
    if (fi >= 0) triplets.emplace_back(fi, fi, w);
    if (fj >= 0) triplets.emplace_back(fj, fj, w);
    if (fi >= 0 && fj >= 0) {
      triplets.emplace_back(fi, fj, -w);
      triplets.emplace_back(fj, fi, -w);
    } else if (fi >= 0) {
      rhs[fi] += w * field[j];
    } else if (fj >= 0) {
      rhs[fj] += w * field[i];
    }
  }
  Eigen::SparseMatrix<double> matrix(n_free, n_free);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite()) return false;
  for (int i = 0; i < n; ++i)
    if (free_index[i] >= 0) field[i] = std::clamp(solution[free_index[i]], 0.0, 1.0);

  // Sides of the iso-line f = 1/2 (0: on it, exactly or snapped), as in cut_along_isoline.
  constexpr double kValue = 0.5;
  std::vector<int> side(n);
  for (int i = 0; i < n; ++i) side[i] = field[i] < kValue ? -1 : (field[i] > kValue ? 1 : 0);
  const double snap = std::max(options.snap_fraction, 1e-12);
  auto parameter = [&](std::uint64_t key) {
    const int i = local[key_low(key)], j = local[key_high(key)];
    return (kValue - field[i]) / (field[j] - field[i]);
  };
  std::vector<char> snapped(n, 0);
  for (std::uint64_t key : union_edges) {
    const int i = local[key_low(key)], j = local[key_high(key)];
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
    const int lo = key_low(key), hi = key_high(key);
    if (side[local[lo]] * side[local[hi]] < 0) crossing.emplace(key, parameter(key));
  }

  LabelledSurface refined;
  refined.points = surface.points;
  refined.texcoords = surface.texcoords;
  refined.input_vertex = surface.input_vertex;
  std::unordered_map<std::uint64_t, int> crossing_point;
  for (std::uint64_t key : union_edges) {
    auto it = crossing.find(key);
    if (it == crossing.end()) continue;
    const int lo = key_low(key), hi = key_high(key);
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
      auto it = crossing_point.find(edge_key(t[(k + 1) % 3], t[(k + 2) % 3]));
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

  const EdgeTriangles refined_edges = edge_triangles(refined);
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

void straighten_boundaries(LabelledSurface& surface, const StraightenOptions& options) {
  if (!(options.band_width > 0)) return;
  std::set<std::pair<int, int>> pairs;
  for (const auto& [key, triangles] : edge_triangles(surface)) {
    if (triangles.size() != 2) continue;
    const int a = surface.labels[triangles[0]], b = surface.labels[triangles[1]];
    if (a != b) pairs.emplace(std::min(a, b), std::max(a, b));
  }
  for (const auto& [a, b] : pairs) straighten_pair(surface, a, b, options);
}

}  // namespace papercraft
