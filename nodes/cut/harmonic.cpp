#include "nodes/cut/harmonic.h"

#include <spdlog/spdlog.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>

#include "core/errors.h"

namespace papercraft {
namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    parent_[a] = b;  // the smallest index is the root, which keeps orders deterministic
  }

 private:
  std::vector<std::size_t> parent_;
};

std::optional<OpenMesh::VPropHandleT<int>> input_vertex_handle(const Mesh& mesh) {
  OpenMesh::VPropHandleT<int> handle;
  if (!mesh.get_property_handle(handle, kInputVertexProperty)) return std::nullopt;
  return handle;
}

// ---------------------------------------------------------------------------------------
// Harmonic field

double clamped_cotangent(const OpenMesh::Vec3d& u, const OpenMesh::Vec3d& v, double limit) {
  const double cross = OpenMesh::cross(u, v).norm();
  const double dot = OpenMesh::dot(u, v);
  if (cross > 0.0) return std::clamp(dot / cross, -limit, limit);
  if (dot == 0.0) return 0.0;
  return dot > 0.0 ? limit : -limit;
}

// Reduced system A x = b over the free vertices; A is the cotangent Laplacian restricted to
// them (symmetric positive definite when every component has a Dirichlet vertex).
struct ReducedSystem {
  Eigen::SparseMatrix<double> matrix;
  Eigen::VectorXd rhs;
};

ReducedSystem assemble(const Mesh& part, const std::vector<double>& weights,
                       const std::vector<int>& free_index, const Eigen::VectorXd& fixed_value) {
  const int n_free = static_cast<int>(
      std::count_if(free_index.begin(), free_index.end(), [](int i) { return i >= 0; }));
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(4 * part.n_edges());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_free);
  for (auto e : part.edges()) {
    const double w = weights[e.idx()];
    const int a = e.v0().idx();
    const int b = e.v1().idx();
    const int ia = free_index[a];
    const int ib = free_index[b];
    if (ia >= 0) triplets.emplace_back(ia, ia, w);
    if (ib >= 0) triplets.emplace_back(ib, ib, w);
    if (ia >= 0 && ib >= 0) {
      triplets.emplace_back(ia, ib, -w);
      triplets.emplace_back(ib, ia, -w);
    } else if (ia >= 0) {
      rhs[ia] += w * fixed_value[b];
    } else if (ib >= 0) {
      rhs[ib] += w * fixed_value[a];
    }
  }
  ReducedSystem system;
  system.matrix.resize(n_free, n_free);
  system.matrix.setFromTriplets(triplets.begin(), triplets.end());
  system.rhs = std::move(rhs);
  return system;
}

std::optional<Eigen::VectorXd> solve_ldlt(const ReducedSystem& system) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system.matrix);
  if (solver.info() != Eigen::Success) return std::nullopt;
  // LDLT also factors indefinite matrices; a non-positive pivot means the weights are broken.
  if (solver.vectorD().size() > 0 && solver.vectorD().minCoeff() <= 0.0) return std::nullopt;
  Eigen::VectorXd x = solver.solve(system.rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
  return x;
}

std::optional<Eigen::VectorXd> solve_lu(const ReducedSystem& system) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system.matrix);
  if (solver.info() != Eigen::Success) return std::nullopt;
  Eigen::VectorXd x = solver.solve(system.rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
  return x;
}

// Non-negative weights with a tiny positive floor: an irreducible M-matrix per component, so
// the reduced system is SPD whatever the triangle shapes.
std::vector<double> clamp_weights(const std::vector<double>& weights) {
  double sum = 0.0;
  int count = 0;
  for (double w : weights) {
    if (w > 0.0) {
      sum += w;
      ++count;
    }
  }
  const double floor = 1e-6 * (count > 0 ? sum / count : 1.0);
  std::vector<double> clamped(weights.size());
  for (std::size_t i = 0; i < weights.size(); ++i) clamped[i] = std::max(weights[i], floor);
  return clamped;
}

// ---------------------------------------------------------------------------------------
// Building manifold pieces from a labelled triangle soup over a shared vertex array.

struct LabelledSoup {
  std::vector<OpenMesh::Vec3d> points;
  std::vector<OpenMesh::Vec2d> texcoords;  // empty if the part has none
  std::vector<int> input_vertex;           // empty if the part has no "v:input_vertex"
  std::vector<Triangle> triangles;
  std::vector<int> labels;  // faces with different labels are never in one piece
};

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

