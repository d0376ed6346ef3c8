#include "nodes/proxy/collapse.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace papercraft {

namespace {

// A plane quadric p -> sum_i area_i * (n_i . p + d_i)^2 as the ten coefficients of a symmetric
// 4x4 matrix, with the area it gathers.
struct Quadric {
  double a00 = 0, a01 = 0, a02 = 0, a03 = 0, a11 = 0, a12 = 0, a13 = 0, a22 = 0, a23 = 0,
         a33 = 0;
  double area = 0;

  void add_plane(const Vec3& n, double d, double weight) {
    a00 += weight * n[0] * n[0];
    a01 += weight * n[0] * n[1];
    a02 += weight * n[0] * n[2];
    a03 += weight * n[0] * d;
    a11 += weight * n[1] * n[1];
    a12 += weight * n[1] * n[2];
    a13 += weight * n[1] * d;
    a22 += weight * n[2] * n[2];
    a23 += weight * n[2] * d;
    a33 += weight * d * d;
    area += weight;
  }
  void operator+=(const Quadric& o) {
    a00 += o.a00, a01 += o.a01, a02 += o.a02, a03 += o.a03, a11 += o.a11, a12 += o.a12;
    a13 += o.a13, a22 += o.a22, a23 += o.a23, a33 += o.a33, area += o.area;
  }
  // Sum of the weighted squared plane distances of p (cancellation can make it slightly
  // negative; callers clamp).
  double operator()(const Vec3& p) const {
    const double x = p[0], y = p[1], z = p[2];
    return x * (a00 * x + 2 * (a01 * y + a02 * z + a03)) + y * (a11 * y + 2 * (a12 * z + a13)) +
           z * (a22 * z + 2 * a23) + a33;
  }
};

// Mean squared plane distance of p under q1 + q2.
double mean_error(const Quadric& q1, const Quadric& q2, const Vec3& p) {
  const double area = q1.area + q2.area;
  const double sum = std::max(0.0, q1(p) + q2(p));
  return area > 0.0 ? sum / area : 0.0;
}

struct Candidate {
  double error;
  int from, to;  // `from` is removed, `to` keeps its position
  bool operator<(const Candidate& o) const {
    if (error != o.error) return error < o.error;
    if (from != o.from) return from < o.from;
    return to < o.to;
  }
};

// Vertex -> incident triangles, compressed rows.
struct Stars {
  std::vector<int> offsets, triangles;

  void build(std::size_t vertex_count, const std::vector<Triangle>& tris) {
    offsets.assign(vertex_count + 1, 0);
    for (const Triangle& t : tris)
      for (int v : t) ++offsets[v + 1];
    for (std::size_t v = 0; v < vertex_count; ++v) offsets[v + 1] += offsets[v];
    triangles.resize(offsets.back());
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
      for (int v : tris[t]) triangles[fill[v]++] = t;
  }
  const int* begin(int v) const { return triangles.data() + offsets[v]; }
  const int* end(int v) const { return triangles.data() + offsets[v + 1]; }
  int size(int v) const { return offsets[v + 1] - offsets[v]; }
};

// The corner of t at v (0..2), or -1.
int corner(const Triangle& t, int v) {
  return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
}

// Vertices that must stay: on a boundary or non-manifold edge, or whose triangles do not form
// one closed fan (a non-manifold vertex).
std::vector<char> locked_vertices(std::size_t vertex_count, const std::vector<Triangle>& tris,
                                  const Stars& stars) {
  std::vector<char> locked(vertex_count, 0);
  std::vector<std::pair<int, int>> fan;  // per triangle at v: (next vertex, previous vertex)
  for (int v = 0; v < static_cast<int>(vertex_count); ++v) {
    fan.clear();
    for (const int* t = stars.begin(v); t != stars.end(v); ++t) {
      const Triangle& tri = tris[*t];
      const int c = corner(tri, v);
      fan.emplace_back(tri[(c + 1) % 3], tri[(c + 2) % 3]);
    }
    if (fan.empty()) {
      locked[v] = 1;
      continue;
    }
    // A closed fan: every "next" vertex is the "previous" of exactly one other triangle, and
    // walking next -> previous from the first triangle visits all of them.
    bool closed = true;
    int steps = 0;
    int at = 0;
    do {
      int following = -1, matches = 0;
      for (int i = 0; i < static_cast<int>(fan.size()); ++i)
        if (fan[i].first == fan[at].second) following = i, ++matches;
      if (matches != 1) {
        closed = false;
        break;
      }
      at = following;
      ++steps;
    } while (at != 0 && steps <= static_cast<int>(fan.size()));
    if (!closed || at != 0 || steps != static_cast<int>(fan.size())) locked[v] = 1;
  }
  return locked;
}

}  // namespace

