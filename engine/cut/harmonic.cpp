#include "engine/cut/harmonic.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>

#include "core/errors.h"
#include "core/labelled_soup.h"
#include "core/laplacian.h"
#include "core/union_find.h"

namespace papercraft {

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

  const std::vector<double> weights = cotangent_edge_weights(part, options.max_cotangent);
  auto system = [&](const std::vector<double>& w) {
    std::vector<WeightedEdge> edges;
    edges.reserve(part.n_edges());
    for (auto e : part.edges()) edges.push_back({e.v0().idx(), e.v1().idx(), w[e.idx()]});
    return assemble_dirichlet(edges, free_index, field);
  };
  std::optional<Eigen::VectorXd> solution;
  if (!options.clamp_negative_weights) {
    solution = solve_dirichlet(system(weights));
    if (!solution) {
      spdlog::debug(
          "harmonic_field: cotangent system not positive definite ({} free vertices); "
          "retrying with clamped weights",
          n_free);
    }
  }
  if (!solution) {
    const DirichletSystem floored = system(floored_weights(weights));
    solution = solve_dirichlet(floored);
    if (!solution) solution = solve_dirichlet(floored, /*lu=*/true);
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

namespace {

// How far the line p0 -> x -> p1 turns at x, a point of the edge with direction `d`, once the
// faces beside the edge are unfolded into one plane (radians): straight where the two
// segments make supplementary angles with the edge.
double turn_at(const Mesh::Point& x, const Mesh::Point& d, const Mesh::Point& p0,
               const Mesh::Point& p1) {
  auto angle = [&](const Mesh::Point& v) {
    const double length = v.norm() * d.norm();
    return length > 0.0 ? std::acos(std::clamp(OpenMesh::dot(v, d) / length, -1.0, 1.0))
                        : 0.5 * std::numbers::pi;
  };
  return std::abs(std::numbers::pi - angle(p0 - x) - angle(p1 - x));
}

// Per edge, whether its crossing lies on a line with two ends apart (`next` and `count` link each
// crossing to the crossings of the faces beside it, as straighten_crossings builds them). A
// closed line (a loop around a tube or around one vertex) has no end to hold it, nor has a loop
// that leaves a vertex on the line and comes back to it: shortened pass after pass, either
// would shrink, a loop to nothing.
std::vector<char> held_by_ends(const Mesh& part, const std::vector<int>& side,
                               const std::vector<double>& t,
                               const std::vector<std::array<int, 2>>& next,
                               const std::vector<int>& count) {
  auto end_vertex = [&](int e) {  // the vertex on the line that ends the line at crossing e
    for (int k = 0; k < 2; ++k) {
      const auto h = part.halfedge_handle(part.edge_handle(e), k);
      if (part.is_boundary(h)) continue;
      const int third = part.to_vertex_handle(part.next_halfedge_handle(h)).idx();
      if (side[third] == 0) return third;
    }
    return -1;
  };
  const int edges = static_cast<int>(t.size());
  std::vector<char> held(edges, 0), seen(edges, 0);
  for (int e = 0; e < edges; ++e) {
    if (t[e] < 0 || count[e] == 2 || seen[e]) continue;
    std::vector<int> line{e};  // from this end along the line to its other end
    for (int from = e, at = next[e][0]; at >= 0 && at != e;) {
      line.push_back(at);
      if (count[at] != 2) break;
      const int after = next[at][0] != from ? next[at][0] : next[at][1];
      from = at;
      at = after;
    }
    const int first = end_vertex(line.front()), last = end_vertex(line.back());
    const bool loop = line.size() > 1 && first >= 0 && first == last;
    for (int crossing : line) {
      seen[crossing] = 1;
      held[crossing] = !loop;
    }
  }
  return held;
}

// Slides the crossings `t` (per edge: the crossing's parameter from v0 to v1, -1 where the edge
// is not crossed) along their edges, `passes` times in edge order, each to the point of its edge
// nearest to a straight path between its two neighbours on the line (the crossings of the two
// faces beside it), where the line turns by more than `min_turn` (radians) there. Faces with a
// corner on the line (`side` 0) end the line there; a closed line stays as it is.
void straighten_crossings(const Mesh& part, const std::vector<int>& side, std::vector<double>& t,
                          int passes, double min_turn) {
  const int edges = static_cast<int>(part.n_edges());
  std::vector<std::array<int, 2>> next(edges, {-1, -1});
  std::vector<int> count(edges, 0);
  for (auto face : part.faces()) {
    int crossed[3], n = 0;
    bool on_line = false;
    for (auto h : face.halfedges()) {
      if (side[h.to().idx()] == 0) on_line = true;
      if (t[h.edge().idx()] >= 0) crossed[n++] = h.edge().idx();
    }
    if (on_line || n != 2) continue;
    for (int k = 0; k < 2; ++k) {
      const int e = crossed[k], other = crossed[1 - k];
      if (count[e] < 2) next[e][count[e]] = other;
      ++count[e];
    }
  }
  const std::vector<char> held = held_by_ends(part, side, t, next, count);
  // The ends of edge e (its first halfedge's, as a smart handle's v0() and v1()).
  auto ends = [&](int e) {
    const auto h = part.halfedge_handle(part.edge_handle(e), 0);
    return std::array<Mesh::Point, 2>{part.point(part.from_vertex_handle(h)),
                                      part.point(part.to_vertex_handle(h))};
  };
  auto point = [&](int e) {
    const auto [a, b] = ends(e);
    return Mesh::Point((1.0 - t[e]) * a + t[e] * b);
  };
  for (int pass = 0; pass < passes; ++pass) {
    for (int e = 0; e < edges; ++e) {
      if (t[e] < 0 || count[e] != 2 || !held[e]) continue;
      const Mesh::Point p0 = point(next[e][0]), p1 = point(next[e][1]);
      // Named copies, not a structured binding: clang 14 cannot capture one in a lambda.
      const std::array<Mesh::Point, 2> end = ends(e);
      const Mesh::Point a = end[0], b = end[1];
      if (turn_at(point(e), b - a, p0, p1) <= min_turn) continue;
      auto length = [&](double s) {
        const Mesh::Point p = (1.0 - s) * a + s * b;
        return (p - p0).norm() + (p - p1).norm();
      };
      // The path's length is convex in s: a ternary search finds its least.
      double lo = 0.0, hi = 1.0;
      for (int i = 0; i < 40; ++i) {
        const double m0 = lo + (hi - lo) / 3, m1 = hi - (hi - lo) / 3;
        if (length(m0) <= length(m1))
          hi = m1;
        else
          lo = m0;
      }
      // Strictly inside the edge: at a corner it would meet the line's other faces there.
      t[e] = std::clamp(0.5 * (lo + hi), 1e-6, 1.0 - 1e-6);
    }
  }
}

}  // namespace

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
  // Per crossed edge, where the line crosses it (from v0 to v1); -1 elsewhere.
  std::vector<double> crossing(part.n_edges(), -1.0);
  for (auto e : part.edges()) {
    const int a = e.v0().idx();
    const int b = e.v1().idx();
    if (side[a] * side[b] < 0) crossing[e.idx()] = (value - f[a]) / (f[b] - f[a]);
  }
  if (options.straighten_passes > 0)
    straighten_crossings(part, side, crossing, options.straighten_passes,
                         options.straighten_turn_degrees * std::numbers::pi / 180.0);
  auto crossing_parameter = [&](auto e) { return crossing[e.idx()]; };
  for (auto e : part.edges()) {
    if (side[e.v0().idx()] * side[e.v1().idx()] >= 0) continue;
    const double t = crossing_parameter(e);
    // The nearer vertex snaps when within the fraction of the edge or within snap_distance.
    const double length = (part.point(e.v1()) - part.point(e.v0())).norm();
    const double near = std::max(snap, std::min(0.5, options.snap_distance / length));
    if (t <= near && t <= 0.5)
      snapped[e.v0().idx()] = 1;
    else if (t >= 1.0 - near)
      snapped[e.v1().idx()] = 1;
  }
  for (int v = 0; v < n; ++v)
    if (snapped[v]) side[v] = 0;

  LabelledSoup soup = soup_of_vertices(part);
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
  soup.origin_face.reserve(soup.triangles.capacity());
  int origin = 0;
  auto emit = [&](int a, int b, int c, int label) {
    soup.triangles.push_back({a, b, c});
    soup.origin_face.push_back(origin);
    soup.labels.push_back(label);
  };
  for (auto face : part.faces()) {
    origin = face.idx();
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

}  // namespace papercraft
