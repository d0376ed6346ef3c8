#include "nodes/segment/face_regions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>

#include "core/errors.h"

namespace papercraft {
namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void unite(std::vector<int>& parent, int a, int b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a == b) return;
  if (a < b) std::swap(a, b);
  parent[a] = b;  // the lowest face is the root, which keeps numberings deterministic
}

// Components of the faces through the arcs accepted by `joins`, numbered by lowest face.
template <typename Joins>
std::vector<int> components(const FaceGraph& graph, Joins joins) {
  const int n = static_cast<int>(graph.areas.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a < graph.arcs.size(); ++a) {
    if (joins(graph.arcs[a])) unite(parent, graph.arcs[a].face_a, graph.arcs[a].face_b);
  }
  std::vector<int> number(n, -1);
  std::vector<int> component(n);
  int count = 0;
  for (int f = 0; f < n; ++f) {
    const int root = find_root(parent, f);
    if (number[root] < 0) number[root] = count++;
    component[f] = number[root];
  }
  return component;
}

// Shortest path between the centroids of two faces sharing the edge p-q, with the second face
// unfolded into the plane of the first: straight across the edge, or through its nearer end
// when the straight line would miss it. (Through the edge's midpoint instead, the path between
// two long thin triangles would be far longer than their distance.)
double unfolded_distance(const Vec3& p, const Vec3& q, const Vec3& ca, const Vec3& cb) {
  const Vec3 axis = q - p;
  const double length = axis.norm();
  if (!(length > 0)) return (ca - cb).norm();
  const Vec3 unit = axis / length;
  const double xa = (ca - p).dot(unit), xb = (cb - p).dot(unit);
  const double ya = (ca - p - xa * unit).norm(), yb = (cb - p - xb * unit).norm();
  const double cross = ya + yb > 0 ? xa + (xb - xa) * ya / (ya + yb) : 0.5 * (xa + xb);
  if (cross >= 0 && cross <= length) return std::hypot(xb - xa, ya + yb);
  const Vec3& end = cross < 0 ? p : q;
  return (ca - end).norm() + (end - cb).norm();
}

}  // namespace

void require_segmentable(const Mesh& mesh, const char* function) {
  if (mesh.n_faces() == 0) {
    throw InvalidInputException(std::string(function) + ": the mesh has no faces");
  }
  require_no_deleted_elements(mesh, function);
}

FaceGraph face_graph(const Mesh& mesh) {
  FaceGraph graph;
  const std::size_t n_faces = mesh.n_faces();
  graph.centroids.resize(n_faces);
  graph.normals.resize(n_faces);
  graph.areas.resize(n_faces);
  graph.face_arcs.resize(n_faces);
  for (auto f : mesh.faces()) {
    Vec3 p[3];
    int k = 0;
    for (auto v : f.vertices()) p[k++] = to_eigen(mesh.point(v));
    const Vec3 cross = (p[1] - p[0]).cross(p[2] - p[0]);
    const double norm = cross.norm();
    graph.centroids[f.idx()] = (p[0] + p[1] + p[2]) / 3.0;
    graph.normals[f.idx()] = norm > 0 ? Vec3(cross / norm) : Vec3::Zero();
    graph.areas[f.idx()] = 0.5 * norm;
    graph.total_area += 0.5 * norm;
  }
  double length_sum = 0;
  for (auto e : mesh.edges()) {
    const Vec3 a = to_eigen(mesh.point(e.v0()));
    const Vec3 b = to_eigen(mesh.point(e.v1()));
    const double length = (b - a).norm();
    length_sum += length;
    if (e.is_boundary()) continue;
    FaceArc arc;
    arc.face_a = e.h0().face().idx();
    arc.face_b = e.h1().face().idx();
    arc.vertex_a = e.v0().idx();
    arc.vertex_b = e.v1().idx();
    arc.length = length;
    const Vec3& na = graph.normals[arc.face_a];
    const Vec3& nb = graph.normals[arc.face_b];
    arc.angle = std::acos(std::clamp(na.dot(nb), -1.0, 1.0));
    const Vec3& ca = graph.centroids[arc.face_a];
    const Vec3& cb = graph.centroids[arc.face_b];
    // Each centroid lies above the other face's plane exactly when the fold is concave; the
    // sum of both tests is symmetric in a and b.
    arc.concave = (na - nb).dot(cb - ca) > 0;
    arc.centroid_distance = unfolded_distance(a, b, ca, cb);
    const int index = static_cast<int>(graph.arcs.size());
    graph.face_arcs[arc.face_a].push_back(index);
    graph.face_arcs[arc.face_b].push_back(index);
    graph.arcs.push_back(arc);
  }
  graph.mean_edge_length = mesh.n_edges() > 0 ? length_sum / mesh.n_edges() : 0.0;
  return graph;
}