CollapseDecimation collapse_decimation(const TriangleMesh& input, double bound,
                                       double max_normal_deviation_deg) {
  const std::size_t n = input.vertices.size();
  const std::vector<Vec3>& pos = input.vertices;
  std::vector<Triangle> tris = input.triangles;
  const double bound2 = bound * bound;
  const double min_cosine = std::cos(max_normal_deviation_deg * std::numbers::pi / 180.0);

  std::vector<Quadric> quadrics(n);
  for (const Triangle& t : tris) {
    const Vec3 cross = (pos[t[1]] - pos[t[0]]).cross(pos[t[2]] - pos[t[0]]);
    const double twice_area = cross.norm();
    if (!(twice_area > 0.0)) continue;
    const Vec3 normal = cross / twice_area;
    Quadric q;
    q.add_plane(normal, -normal.dot(pos[t[0]]), 0.5 * twice_area);
    for (int v : t) quadrics[v] += q;
  }

  Stars stars;
  stars.build(n, tris);
  const std::vector<char> locked = locked_vertices(n, tris, stars);
  std::vector<int> triangle_count(n);
  for (std::size_t v = 0; v < n; ++v) triangle_count[v] = stars.size(static_cast<int>(v));

  std::vector<char> alive;
  std::vector<int> touched(n, -1), mark(n, -1);
  std::vector<Candidate> candidates;
  CollapseDecimation result;
  int stamp = 0;

  // Whether collapsing from -> to keeps the topology and the triangles' orientation.
  const auto legal = [&](int from, int to) {
    int opposite[2], shared = 0;
    for (const int* t = stars.begin(from); t != stars.end(from); ++t) {
      const Triangle& tri = tris[*t];
      const int c = corner(tri, to);
      if (c < 0) continue;
      if (shared == 2) return false;
      opposite[shared++] = tri[0] != from && tri[0] != to ? tri[0]
                           : tri[1] != from && tri[1] != to ? tri[1]
                                                            : tri[2];
    }
    if (shared != 2 || opposite[0] == opposite[1]) return false;
    for (int o : opposite)
      if (!locked[o] && triangle_count[o] <= 3) return false;
    // The link condition: the ends share no neighbour but the two opposite vertices.
    ++stamp;
    for (const int* t = stars.begin(from); t != stars.end(from); ++t)
      for (int w : tris[*t]) mark[w] = stamp;
    for (const int* t = stars.begin(to); t != stars.end(to); ++t)
      for (int w : tris[*t])
        if (w != from && w != to && w != opposite[0] && w != opposite[1] && mark[w] == stamp)
          return false;
    // No remaining triangle of `from` turns too far or degenerates.
    for (const int* t = stars.begin(from); t != stars.end(from); ++t) {
      const Triangle& tri = tris[*t];
      if (corner(tri, to) >= 0) continue;
      const int c = corner(tri, from);
      const Vec3& p1 = pos[tri[(c + 1) % 3]];
      const Vec3& p2 = pos[tri[(c + 2) % 3]];
      const Vec3 before = (p1 - pos[from]).cross(p2 - pos[from]);
      const Vec3 after = (p1 - pos[to]).cross(p2 - pos[to]);
      const double lengths = before.norm() * after.norm();
      if (!(lengths > 0.0) || before.dot(after) < min_cosine * lengths) return false;
    }
    return true;
  };

  for (int pass = 0;; ++pass) {
    candidates.clear();
    for (const Triangle& t : tris) {
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        // Each interior edge once: from the triangle where it runs from the lower index.
        if (a > b || (locked[a] && locked[b])) continue;
        const double a_to_b = locked[a] ? std::numeric_limits<double>::infinity()
                                        : mean_error(quadrics[a], quadrics[b], pos[b]);
        const double b_to_a = locked[b] ? std::numeric_limits<double>::infinity()
                                        : mean_error(quadrics[a], quadrics[b], pos[a]);
        if (a_to_b <= b_to_a) {
          if (a_to_b <= bound2) candidates.push_back({a_to_b, a, b});
        } else if (b_to_a <= bound2) {
          candidates.push_back({b_to_a, b, a});
        }
      }
    }
    std::sort(candidates.begin(), candidates.end());
    std::size_t collapses = 0;
    alive.assign(tris.size(), 1);
    for (const Candidate& c : candidates) {
      if (touched[c.from] == pass || touched[c.to] == pass) continue;
      if (!legal(c.from, c.to)) continue;
      // Only the stars of `from`'s neighbours change (and `to`'s quadric): a later collapse
      // of this pass between untouched vertices reads unchanged stars.
      for (const int* t = stars.begin(c.from); t != stars.end(c.from); ++t)
        for (int w : tris[*t]) touched[w] = pass;
      for (const int* t = stars.begin(c.from); t != stars.end(c.from); ++t) {
        Triangle& tri = tris[*t];
        if (corner(tri, c.to) >= 0) {
          alive[*t] = 0;
          for (int w : tri) --triangle_count[w];
        } else {
          tri[corner(tri, c.from)] = c.to;
          ++triangle_count[c.to];
        }
      }
      quadrics[c.to] += quadrics[c.from];
      ++collapses;
    }
    result.passes = pass + 1;
    result.collapses += collapses;
    if (collapses == 0) break;
    std::size_t kept = 0;
    for (std::size_t t = 0; t < tris.size(); ++t)
      if (alive[t]) tris[kept++] = tris[t];
    tris.resize(kept);
    stars.build(n, tris);
  }

  // Compact: the vertices still used, in input order.
  std::vector<int> index(n, -1);
  for (const Triangle& t : tris)
    for (int v : t) index[v] = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (index[v] < 0) continue;
    index[v] = static_cast<int>(result.source_vertex.size());
    result.source_vertex.push_back(static_cast<int>(v));
    result.mesh.vertices.push_back(pos[v]);
  }
  result.mesh.triangles.reserve(tris.size());
  for (const Triangle& t : tris) result.mesh.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return result;
}

}  // namespace papercraft
