// Checks of the raw faces and the triangle soup, and the safe repairs: unreferenced and duplicate
// vertices, degenerate and duplicate faces. check_topology_and_orient (the non-manifold
// vertices and edges, the orientation) is in topology.cpp.

#include "nodes/load/repair.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "core/edge_map.h"
#include "core/union_find.h"
#include "nodes/load/messages.h"

namespace papercraft::load_internal {
namespace {

// Keeps the vertices with target[v] == v; any other v becomes the kept vertex target[v]
// (target[v] < v), or is dropped when target[v] is -1.
void compact_vertices(Soup& soup, const std::vector<int>& target) {
  std::vector<int> new_index(soup.positions.size(), -1);
  int next = 0;
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    if (target[v] == static_cast<int>(v)) {
      soup.positions[next] = soup.positions[v];
      soup.source_vertex[next] = soup.source_vertex[v];
      new_index[v] = next++;
    } else if (target[v] >= 0) {
      new_index[v] = new_index[target[v]];
    }
  }
  soup.positions.resize(next);
  soup.source_vertex.resize(next);
  for (Triangle3& t : soup.triangles) {
    for (int& v : t) v = new_index[v];
  }
}

}  // namespace

void check_raw_faces(const RawMesh& raw, const std::string& file, bool repair) {
  const std::size_t vertices = raw.positions.size();
  std::uint64_t non_finite = 0, short_faces = 0, out_of_range = 0, repeated = 0;
  std::size_t first_non_finite = 0, first_short = 0, first_out = 0, first_repeated = 0;
  std::int64_t first_bad_index = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    const Vec3d& p = raw.positions[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      if (non_finite++ == 0) first_non_finite = v;
    }
  }
  if (non_finite > 0) {
    const Vec3d& p = raw.positions[first_non_finite];
    throw_invalid(file, "mesh has " + counted(non_finite, "vertex", "vertices") +
                            " with non-finite coordinates (NaN or infinite), first vertex " +
                            std::to_string(first_non_finite) + " (" + std::to_string(p[0]) + ", " +
                            std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")");
  }
  for (std::size_t f = 0; f < raw.n_faces(); ++f) {
    const std::size_t begin = raw.face_start[f];
    const std::size_t end = raw.face_start[f + 1];
    if (end - begin < 3) {
      if (short_faces++ == 0) first_short = f;
      continue;
    }
    bool bad = false;
    for (std::size_t c = begin; c < end; ++c) {
      const int index = raw.corners[c];
      if (index < 0 || static_cast<std::size_t>(index) >= vertices) {
        if (!bad && out_of_range++ == 0) {
          first_out = f;
          first_bad_index = index;
        }
        bad = true;
      }
    }
    if (bad || (repair && end - begin == 3)) continue;  // a triangle of no area: healed
    for (std::size_t c = begin; c < end && !bad; ++c) {
      for (std::size_t d = c + 1; d < end; ++d) {
        if (raw.corners[c] == raw.corners[d]) {
          if (repeated++ == 0) first_repeated = f;
          bad = true;
          break;
        }
      }
    }
  }
  if (short_faces > 0) {
    throw_invalid(
        file, "mesh has " + counted(short_faces, "face", "faces") +
                  " with fewer than 3 vertices (degenerate), first face " +
                  std::to_string(first_short) + " (" +
                  std::to_string(raw.face_start[first_short + 1] - raw.face_start[first_short]) +
                  " vertices)");
  }
  if (out_of_range > 0) {
    throw_invalid(file, "mesh has " + counted(out_of_range, "face", "faces") +
                            " with out-of-range vertex indices, first face " +
                            std::to_string(first_out) + " refers to vertex " +
                            std::to_string(first_bad_index) + " but there are " +
                            counted(vertices, "vertex", "vertices") + " (indices are 0-based)");
  }
  if (repeated > 0) {
    throw_invalid(file, "mesh has " + counted(repeated, "degenerate face", "degenerate faces") +
                            " (a vertex repeated), first face " + std::to_string(first_repeated));
  }
}

std::size_t remove_unreferenced_vertices(Soup& soup) {
  std::vector<int> target(soup.positions.size(), -1);
  for (const Triangle3& t : soup.triangles) {
    for (int v : t) target[v] = v;
  }
  const auto removed = static_cast<std::size_t>(std::count(target.begin(), target.end(), -1));
  if (removed > 0) compact_vertices(soup, target);
  return removed;
}