std::vector<Mesh> build_pieces(const LabelledSoup& soup) {
  const std::size_t n_faces = soup.triangles.size();
  // Faces of each undirected edge (at most two: the soup refines a manifold mesh).
  std::unordered_map<std::uint64_t, std::vector<int>> edge_faces;
  edge_faces.reserve(3 * n_faces);
  for (std::size_t f = 0; f < n_faces; ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k)
      edge_faces[edge_key(t[k], t[(k + 1) % 3])].push_back(static_cast<int>(f));
  }

  // Pieces: faces of equal label connected through edges. Fans: corners (face, vertex) of
  // one piece connected through edges at that vertex; each fan becomes its own output vertex.
  UnionFind pieces(n_faces);
  UnionFind fans(3 * n_faces);
  auto corner = [&](int face, int vertex) {
    const Triangle& t = soup.triangles[face];
    const int k = t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2);
    return static_cast<std::size_t>(3 * face + k);
  };
  for (const auto& [key, faces] : edge_faces) {
    for (std::size_t i = 0; i < faces.size(); ++i) {
      for (std::size_t j = i + 1; j < faces.size(); ++j) {
        const int f = faces[i];
        const int g = faces[j];
        if (soup.labels[f] != soup.labels[g]) continue;
        pieces.unite(f, g);
        const int a = static_cast<int>(key >> 32);
        const int b = static_cast<int>(key & 0xffffffffu);
        fans.unite(corner(f, a), corner(g, a));
        fans.unite(corner(f, b), corner(g, b));
      }
    }
  }

  std::vector<int> piece_of_root(n_faces, -1);
  std::vector<std::vector<int>> piece_faces;
  std::vector<int> piece_label;
  for (std::size_t f = 0; f < n_faces; ++f) {
    const std::size_t root = pieces.find(f);
    if (piece_of_root[root] < 0) {
      piece_of_root[root] = static_cast<int>(piece_faces.size());
      piece_faces.emplace_back();
      piece_label.push_back(soup.labels[f]);
    }
    piece_faces[piece_of_root[root]].push_back(static_cast<int>(f));
  }
  std::vector<std::size_t> order(piece_faces.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return piece_label[a] < piece_label[b]; });

  const bool has_texcoords = !soup.texcoords.empty();
  const bool has_input_vertex = !soup.input_vertex.empty();
  std::vector<Mesh> result;
  result.reserve(order.size());
  std::unordered_map<std::size_t, Mesh::VertexHandle> vertex_of_fan;
  for (std::size_t p : order) {
    Mesh mesh;
    if (has_texcoords) mesh.request_vertex_texcoords2D();
    OpenMesh::VPropHandleT<int> input_vertex;
    if (has_input_vertex) mesh.add_property(input_vertex, kInputVertexProperty);
    // Output vertices follow the order of the soup's vertices (input vertices first, in
    // their order), so an uncut component keeps its indices.
    std::vector<std::pair<int, std::size_t>> used;  // (soup vertex, fan)
    for (int f : piece_faces[p])
      for (int v : soup.triangles[f]) used.emplace_back(v, fans.find(corner(f, v)));
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    vertex_of_fan.clear();
    for (const auto& [v, fan] : used) {
      const auto handle = mesh.add_vertex(soup.points[v]);
      vertex_of_fan.emplace(fan, handle);
      if (has_texcoords) mesh.set_texcoord2D(handle, soup.texcoords[v]);
      if (has_input_vertex) mesh.property(input_vertex, handle) = soup.input_vertex[v];
    }
    auto vertex = [&](int face, int v) { return vertex_of_fan.at(fans.find(corner(face, v))); };
    for (int f : piece_faces[p]) {
      const Triangle& t = soup.triangles[f];
      auto added = mesh.add_face(vertex(f, t[0]), vertex(f, t[1]), vertex(f, t[2]));
      if (!added.is_valid()) {
        throw TopologyException("building a piece: refined triangle " + std::to_string(f) +
                                " (vertices " + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                                ", " + std::to_string(t[2]) +
                                ") cannot be added to its piece without a non-manifold edge");
      }
    }
    result.push_back(std::move(mesh));
  }
  return result;
}

LabelledSoup soup_of(const Mesh& mesh) {
  LabelledSoup soup;
  soup.points.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) soup.points.push_back(mesh.point(v));
  if (mesh.has_vertex_texcoords2D()) {
    for (auto v : mesh.vertices()) soup.texcoords.push_back(mesh.texcoord2D(v));
  }
  if (auto handle = input_vertex_handle(mesh)) {
    for (auto v : mesh.vertices()) soup.input_vertex.push_back(mesh.property(*handle, v));
  }
  return soup;
}

}  // namespace

