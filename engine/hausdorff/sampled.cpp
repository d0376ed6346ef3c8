#include "engine/hausdorff/sampled.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/bvh.h"
#include "core/errors.h"

namespace papercraft {
namespace {

struct Sample {
  Vec3 point;
  int triangle;
};

double triangle_area(const TriangleMesh& mesh, const Triangle& t) {
  const Vec3& a = mesh.vertices[t[0]];
  return 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
}

std::vector<Sample> sample_surface(const TriangleMesh& mesh,
                                   const SampledHausdorffOptions& options) {
  std::vector<Sample> samples;
  double total_area = 0.0, total_length = 0.0;
  for (const Triangle& t : mesh.triangles) {
    total_area += triangle_area(mesh, t);
    for (int i = 0; i < 3; ++i) {
      total_length += (mesh.vertices[t[(i + 1) % 3]] - mesh.vertices[t[i]]).norm();
    }
  }
  const double face_density =
      total_area > 0.0 ? static_cast<double>(options.face_samples) / total_area : 0.0;
  const double edge_density =
      total_area > 0.0 ? std::sqrt(face_density)
                       : (total_length > 0.0 ? options.face_samples / total_length : 0.0);

  if (options.sample_vertices) {
    std::vector<int> owner(mesh.vertices.size(), -1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      for (int v : mesh.triangles[f]) {
        if (owner[v] < 0) owner[v] = static_cast<int>(f);
      }
    }
    for (std::size_t v = 0; v < owner.size(); ++v) {
      if (owner[v] >= 0) samples.push_back({mesh.vertices[v], owner[v]});
    }
  }
  if (options.sample_edges) {
    std::vector<std::pair<std::pair<int, int>, int>> edges;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const Triangle& t = mesh.triangles[f];
      for (int i = 0; i < 3; ++i) {
        const int u = t[i], w = t[(i + 1) % 3];
        edges.push_back({{std::min(u, w), std::max(u, w)}, static_cast<int>(f)});
      }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (e > 0 && edges[e].first == edges[e - 1].first) continue;
      const Vec3& p = mesh.vertices[edges[e].first.first];
      const Vec3& q = mesh.vertices[edges[e].first.second];
      const int segments = static_cast<int>(std::ceil((q - p).norm() * edge_density));
      for (int i = 1; i < segments; ++i) {
        samples.push_back({p + (q - p) * (static_cast<double>(i) / segments), edges[e].second});
      }
    }
  }
  // Stratified: the centroids of the k*k similar sub-triangles (Metro's "similar triangles").
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const double area = triangle_area(mesh, t);
    if (area <= 0.0) continue;
    const int k = std::max(1, static_cast<int>(std::lround(std::sqrt(area * face_density))));
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 ab = mesh.vertices[t[1]] - a;
    const Vec3 ac = mesh.vertices[t[2]] - a;
    for (int i = 0; i < k; ++i) {
      for (int j = 0; i + j < k; ++j) {
        samples.push_back(
            {a + ab * ((i + 1.0 / 3) / k) + ac * ((j + 1.0 / 3) / k), static_cast<int>(f)});
        if (i + j + 2 <= k) {
          samples.push_back(
              {a + ab * ((i + 2.0 / 3) / k) + ac * ((j + 2.0 / 3) / k), static_cast<int>(f)});
        }
      }
    }
  }
  return samples;
}

void validate(const TriangleMesh& mesh, const char* name) {
  if (mesh.triangles.empty()) {
    throw InvalidInputException(std::string("sampled Hausdorff distance: mesh ") + name +
                                " has no triangles");
  }
}

}  // namespace

HausdorffResult sampled_hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b,
                                           const SampledHausdorffOptions& options) {
  validate(a, "a");
  validate(b, "b");
  const TriangleBvh tree_a(a), tree_b(b);  // also validates indices and coordinates
  HausdorffResult result;
  result.certified = false;
  result.within = true;
  for (int side = 0; side < 2; ++side) {
    const std::vector<Sample> samples = sample_surface(side == 0 ? a : b, options);
    const TriangleBvh& target = side == 0 ? tree_b : tree_a;
    std::vector<double> distances(samples.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        int previous = -1;
                        for (std::size_t s = range.begin(); s != range.end(); ++s) {
                          const BvhClosestHit hit =
                              previous >= 0 ? target.closest(samples[s].point,
                                                             std::span<const int>(&previous, 1))
                                            : target.closest(samples[s].point);
                          distances[s] = hit.distance;
                          previous = hit.triangle;
                        }
                      });
    for (std::size_t s = 0; s < samples.size(); ++s) {
      if (distances[s] > result.lower || result.witness.triangle < 0) {
        result.lower = std::max(result.lower, distances[s]);
        result.witness = {samples[s].point, side, samples[s].triangle, distances[s]};
      }
    }
    result.evaluations += samples.size();
  }
  result.upper = result.lower;
  return result;
}

HausdorffResult sampled_hausdorff_within(const TriangleMesh& a, const TriangleMesh& b, double tau,
                                         const SampledHausdorffOptions& options) {
  if (!std::isfinite(tau) || tau <= 0.0) {
    throw InvalidInputException("sampled Hausdorff distance: tau must be finite and > 0, got " +
                                std::to_string(tau));
  }
  HausdorffResult result = sampled_hausdorff_distance(a, b, options);
  result.within = result.lower <= tau;
  return result;
}

}  // namespace papercraft