std::size_t merge_duplicate_vertices(Soup& soup, double epsilon) {
  const std::size_t n = soup.positions.size();
  std::vector<int> target(n);
  std::iota(target.begin(), target.end(), 0);
  const std::vector<Vec3d>& p = soup.positions;
  if (epsilon <= 0.0) {
    // Each vertex goes to the first vertex of its exact position (-0 equals 0; a NaN
    // coordinate equals nothing): an open-addressing table of vertex indices by position.
    auto normal = [&](std::size_t v, int axis) { return p[v][axis] == 0.0 ? 0.0 : p[v][axis]; };
    auto hash = [&](std::size_t v) {
      std::uint64_t h = 0;
      for (int axis = 0; axis < 3; ++axis) {
        const double x = normal(v, axis);
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof x);
        h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
        h ^= h >> 29;
      }
      return h;
    };
    std::size_t size = 16;
    while (size < 2 * n) size *= 2;
    std::vector<int> table(size, -1);
    for (std::size_t v = 0; v < n; ++v) {
      if (std::isnan(p[v][0]) || std::isnan(p[v][1]) || std::isnan(p[v][2])) continue;
      for (std::size_t slot = hash(v) & (size - 1);; slot = (slot + 1) & (size - 1)) {
        const int other = table[slot];
        if (other < 0) {
          table[slot] = static_cast<int>(v);
          break;
        }
        if (p[other] == p[v]) {
          target[v] = other;
          break;
        }
      }
    }
  } else {
    // Grid of cell size epsilon: a duplicate lies in one of the 27 cells around a vertex.
    auto cell = [&](double x) {
      return static_cast<std::int64_t>(std::clamp(std::floor(x / epsilon), -1e15, 1e15));
    };
    auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
      std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull;
      h ^= static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
      h ^= static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
      return h;
    };
    std::unordered_multimap<std::uint64_t, int> grid;
    grid.reserve(n);
    for (std::size_t v = 0; v < n; ++v) {
      const std::int64_t cx = cell(p[v][0]), cy = cell(p[v][1]), cz = cell(p[v][2]);
      int found = -1;
      for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx) {
        for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy) {
          for (std::int64_t dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto range = grid.equal_range(key(cx + dx, cy + dy, cz + dz));
            for (auto it = range.first; it != range.second; ++it) {
              const Vec3d d = p[it->second] - p[v];
              if (std::fabs(d[0]) <= epsilon && std::fabs(d[1]) <= epsilon &&
                  std::fabs(d[2]) <= epsilon && (found < 0 || it->second < found)) {
                found = it->second;
              }
            }
          }
        }
      }
      if (found >= 0) {
        target[v] = found;
      } else {
        grid.emplace(key(cx, cy, cz), static_cast<int>(v));
      }
    }
  }
  std::size_t merged = 0;
  for (std::size_t v = 0; v < n; ++v) merged += target[v] != static_cast<int>(v);
  if (merged > 0) compact_vertices(soup, target);
  return merged;
}

namespace {

bool repeats_a_corner(const Triangle3& tri) {
  return tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2];
}

// Twice the area at most `ratio` times the longest edge squared (corners all different).
bool flat_corners(const Soup& soup, const Triangle3& tri, double ratio) {
  const Vec3d& a = soup.positions[tri[0]];
  const Vec3d& b = soup.positions[tri[1]];
  const Vec3d& c = soup.positions[tri[2]];
  const double twice_area = cross(b - a, c - a).norm();
  const double longest = std::max({(b - a).sqrnorm(), (c - b).sqrnorm(), (a - c).sqrnorm()});
  return twice_area <= ratio * longest;
}

// Removes the triangles t with erase[t] (with their source faces and UVs), keeping the order.
void erase_triangles(Soup& soup, const std::vector<char>& erase) {
  const bool with_uvs = !soup.corner_uv.empty();
  std::size_t kept = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    if (erase[t]) continue;
    soup.triangles[kept] = soup.triangles[t];
    soup.source_face[kept] = soup.source_face[t];
    if (with_uvs) soup.corner_uv[kept] = soup.corner_uv[t];
    ++kept;
  }
  soup.triangles.resize(kept);
  soup.source_face.resize(kept);
  if (with_uvs) soup.corner_uv.resize(kept);
}

}  // namespace