Eigen::VectorXd harmonic_field(const Mesh& part, const std::vector<int>& zero_vertices,
                               const std::vector<int>& one_vertices,
                               const HarmonicOptions& options) {
  require_no_deleted_elements(part, "harmonic_field");
  if (zero_vertices.empty() || one_vertices.empty()) {
    throw InvalidInputException(
        "harmonic_field: needs at least one vertex with f = 0 and one with f = 1 (got " +
        std::to_string(zero_vertices.size()) + " and " + std::to_string(one_vertices.size()) + ")");
  }
  const int n = static_cast<int>(part.n_vertices());
  std::vector<signed char> constraint(n, -1);
  auto mark = [&](const std::vector<int>& vertices, signed char value) {
    for (int v : vertices) {
      if (v < 0 || v >= n) {
        throw InvalidInputException("harmonic_field: vertex index " + std::to_string(v) +
                                    " out of range (part has " + std::to_string(n) + " vertices)");
      }
      if (constraint[v] >= 0 && constraint[v] != value) {
        throw InvalidInputException("harmonic_field: vertex " + std::to_string(v) +
                                    " is asked to have both f = 0 and f = 1");
      }
      constraint[v] = value;
    }
  };
  mark(zero_vertices, 0);
  mark(one_vertices, 1);

  UnionFind components(n);
  for (auto e : part.edges()) components.unite(e.v0().idx(), e.v1().idx());
  std::vector<char> component_constrained(n, 0);
  for (int v = 0; v < n; ++v)
    if (constraint[v] >= 0) component_constrained[components.find(v)] = 1;

  Eigen::VectorXd field(n);
  std::vector<int> free_index(n, -1);
  int n_free = 0;
  for (int v = 0; v < n; ++v) {
    if (constraint[v] >= 0) {
      field[v] = constraint[v];
    } else if (component_constrained[components.find(v)]) {
      free_index[v] = n_free++;
    } else if (options.allow_unconstrained_components) {
      field[v] = options.unconstrained_value;
    } else {
      throw TopologyException("harmonic_field: the connected component of vertex " +
                              std::to_string(v) +
                              " has no vertex with f = 0 or f = 1, so its field is undefined");
    }
  }
  if (n_free == 0) return field;

  // Meyer et al. 2003, eq. (8): w_ij = (cot alpha_ij + cot beta_ij) / 2.
  std::vector<double> weights(part.n_edges(), 0.0);
  for (auto f : part.faces()) {
    for (auto h : f.halfedges()) {
      const auto opposite = part.point(h.next().to());
      weights[h.edge().idx()] +=
          0.5 * clamped_cotangent(part.point(h.from()) - opposite, part.point(h.to()) - opposite,
                                  options.max_cotangent);
    }
  }

  std::optional<Eigen::VectorXd> solution;
  if (!options.clamp_negative_weights) {
    solution = solve_ldlt(assemble(part, weights, free_index, field));
    if (!solution) {
      spdlog::debug(
          "harmonic_field: cotangent system not positive definite ({} free vertices); "
          "retrying with clamped weights",
          n_free);
    }
  }
  if (!solution) {
    const ReducedSystem clamped = assemble(part, clamp_weights(weights), free_index, field);
    solution = solve_ldlt(clamped);
    if (!solution) solution = solve_lu(clamped);
  }
  if (!solution) {
    throw SolverException("harmonic_field: the Laplace system on " + std::to_string(n_free) +
                          " free vertices could not be factorised, even with clamped weights "
                          "(degenerate or non-finite geometry?)");
  }
  for (int v = 0; v < n; ++v)
    if (free_index[v] >= 0) field[v] = std::clamp((*solution)[free_index[v]], 0.0, 1.0);
  return field;
}