std::vector<int> face_components(const FaceGraph& graph) {
  return components(graph, [](const FaceArc&) { return true; });
}

std::vector<int> consolidate_regions(const FaceGraph& graph, const std::vector<int>& labels,
                                     double min_area) {
  const std::vector<int> piece = components(graph, [&](const FaceArc& arc) {
    return labels[arc.face_a] >= 0 && labels[arc.face_a] == labels[arc.face_b];
  });
  const int n_faces = static_cast<int>(labels.size());
  const int n_pieces = n_faces == 0 ? 0 : *std::max_element(piece.begin(), piece.end()) + 1;
  std::vector<char> excluded(n_pieces, 0);
  for (int f = 0; f < n_faces; ++f)
    if (labels[f] < 0) excluded[piece[f]] = 1;

  std::vector<double> area(n_pieces, 0.0);
  std::vector<int> piece_label(n_pieces, 0);
  for (int f = 0; f < n_faces; ++f) {
    area[piece[f]] += graph.areas[f];
    piece_label[piece[f]] = labels[f];
  }
  std::map<int, int> largest_of_label;
  for (int p = 0; p < n_pieces; ++p) {
    if (excluded[p]) continue;
    auto [it, inserted] = largest_of_label.try_emplace(piece_label[p], p);
    if (!inserted && area[p] > area[it->second]) it->second = p;
  }
  std::vector<char> primary(n_pieces, 0);
  for (const auto& [label, p] : largest_of_label) primary[p] = 1;

  std::vector<std::map<int, double>> shared(n_pieces);  // neighbour -> boundary length
  for (const FaceArc& arc : graph.arcs) {
    const int a = piece[arc.face_a];
    const int b = piece[arc.face_b];
    if (a == b || excluded[a] || excluded[b]) continue;
    shared[a][b] += arc.length;
    shared[b][a] += arc.length;
  }

  auto needs_merge = [&](int p) { return !primary[p] || area[p] < min_area; };
  std::set<std::pair<double, int>> pending;  // (area, piece), smallest first
  for (int p = 0; p < n_pieces; ++p)
    if (!excluded[p] && needs_merge(p)) pending.emplace(area[p], p);
  std::vector<int> merged_into(n_pieces);
  std::iota(merged_into.begin(), merged_into.end(), 0);
  while (!pending.empty()) {
    const int p = pending.begin()->second;
    pending.erase(pending.begin());
    if (shared[p].empty()) continue;
    int target = -1;
    double best = -1;
    for (const auto& [q, length] : shared[p]) {
      if (length > best) {
        best = length;
        target = q;
      }
    }
    const bool target_pending = needs_merge(target);
    if (target_pending) pending.erase({area[target], target});
    area[target] += area[p];
    for (const auto& [q, length] : shared[p]) {
      shared[q].erase(p);
      if (q == target) continue;
      shared[target][q] += length;
      shared[q][target] += length;
    }
    shared[p].clear();
    merged_into[p] = target;
    if (needs_merge(target)) pending.emplace(area[target], target);
  }

  auto final_piece = [&](int p) {
    while (merged_into[p] != p) p = merged_into[p];
    return p;
  };
  std::vector<int> number(n_pieces, -1);
  std::vector<int> result(n_faces);
  int count = 0;
  for (int f = 0; f < n_faces; ++f) {
    if (labels[f] < 0) {
      result[f] = -1;
      continue;
    }
    const int p = final_piece(piece[f]);
    if (number[p] < 0) number[p] = count++;
    result[f] = number[p];
  }
  return result;
}

}  // namespace papercraft
