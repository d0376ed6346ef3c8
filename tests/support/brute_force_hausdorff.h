#pragma once
// Independent reference for distance tests: plain O(n*m) loops, no BVH and no code shared with
// core/closest_point (projection onto the plane by the normal equations, else the edges).

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft::testing {

inline double reference_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double length2 = d.squaredNorm();
  if (length2 == 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(d) / length2, 0.0, 1.0);
  return (p - (a + t * d)).norm();
}

/// Distance from p to the triangle (a, b, c), any shape (accurate to about 1e-16 / sin of the
/// smallest angle, relative to the size, for slivers).
inline double reference_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c) {
  double best = std::min({reference_segment_distance(p, a, b), reference_segment_distance(p, b, c),
                          reference_segment_distance(p, c, a)});
  // Inside the prism over the triangle (edge-side tests against the normal): the distance
  // to the plane.
  const Vec3 n = (b - a).cross(c - a);
  const double n_length = n.norm();
  if (n_length > 0.0 && n.dot((b - a).cross(p - a)) >= 0.0 && n.dot((c - b).cross(p - b)) >= 0.0 &&
      n.dot((a - c).cross(p - c)) >= 0.0) {
    best = std::min(best, std::abs(n.dot(p - a)) / n_length);
  }
  return best;
}

/// Distance from p to the union of mesh's triangles, by looping over all of them.
inline double reference_mesh_distance(const Vec3& p, const TriangleMesh& mesh) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles) {
    best = std::min(best, reference_triangle_distance(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                      mesh.vertices[t[2]]));
  }
  return best;
}

struct SampledPoint {
  Vec3 point;
  int triangle;
};

/// Barycentric grid with `divisions` steps per edge on every triangle (corners and edges
/// included). Every point of the surface lies within max_gap(mesh, divisions) of a sample.
inline std::vector<SampledPoint> grid_samples(const TriangleMesh& mesh, int divisions) {
  std::vector<SampledPoint> samples;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i <= divisions; ++i) {
      for (int j = 0; i + j <= divisions; ++j) {
        const double u = double(i) / divisions, v = double(j) / divisions;
        samples.push_back(
            {(1 - u - v) * mesh.vertices[t[0]] + u * mesh.vertices[t[1]] + v * mesh.vertices[t[2]],
             static_cast<int>(f)});
      }
    }
  }
  return samples;
}

inline double max_gap(const TriangleMesh& mesh, int divisions) {
  double longest = 0.0;
  for (const Triangle& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      longest = std::max(longest, (mesh.vertices[t[(i + 1) % 3]] - mesh.vertices[t[i]]).norm());
    }
  }
  return longest / divisions;
}

struct BruteForceHausdorff {
  double distance = 0.0;  // max over samples of both sides (<= true H)
  Vec3 point = Vec3::Zero();
  int side = 0;
  double gap = 0.0;  // true H <= distance + gap (the distance is 1-Lipschitz)
};

inline BruteForceHausdorff brute_force_one_sided(const TriangleMesh& a, const TriangleMesh& b,
                                                 int divisions) {
  BruteForceHausdorff result;
  for (const SampledPoint& s : grid_samples(a, divisions)) {
    const double d = reference_mesh_distance(s.point, b);
    if (d > result.distance) {
      result.distance = d;
      result.point = s.point;
    }
  }
  result.gap = max_gap(a, divisions);
  return result;
}

inline BruteForceHausdorff brute_force_hausdorff(const TriangleMesh& a, const TriangleMesh& b,
                                                 int divisions) {
  BruteForceHausdorff ab = brute_force_one_sided(a, b, divisions);
  BruteForceHausdorff ba = brute_force_one_sided(b, a, divisions);
  ba.side = 1;
  BruteForceHausdorff result = ab.distance >= ba.distance ? ab : ba;
  result.gap = std::max(ab.gap, ba.gap);
  return result;
}

/// A height field z = f(x, y) over [0, 1]^2 on an n x n grid of quads (2 n^2 triangles), with
/// vertices jittered by `noise` in all directions; diagonals alternate.
template <class Height>
TriangleMesh height_field(int n, Height height, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-noise, noise);
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      mesh.vertices.emplace_back(x + jitter(rng), y + jitter(rng), height(x, y) + jitter(rng));
    }
  }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        mesh.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  }
  return mesh;
}

}  // namespace papercraft::testing