double field_value_at(const Mesh& part, const Eigen::VectorXd& f, const Vec3& point) {
  if (f.size() != static_cast<Eigen::Index>(part.n_vertices())) {
    throw InvalidInputException("field_value_at: field has " + std::to_string(f.size()) +
                                " values but the part has " + std::to_string(part.n_vertices()) +
                                " vertices");
  }
  double best_distance = std::numeric_limits<double>::infinity();
  double best_value = std::numeric_limits<double>::quiet_NaN();
  for (auto face : part.faces()) {
    if (part.status(face).deleted()) continue;
    Vec3 p[3];
    double value[3];
    int k = 0;
    for (auto v : face.vertices()) {
      p[k] = to_eigen(part.point(v));
      value[k] = f[v.idx()];
      ++k;
    }
    // Closest point on a triangle by Voronoi regions (Ericson, Real-Time Collision Detection,
    // 5.1.5), returned as barycentric coordinates.
    const Vec3 ab = p[1] - p[0];
    const Vec3 ac = p[2] - p[0];
    const Vec3 ap = point - p[0];
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    Eigen::Vector3d bary;
    const Vec3 bp = point - p[1];
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    const Vec3 cp = point - p[2];
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    const double vc = d1 * d4 - d3 * d2;
    const double vb = d5 * d2 - d1 * d6;
    const double va = d3 * d6 - d5 * d4;
    if (d1 <= 0.0 && d2 <= 0.0) {
      bary = {1, 0, 0};
    } else if (d3 >= 0.0 && d4 <= d3) {
      bary = {0, 1, 0};
    } else if (d6 >= 0.0 && d5 <= d6) {
      bary = {0, 0, 1};
    } else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
      const double t = d1 / (d1 - d3);
      bary = {1 - t, t, 0};
    } else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
      const double t = d2 / (d2 - d6);
      bary = {1 - t, 0, t};
    } else if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
      const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
      bary = {0, 1 - t, t};
    } else {
      const double denominator = va + vb + vc;
      if (!(denominator > 0.0)) {
        bary = {1, 0, 0};  // degenerate triangle: its edges are covered by the neighbours
      } else {
        bary = {va / denominator, vb / denominator, vc / denominator};
      }
    }
    const Vec3 closest = bary[0] * p[0] + bary[1] * p[1] + bary[2] * p[2];
    const double distance = (closest - point).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best_value = bary[0] * value[0] + bary[1] * value[1] + bary[2] * value[2];
    }
  }
  if (!(best_distance < std::numeric_limits<double>::infinity())) {
    throw InvalidInputException("field_value_at: the part has no faces");
  }
  return best_value;
}

double hole_split_value(const Eigen::VectorXd& f, const std::vector<int>& loop) {
  if (loop.empty()) throw InvalidInputException("hole_split_value: the hole's loop is empty");
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  for (int v : loop) {
    if (v < 0 || v >= f.size()) {
      throw InvalidInputException("hole_split_value: loop vertex " + std::to_string(v) +
                                  " out of range (field has " + std::to_string(f.size()) +
                                  " values)");
    }
    low = std::min(low, f[v]);
    high = std::max(high, f[v]);
  }
  return 0.5 * (low + high);
}

