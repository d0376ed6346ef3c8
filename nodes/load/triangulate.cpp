// Triangulation of the file's faces: fans, ear clipping for polygons a fan would fold over, and
// for a twisted quad or another polygon out of its plane with no ear to clip, the triangulation
// that folds least.

#include "nodes/load/triangulate.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>

#include "nodes/load/messages.h"

namespace papercraft::load_internal {
namespace {

// Ear clipping of a polygon (indices into `points`, in order) in the plane orthogonal to its
// Newell normal; corner positions in the polygon go to `ears`. False when no ear is left to
// clip (a self-intersecting polygon).
bool ear_clip(const Vec3d* const* points, std::size_t size, const Vec3d& normal,
              std::vector<std::array<std::size_t, 3>>& ears) {
  // Drop the normal's dominant axis; flip so that the projected polygon runs counterclockwise.
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  }
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] < 0.0 ? -1.0 : 1.0;
  std::vector<std::array<double, 2>> p(size);
  for (std::size_t i = 0; i < size; ++i) p[i] = {(*points[i])[u], flip * (*points[i])[v]};
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
  };
  std::vector<std::size_t> ring(size);
  std::iota(ring.begin(), ring.end(), std::size_t{0});
  ears.clear();
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const std::size_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                        c = ring[(i + 1) % ring.size()];
      if (orient(a, b, c) <= 0.0) continue;  // reflex or flat corner
      bool empty = true;
      for (const std::size_t q : ring) {
        if (q == a || q == b || q == c) continue;
        if (orient(a, b, q) >= 0.0 && orient(b, c, q) >= 0.0 && orient(c, a, q) >= 0.0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      ears.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return false;
  }
  if (orient(ring[0], ring[1], ring[2]) <= 0.0) return false;
  ears.push_back({ring[0], ring[1], ring[2]});
  return true;
}

// The cosine of the angle between normals m and n; a triangle of no area agrees with nothing.
double agreement(const Vec3d& m, const Vec3d& n) {
  const double lengths = std::sqrt(OpenMesh::dot(m, m) * OpenMesh::dot(n, n));
  return lengths > 0.0 ? OpenMesh::dot(m, n) / lengths : -2.0;
}

// The two triangles of quad 0-1-2-3 over the diagonal 0-2 or 1-3, whichever gives triangles
// whose normals agree most (the cosine of the angle between them; a triangle of no area
// agrees with nothing), 0-2 on a tie.
std::vector<std::array<std::size_t, 3>> least_folded_split(const Vec3d* const* points) {
  auto normal = [&](std::size_t a, std::size_t b, std::size_t c) {
    return cross(*points[b] - *points[a], *points[c] - *points[a]);
  };
  const double over_02 = agreement(normal(0, 1, 2), normal(0, 2, 3));
  const double over_13 = agreement(normal(0, 1, 3), normal(1, 2, 3));
  if (over_02 >= over_13) return {{0, 1, 2}, {0, 2, 3}};
  return {{0, 1, 3}, {1, 2, 3}};
}

// Of every triangulation of the polygon 0..size-1 (size at most kMostFolded: 132 of them for 8
// corners), the one whose worst fold is least: the least, over its diagonals, of the cosine of
// the angle between the normals of the two triangles on either side (a triangle of no area
// agrees with nothing), the first found on a tie. Quads go to least_folded_split, which keeps
// the diagonal and the order of its triangles a twisted quad has always had.
constexpr std::size_t kMostFolded = 8;

