// Triangulation of the file's faces: fans, ear clipping for polygons a fan would fold over, and
// for a twisted quad (no ear to clip) the diagonal that folds least.

#include "nodes/load/triangulate.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

// The two triangles of quad 0-1-2-3 over the diagonal 0-2 or 1-3, whichever gives triangles
// whose normals agree most (the cosine of the angle between them; a triangle of no area
// agrees with nothing).
std::vector<std::array<std::size_t, 3>> least_folded_split(const Vec3d* const* points) {
  auto normal = [&](std::size_t a, std::size_t b, std::size_t c) {
    return cross(*points[b] - *points[a], *points[c] - *points[a]);
  };
  auto agreement = [&](const Vec3d& m, const Vec3d& n) {
    const double lengths = std::sqrt(OpenMesh::dot(m, m) * OpenMesh::dot(n, n));
    return lengths > 0.0 ? OpenMesh::dot(m, n) / lengths : -2.0;
  };
  const double over_02 = agreement(normal(0, 1, 2), normal(0, 2, 3));
  const double over_13 = agreement(normal(0, 1, 3), normal(1, 2, 3));
  if (over_02 >= over_13) return {{0, 1, 2}, {0, 2, 3}};
  return {{0, 1, 3}, {1, 2, 3}};
}

}  // namespace

Soup triangulate(RawMesh& raw, bool with_uvs, const LoadOptions& options, const std::string& file,
                 std::vector<std::string>& repairs) {
  Soup soup;
  soup.triangles.reserve(raw.corners.size() >= 2 * raw.n_faces()
                             ? raw.corners.size() - 2 * raw.n_faces()
                             : raw.n_faces());
  std::uint64_t polygons = 0, non_convex = 0, self_intersecting = 0, twisted_quads = 0;
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
      bool folds = false;
      for (std::size_t i = 1; i + 1 < size; ++i) {
        const Vec3d& origin = raw.positions[corner[0]];
        const Vec3d turn =
            cross(raw.positions[corner[i]] - origin, raw.positions[corner[i + 1]] - origin);
        if (OpenMesh::dot(turn, normal) < 0.0) folds = true;
      }
      if (folds) {
        ++non_convex;
        points.resize(size);
        for (std::size_t i = 0; i < size; ++i) points[i] = &raw.positions[corner[i]];
        if (!ear_clip(points.data(), size, normal, ears)) {
          if (size != 4) {
            if (self_intersecting++ == 0) first_self_intersecting = f;
            continue;
          }
          // A twisted quad (a bowtie seen along its normal): split along the diagonal whose
          // two triangles fold least against each other.
          ++twisted_quads;
          ears = least_folded_split(points.data());
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
  if (non_convex > twisted_quads) {
    repairs.push_back("ear-clipped " + counted(non_convex - twisted_quads, "non-convex polygon",
                                               "non-convex polygons"));
  }
  if (twisted_quads > 0) {
    repairs.push_back("split " + counted(twisted_quads, "twisted quad", "twisted quads") +
                      " (self-intersecting seen along its normal) along the diagonal whose two "
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