std::vector<Mesh> cut_along_isoline(const Mesh& part, const Eigen::VectorXd& f, double value,
                                    const CutOptions& options) {
  require_no_deleted_elements(part, "cut_along_isoline");
  const int n = static_cast<int>(part.n_vertices());
  if (f.size() != n) {
    throw InvalidInputException("cut_along_isoline: field has " + std::to_string(f.size()) +
                                " values but the part has " + std::to_string(n) + " vertices");
  }
  if (!f.allFinite() || !std::isfinite(value)) {
    throw InvalidInputException("cut_along_isoline: field or iso-value is not finite");
  }
  if (!(options.snap_fraction >= 0.0 && options.snap_fraction < 0.5)) {
    throw InvalidInputException("cut_along_isoline: snap_fraction " +
                                std::to_string(options.snap_fraction) + " is outside [0, 0.5)");
  }
  if (!(options.snap_distance >= 0.0 && std::isfinite(options.snap_distance))) {
    throw InvalidInputException("cut_along_isoline: snap_distance " +
                                std::to_string(options.snap_distance) +
                                " is negative or not finite");
  }
  if (n == 0 || value <= f.minCoeff() || value >= f.maxCoeff()) return {part};

  // Side of each vertex: -1 below, +1 above, 0 on the iso-line (exactly, or snapped).
  std::vector<int> side(n);
  for (int v = 0; v < n; ++v) side[v] = f[v] < value ? -1 : (f[v] > value ? 1 : 0);
  const double snap = std::max(options.snap_fraction, 1e-12);
  std::vector<char> snapped(n, 0);
  auto crossing_parameter = [&](auto e) {
    const int a = e.v0().idx();
    const int b = e.v1().idx();
    return (value - f[a]) / (f[b] - f[a]);
  };
  for (auto e : part.edges()) {
    if (side[e.v0().idx()] * side[e.v1().idx()] >= 0) continue;
    const double t = crossing_parameter(e);
    // The nearer vertex snaps when within the fraction of the edge or within snap_distance.
    const double length = (part.point(e.v1()) - part.point(e.v0())).norm();
    const double near = std::max(snap, std::min(0.5, options.snap_distance / length));
    if (t <= near && t <= 0.5) snapped[e.v0().idx()] = 1;
    else if (t >= 1.0 - near) snapped[e.v1().idx()] = 1;
  }
  for (int v = 0; v < n; ++v)
    if (snapped[v]) side[v] = 0;

  LabelledSoup soup = soup_of(part);
  std::vector<int> edge_vertex(part.n_edges(), -1);
  for (auto e : part.edges()) {
    const int a = e.v0().idx();
    const int b = e.v1().idx();
    if (side[a] * side[b] >= 0) continue;
    const double t = crossing_parameter(e);
    edge_vertex[e.idx()] = static_cast<int>(soup.points.size());
    soup.points.push_back((1.0 - t) * part.point(e.v0()) + t * part.point(e.v1()));
    if (!soup.texcoords.empty()) {
      soup.texcoords.push_back((1.0 - t) * soup.texcoords[a] + t * soup.texcoords[b]);
    }
    if (!soup.input_vertex.empty()) soup.input_vertex.push_back(-1);
  }

  soup.triangles.reserve(part.n_faces() + 2 * part.n_edges() / 3);
  soup.labels.reserve(soup.triangles.capacity());
  auto emit = [&](int a, int b, int c, int label) {
    soup.triangles.push_back({a, b, c});
    soup.labels.push_back(label);
  };
  for (auto face : part.faces()) {
    int corner[3];
    int crossing[3];  // new vertex on the edge opposite corner k, or -1
    int k = 0;
    for (auto h : face.halfedges()) {
      corner[k] = h.from().idx();
      crossing[(k + 2) % 3] = edge_vertex[h.edge().idx()];
      ++k;
    }
    const int n_crossings = (crossing[0] >= 0) + (crossing[1] >= 0) + (crossing[2] >= 0);
    if (n_crossings == 0) {
      int label = 0;
      for (int c : corner) label = label != 0 ? label : side[c];
      if (label == 0) {
        // Every corner lies on the iso-line (snapped): decide by the unsnapped field.
        label = f[corner[0]] + f[corner[1]] + f[corner[2]] > 3.0 * value ? 1 : -1;
      }
      emit(corner[0], corner[1], corner[2], label);
    } else if (n_crossings == 1) {
      // One corner on the iso-line, the opposite edge crossed.
      int r = crossing[0] >= 0 ? 0 : (crossing[1] >= 0 ? 1 : 2);
      const int a = corner[r];
      const int b = corner[(r + 1) % 3];
      const int c = corner[(r + 2) % 3];
      const int p = crossing[r];
      emit(a, b, p, side[b]);
      emit(a, p, c, side[c]);
    } else {
      // Corner r is alone on its side; the edges r-(r+1) and r-(r+2) are crossed.
      int r = crossing[0] < 0 ? 0 : (crossing[1] < 0 ? 1 : 2);
      const int a = corner[r];
      const int b = corner[(r + 1) % 3];
      const int c = corner[(r + 2) % 3];
      const int p = crossing[(r + 2) % 3];  // on a-b
      const int q = crossing[(r + 1) % 3];  // on c-a
      emit(a, p, q, side[a]);
      // The quad p-b-c-q is split along its shorter diagonal.
      if ((soup.points[p] - soup.points[c]).sqrnorm() <=
          (soup.points[b] - soup.points[q]).sqrnorm()) {
        emit(p, b, c, side[b]);
        emit(p, c, q, side[b]);
      } else {
        emit(p, b, q, side[b]);
        emit(q, b, c, side[b]);
      }
    }
  }

  const bool has_below = std::find(soup.labels.begin(), soup.labels.end(), -1) != soup.labels.end();
  const bool has_above = std::find(soup.labels.begin(), soup.labels.end(), 1) != soup.labels.end();
  if (!has_below || !has_above) return {part};
  return build_pieces(soup);
}

std::vector<Mesh> split_connected_components(const Mesh& mesh) {
  require_no_deleted_elements(mesh, "split_connected_components");
  LabelledSoup soup = soup_of(mesh);
  soup.triangles.reserve(mesh.n_faces());
  for (auto face : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (auto v : face.vertices()) t[k++] = v.idx();
    soup.triangles.push_back(t);
  }
  soup.labels.assign(soup.triangles.size(), 0);
  return build_pieces(soup);
}

}  // namespace papercraft