std::vector<std::array<std::size_t, 3>> least_folded_triangulation(const Vec3d* const* points,
                                                                   std::size_t size) {
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  auto normal = [&](const std::array<std::size_t, 3>& t) {
    return cross(*points[t[1]] - *points[t[0]], *points[t[2]] - *points[t[0]]);
  };
  // Every triangulation of the corners first..last (in order): the triangle on the edge
  // first-last and the corner k between, then those of the two sides.
  const std::function<std::vector<Triangles>(std::size_t, std::size_t)> all =
      [&](std::size_t first, std::size_t last) -> std::vector<Triangles> {
    if (last - first < 2) return {Triangles{}};
    std::vector<Triangles> result;
    for (std::size_t k = first + 1; k < last; ++k)
      for (const Triangles& left : all(first, k))
        for (const Triangles& right : all(k, last)) {
          Triangles t = left;
          t.insert(t.end(), right.begin(), right.end());
          t.push_back({first, k, last});
          result.push_back(std::move(t));
        }
    return result;
  };
  Triangles best;
  double best_worst = -3.0;
  for (const Triangles& triangulation : all(0, size - 1)) {
    double worst = 1.0;
    for (std::size_t i = 0; i < triangulation.size(); ++i)
      for (std::size_t j = i + 1; j < triangulation.size(); ++j) {
        int shared = 0;
        for (std::size_t a : triangulation[i])
          for (std::size_t b : triangulation[j]) shared += a == b;
        if (shared == 2)
          worst = std::min(worst, agreement(normal(triangulation[i]), normal(triangulation[j])));
      }
    if (worst > best_worst) best = triangulation, best_worst = worst;
  }
  return best;
}

// Whether the polygon's corners lie in one plane (within 1e-9 of its extent) across `normal`:
// a self-intersecting polygon in a plane has no triangulation that does not fold over itself.
bool planar(const Vec3d* const* points, std::size_t size, const Vec3d& normal) {
  const double length = OpenMesh::norm(normal);
  if (!(length > 0.0)) return true;
  const Vec3d n = normal / length;
  double low = std::numeric_limits<double>::infinity(), high = -low, extent = 0.0;
  for (std::size_t i = 0; i < size; ++i) {
    const double height = OpenMesh::dot(*points[i], n);
    low = std::min(low, height), high = std::max(high, height);
    for (std::size_t j = i + 1; j < size; ++j)
      extent = std::max(extent, OpenMesh::norm(*points[j] - *points[i]));
  }
  return high - low <= 1e-9 * extent;
}

}  // namespace