DegenerateFaces heal_degenerate_triangles(Soup& soup, double ratio) {
  DegenerateFaces healed;
  const bool with_uvs = !soup.corner_uv.empty();
  std::vector<char> dead(soup.triangles.size(), 0);
  // A face whose corners merged into one another (duplicate vertices) has no area nor edges
  // of its own: dropped.
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    if (repeats_a_corner(soup.triangles[t])) dead[t] = 1, ++healed.collapsed;
  // A face whose corners lie on one line (its middle corner m on its longest edge a-b) is
  // dropped and the face across a-b split at m into two, which take its place along a-m and
  // m-b: the surface is the same, and each edge still has its two faces. Passes repeat while
  // they heal one (a face split may lie on the line too), a face changed in a pass waiting for
  // the next.
  for (int pass = 0; pass < 8; ++pass) {
    EdgeTriangles faces_on;  // of the faces alive
    std::vector<int> flat;
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
      if (dead[t]) continue;
      const Triangle3& tri = soup.triangles[t];
      for (int k = 0; k < 3; ++k)
        faces_on[undirected_edge_key(tri[k], tri[(k + 1) % 3])].push_back(static_cast<int>(t));
      if (flat_corners(soup, tri, ratio)) flat.push_back(static_cast<int>(t));
    }
    std::vector<char> changed(soup.triangles.size(), 0);
    bool progress = false;
    for (const int f : flat) {
      if (changed[f]) continue;
      const Triangle3 tri = soup.triangles[f];
      int longest = 0;
      double most = -1.0;
      for (int k = 0; k < 3; ++k) {
        const double length = (soup.positions[tri[(k + 1) % 3]] - soup.positions[tri[k]]).sqrnorm();
        if (length > most) most = length, longest = k;
      }
      const int a = tri[longest], b = tri[(longest + 1) % 3], m = tri[(longest + 2) % 3];
      std::vector<int> across;
      for (const int g : faces_on.at(undirected_edge_key(a, b)))
        if (g != f && !dead[g]) across.push_back(g);
      if (across.size() > 1) continue;  // a non-manifold edge: left to the topology check
      if (across.size() == 1) {
        const int g = across[0];
        if (changed[g]) continue;
        Triangle3& other = soup.triangles[g];
        // other = (p, q, x) in its own order, {p, q} = {a, b}.
        int k = 0;
        while (!((other[k] == a || other[k] == b) &&
                 (other[(k + 1) % 3] == a || other[(k + 1) % 3] == b)))
          ++k;
        const int p = other[k], q = other[(k + 1) % 3], x = other[(k + 2) % 3];
        if (x == m) continue;  // the flat face repeated the other way: left to the checks
        const Vec3d along = soup.positions[q] - soup.positions[p];
        const double share = OpenMesh::dot(soup.positions[m] - soup.positions[p], along) /
                             std::max(along.sqrnorm(), std::numeric_limits<double>::min());
        other = {p, m, x};
        soup.triangles.push_back({m, q, x});
        soup.source_face.push_back(soup.source_face[g]);
        if (with_uvs) {
          const std::array<Vec2d, 3> uv = soup.corner_uv[g];
          const Vec2d& uv_p = uv[k];
          const Vec2d& uv_q = uv[(k + 1) % 3];
          const Vec2d& uv_x = uv[(k + 2) % 3];
          const Vec2d uv_m = uv_p + (uv_q - uv_p) * std::clamp(share, 0.0, 1.0);
          soup.corner_uv[g] = {uv_p, uv_m, uv_x};
          soup.corner_uv.push_back({uv_m, uv_q, uv_x});
        }
        dead.push_back(0);
        changed.push_back(1);
        changed[g] = 1;
      }
      dead[f] = 1;
      changed[f] = 1;
      ++healed.flat;
      progress = true;
    }
    if (!progress) break;
  }
  if (healed.collapsed + healed.flat > 0) erase_triangles(soup, dead);
  return healed;
}

void check_degenerate_triangles(const Soup& soup, const LoadOptions& options,
                                const std::string& file) {
  std::uint64_t degenerate = 0;
  std::size_t first = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const Triangle3& tri = soup.triangles[t];
    const bool bad =
        repeats_a_corner(tri) || flat_corners(soup, tri, options.degenerate_area_ratio);
    if (bad && degenerate++ == 0) first = t;
  }
  if (degenerate > 0) {
    throw_invalid(
        file,
        "mesh has " +
            counted(degenerate, "degenerate (zero-area) face", "degenerate (zero-area) faces") +
            ", first face " + std::to_string(soup.source_face[first]) + " (vertices " +
            vertex_list(soup.source_vertex, soup.triangles[first]) + ")");
  }
}

DuplicateFaces remove_duplicate_triangles(Soup& soup) {
  // Triangles by their sorted corners, then by index: equal keys are adjacent.
  std::vector<std::pair<Triangle3, int>> keys(soup.triangles.size());
  for (std::size_t t = 0; t < keys.size(); ++t) {
    keys[t] = {soup.triangles[t], static_cast<int>(t)};
    std::sort(keys[t].first.begin(), keys[t].first.end());
  }
  std::sort(keys.begin(), keys.end());
  // Whether triangle t runs through its sorted corners a < b < c in that cyclic order.
  const auto ascending = [&](int t) {
    const Triangle3& tri = soup.triangles[t];
    const int low = tri[0] < tri[1] ? (tri[0] < tri[2] ? 0 : 2) : (tri[1] < tri[2] ? 1 : 2);
    return tri[(low + 1) % 3] < tri[(low + 2) % 3];
  };
  // The groups of faces over one set of corners [begin, end) in `keys`, and whether each
  // face is in a group with as many facing each way (a fold, or one side of a two-sided
  // surface).
  std::vector<std::pair<std::size_t, std::size_t>> groups;
  std::vector<char> balanced(soup.triangles.size(), 0);
  for (std::size_t begin = 0, end = 0; begin < keys.size(); begin = end) {
    end = begin + 1;
    while (end < keys.size() && keys[end].first == keys[begin].first) ++end;
    if (end - begin == 1) continue;
    groups.push_back({begin, end});
    std::size_t up = 0;
    for (std::size_t i = begin; i < end; ++i) up += ascending(keys[i].second);
    if (2 * up == end - begin)
      for (std::size_t i = begin; i < end; ++i) balanced[keys[i].second] = 1;
  }
  DuplicateFaces removed;
  if (groups.empty()) return removed;
  // A connected part made of nothing but such balanced groups is a two-sided surface (each
  // face written once for each side, as game models are): one face of each group is kept.
  UnionFind parts(soup.positions.size());
  for (const Triangle3& t : soup.triangles) parts.unite(t[0], t[1]), parts.unite(t[0], t[2]);
  std::vector<char> one_sided_part(soup.positions.size(), 0);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    if (!balanced[t]) one_sided_part[parts.find(soup.triangles[t][0])] = 1;
  std::vector<char> drop(soup.triangles.size(), 0);
  for (const auto& [begin, end] : groups) {
    // The faces over one set of corners: as many facing each way cancel (folds, all dropped,
    // but for one on a two-sided part); otherwise the first facing the way most do is kept.
    std::vector<int> up, down;
    for (std::size_t i = begin; i < end; ++i)
      (ascending(keys[i].second) ? up : down).push_back(keys[i].second);
    if (up.size() == down.size()) {
      const bool two_sided = !one_sided_part[parts.find(soup.triangles[up[0]][0])];
      for (std::size_t i = begin; i < end; ++i)
        drop[keys[i].second] = !two_sided || keys[i].second != std::min(up[0], down[0]);
      if (two_sided)
        removed.other_sides += end - begin - 1;
      else
        removed.folds += up.size();
      continue;
    }
    const std::size_t folds = std::min(up.size(), down.size());
    removed.folds += folds;
    const std::vector<int>& most = up.size() > down.size() ? up : down;
    removed.copies += most.size() - 1 - folds;
    for (std::size_t i = begin; i < end; ++i) drop[keys[i].second] = keys[i].second != most[0];
  }
  if (removed.copies + removed.folds + removed.other_sides > 0) erase_triangles(soup, drop);
  return removed;
}

void check_duplicate_triangles(const Soup& soup, const std::string& file) {
  struct Key {
    Triangle3 sorted;
    int triangle;
  };
  // Sorted by (sorted vertices, triangle): bucketed by the lowest vertex in triangle order (a
  // counting sort), then each bucket, a vertex's few triangles, stably sorted by the rest.
  std::vector<Key> keys(soup.triangles.size());
  {
    std::vector<std::uint32_t> start(soup.positions.size() + 1, 0);
    std::vector<Triangle3> sorted(soup.triangles.size());
    for (std::size_t t = 0; t < sorted.size(); ++t) {
      sorted[t] = soup.triangles[t];
      std::sort(sorted[t].begin(), sorted[t].end());
      ++start[sorted[t][0] + 1];
    }
    for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < sorted.size(); ++t)
      keys[fill[sorted[t][0]]++] = {sorted[t], static_cast<int>(t)};
    for (std::size_t v = 0; v + 1 < start.size(); ++v)
      std::stable_sort(keys.begin() + start[v], keys.begin() + start[v + 1],
                       [](const Key& a, const Key& b) {
                         return a.sorted[1] != b.sorted[1] ? a.sorted[1] < b.sorted[1]
                                                           : a.sorted[2] < b.sorted[2];
                       });
  }
  std::uint64_t duplicates = 0;
  std::size_t first = 0;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (keys[i].sorted == keys[i - 1].sorted && duplicates++ == 0) first = i;
  }
  if (duplicates > 0) {
    const Key& original = keys[first - 1];
    const Key& copy = keys[first];
    throw_invalid(file, "mesh has " + counted(duplicates, "duplicate face", "duplicate faces") +
                            " (the same vertices as another face), first face " +
                            std::to_string(soup.source_face[copy.triangle]) + " repeats face " +
                            std::to_string(soup.source_face[original.triangle]) + " (vertices " +
                            vertex_list(soup.source_vertex, soup.triangles[copy.triangle]) + ")");
  }
}

}  // namespace papercraft::load_internal