Soup triangulate(RawMesh& raw, bool with_uvs, const LoadOptions& options, const std::string& file,
                 std::vector<std::string>& repairs) {
  Soup soup;
  soup.triangles.reserve(raw.corners.size() >= 2 * raw.n_faces()
                             ? raw.corners.size() - 2 * raw.n_faces()
                             : raw.n_faces());
  std::uint64_t polygons = 0, non_convex = 0, self_intersecting = 0, twisted_quads = 0,
                twisted_polygons = 0, with_flat_corner = 0;
  std::size_t first_self_intersecting = 0;
  std::vector<const Vec3d*> points;
  std::vector<std::array<std::size_t, 3>> ears;
  for (std::size_t f = 0; f < raw.n_faces(); ++f) {
    const std::size_t begin = raw.face_start[f];
    const std::size_t size = raw.face_start[f + 1] - begin;
    const int* corner = raw.corners.data() + begin;
    if (size > 3) {
      ++polygons;
      Vec3d normal(0.0, 0.0, 0.0);  // Newell's normal
      for (std::size_t i = 0; i < size; ++i) {
        normal += cross(raw.positions[corner[i]], raw.positions[corner[(i + 1) % size]]);
      }
      // A fan folds where one of its triangles turns against the normal, and makes a triangle
      // of no area where the fan's corner lies on the line through two others (a CAD polygon
      // with a corner in the middle of a side, where a neighbour's corner meets it): either way
      // the polygon is ear-clipped, which clips no flat corner.
      bool folds = false, flat = false;
      const double least_turn = 1e-9 * OpenMesh::norm(normal);
      for (std::size_t i = 1; i + 1 < size; ++i) {
        const Vec3d& origin = raw.positions[corner[0]];
        const Vec3d turn =
            cross(raw.positions[corner[i]] - origin, raw.positions[corner[i + 1]] - origin);
        if (OpenMesh::dot(turn, normal) < 0.0) folds = true;
        if (OpenMesh::norm(turn) <= least_turn) flat = true;
      }
      if (flat && !folds) {
        points.resize(size);
        for (std::size_t i = 0; i < size; ++i) points[i] = &raw.positions[corner[i]];
        if (ear_clip(points.data(), size, normal, ears)) {
          ++with_flat_corner;
          for (const auto& ear : ears) {
            soup.triangles.push_back({corner[ear[0]], corner[ear[1]], corner[ear[2]]});
            soup.source_face.push_back(static_cast<int>(f));
            if (with_uvs) {
              soup.corner_uv.push_back({raw.corner_uv[begin + ear[0]],
                                        raw.corner_uv[begin + ear[1]],
                                        raw.corner_uv[begin + ear[2]]});
            }
          }
          continue;
        }
      }
      if (folds) {
        ++non_convex;
        points.resize(size);
        for (std::size_t i = 0; i < size; ++i) points[i] = &raw.positions[corner[i]];
        if (!ear_clip(points.data(), size, normal, ears)) {
          // A twisted quad (a bowtie seen along its normal) or another polygon out of its plane
          // that folds over itself seen along its normal (a square with a corner raised):
          // triangulated so that its triangles fold least against each other. One in its plane
          // crosses itself: an error.
          if (size > kMostFolded || (size > 4 && planar(points.data(), size, normal))) {
            if (self_intersecting++ == 0) first_self_intersecting = f;
            continue;
          }
          ++(size == 4 ? twisted_quads : twisted_polygons);
          ears = size == 4 ? least_folded_split(points.data())
                           : least_folded_triangulation(points.data(), size);
        }
        for (const auto& ear : ears) {
          soup.triangles.push_back({corner[ear[0]], corner[ear[1]], corner[ear[2]]});
          soup.source_face.push_back(static_cast<int>(f));
          if (with_uvs) {
            soup.corner_uv.push_back({raw.corner_uv[begin + ear[0]], raw.corner_uv[begin + ear[1]],
                                      raw.corner_uv[begin + ear[2]]});
          }
        }
        continue;
      }
    }
    for (std::size_t i = 1; i + 1 < size; ++i) {
      soup.triangles.push_back({corner[0], corner[i], corner[i + 1]});
      soup.source_face.push_back(static_cast<int>(f));
      if (with_uvs) {
        soup.corner_uv.push_back(
            {raw.corner_uv[begin], raw.corner_uv[begin + i], raw.corner_uv[begin + i + 1]});
      }
    }
  }
  if (self_intersecting > 0) {
    throw_invalid(
        file,
        "mesh has " +
            counted(self_intersecting, "self-intersecting polygon", "self-intersecting polygons") +
            " (no ear to clip), first face " + std::to_string(first_self_intersecting) +
            "; triangulate it before loading");
  }
  if (non_convex > twisted_quads + twisted_polygons) {
    repairs.push_back("ear-clipped " + counted(non_convex - twisted_quads - twisted_polygons,
                                               "non-convex polygon", "non-convex polygons"));
  }
  if (with_flat_corner > 0) {
    repairs.push_back("ear-clipped " + counted(with_flat_corner, "polygon", "polygons") +
                      " with a corner on a straight side, where a fan would make triangles of no "
                      "area");
  }
  if (twisted_quads > 0) {
    repairs.push_back("split " + counted(twisted_quads, "twisted quad", "twisted quads") +
                      " (self-intersecting seen along its normal) along the diagonal whose two "
                      "triangles fold least");
  }
  if (twisted_polygons > 0) {
    repairs.push_back("triangulated " + counted(twisted_polygons, "polygon", "polygons") +
                      " out of its plane that crossed itself seen along its normal so that its "
                      "triangles fold least");
  }
  if (soup.triangles.size() > options.max_faces) {
    throw_invalid(file, "mesh has " + std::to_string(soup.triangles.size()) +
                            " triangles, more than the limit of " +
                            std::to_string(options.max_faces) + " (LoadOptions::max_faces)");
  }
  if (polygons > 0) {
    repairs.push_back(
        "triangulated " + counted(polygons, "polygon", "polygons") + " into " +
        counted(polygons + (soup.triangles.size() - raw.n_faces()), "triangle", "triangles"));
  }
  soup.positions = std::move(raw.positions);
  soup.source_vertex.resize(soup.positions.size());
  std::iota(soup.source_vertex.begin(), soup.source_vertex.end(), 0);
  return soup;
}

}  // namespace papercraft::load_internal
