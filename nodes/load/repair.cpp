// Checks of the raw faces and the triangle soup, and the safe repairs: unreferenced and duplicate
// vertices, degenerate and duplicate faces, non-manifold vertices split per fan, consistent and
// outward orientation.

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

namespace {

struct EdgeUse {
  std::uint64_t key;   // (lower vertex << 32) | higher vertex
  std::uint32_t slot;  // 3 * triangle + k: the edge from corner k to corner k + 1
};

std::vector<std::uint32_t> slots_of(const std::vector<EdgeUse>& uses, std::size_t begin,
                                    std::size_t end) {
  std::vector<std::uint32_t> slots;
  for (std::size_t i = begin; i < end; ++i) slots.push_back(uses[i].slot);
  return slots;
}

// The faces on a non-manifold edge (its uses `slots`, edge `key` a < b) paired into sheets that
// each pass the edge as a manifold surface would, each pair two faces next to each other in the
// order of their third corner's angle about the edge, running opposite ways. Where the faces
// alternate in direction around the edge, a face running b -> a (its back, the inside of a
// consistently oriented surface, toward increasing angle) goes with the next: two solids
// touching along an edge stay two solids, each closed. Otherwise (an odd number: a fin on a
// surface, or directions that do not alternate) as many pairs as can be made, of those the
// flattest (the angle between the two faces of a pair nearest a half turn), of faces running
// opposite ways where there are such (else of any: the orientation is repaired later); a face
// left over gets the edge as a boundary. Empty when a face has no extent away from the edge or
// there are more than kMostFaces.
std::vector<std::pair<std::uint32_t, std::uint32_t>> sheets_around_edge(
    const Soup& soup, std::uint64_t key, const std::vector<std::uint32_t>& slots) {
  constexpr std::size_t kMostFaces = 12;  // beyond this, not worth guessing: an error
  const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
  if (slots.size() > kMostFaces) return {};
  const Vec3d origin = soup.positions[a];
  const Vec3d axis = soup.positions[b] - origin;
  const double length2 = OpenMesh::dot(axis, axis);
  if (!(length2 > 0.0)) return {};
  struct Around {
    double angle;
    bool forward;  // runs a -> b
    std::uint32_t slot;
  };
  std::vector<Around> around;
  Vec3d e1(0, 0, 0), e2(0, 0, 0);
  for (std::uint32_t slot : slots) {
    const Triangle3& t = soup.triangles[slot / 3];
    const int k = static_cast<int>(slot % 3);
    const Vec3d c = soup.positions[t[(k + 2) % 3]] - origin;
    const Vec3d w = c - axis * (OpenMesh::dot(c, axis) / length2);
    if (!(OpenMesh::norm(w) > 0.0)) return {};
    if (around.empty()) {
      e1 = w / OpenMesh::norm(w);
      e2 = cross(axis, e1);
      e2 /= OpenMesh::norm(e2);
    }
    around.push_back({std::atan2(OpenMesh::dot(w, e2), OpenMesh::dot(w, e1)), t[k] == a, slot});
  }
  std::sort(around.begin(), around.end(),
            [](const Around& x, const Around& y) { return x.angle < y.angle; });
  const std::size_t n = around.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sheets;
  // Alternating: each back with the face after it.
  std::size_t start = 0;
  while (start < n && around[start].forward) ++start;
  bool alternating = n % 2 == 0 && start < n;
  for (std::size_t k = 0; alternating && k < n; k += 2) {
    const Around& back = around[(start + k) % n];
    const Around& front = around[(start + k + 1) % n];
    alternating = !back.forward && front.forward;
    sheets.push_back({back.slot, front.slot});
  }
  if (alternating) return sheets;
  // Otherwise every matching of neighbours (i, i + 1 mod n) running opposite ways: the most
  // pairs, then the flattest. Pair i is (i, i + 1); a matching takes no two pairs that share a
  // face.
  const auto gap = [&](std::size_t i) {
    const double next = around[(i + 1) % n].angle + (i + 1 == n ? 2.0 * M_PI : 0.0);
    return std::abs(next - around[i].angle - M_PI);
  };
  std::vector<std::size_t> chosen, best;
  double best_bend = std::numeric_limits<double>::infinity();
  bool any_direction = false;
  const std::function<void(std::size_t, std::uint32_t, double)> search =
      [&](std::size_t i, std::uint32_t used, double bend) {
        if (i == n) {
          if (chosen.size() > best.size() || (chosen.size() == best.size() && bend < best_bend))
            best = chosen, best_bend = bend;
          return;
        }
        search(i + 1, used, bend);
        const std::size_t j = (i + 1) % n;
        if ((used >> i & 1u) || (used >> j & 1u) ||
            (!any_direction && around[i].forward == around[j].forward))
          return;
        chosen.push_back(i);
        search(i + 1, used | 1u << i | 1u << j, bend + gap(i));
        chosen.pop_back();
      };
  search(0, 0, 0.0);
  // Faces that all run one way (their orientation is not yet repaired): paired as they lie.
  if (best.empty()) {
    any_direction = true;
    search(0, 0, 0.0);
  }
  sheets.clear();
  for (std::size_t i : best) sheets.push_back({around[i].slot, around[(i + 1) % n].slot});
  return sheets;
}

// The angle between the two faces joined across edge use `slot` (0: folded flat onto each
// other, pi: flat), whichever way either faces.
double opening_angle(const Soup& soup, const std::vector<int>& neighbor, std::uint32_t slot) {
  const Triangle3& t = soup.triangles[slot / 3];
  const Triangle3& u = soup.triangles[static_cast<std::size_t>(neighbor[slot])];
  const int from = t[slot % 3], to = t[(slot % 3 + 1) % 3];
  const int p = t[(slot % 3 + 2) % 3];
  const int q = u[0] != from && u[0] != to ? u[0] : (u[1] != from && u[1] != to ? u[1] : u[2]);
  const Vec3d axis = soup.positions[to] - soup.positions[from];
  const double length2 = OpenMesh::dot(axis, axis);
  if (!(length2 > 0.0)) return M_PI;
  const auto across = [&](int c) {
    const Vec3d w = soup.positions[c] - soup.positions[from];
    return w - axis * (OpenMesh::dot(w, axis) / length2);
  };
  const Vec3d x = across(p), y = across(q);
  return std::atan2(OpenMesh::norm(cross(x, y)), OpenMesh::dot(x, y));
}

// Where the sheets of a non-manifold edge (key a < b, its uses `slots`, each pair of a sheet
// joined in `neighbor`, a face left over not) still meet around one of its ends, the manifold
// edges at that end to leave unjoined so that every sheet there lies in a fan of its own. The
// faces around a vertex, joined across its edges, form paths and cycles (each face has two
// edges at the vertex, each edge joins two faces); the sheets are places on them, a joined pair
// across a-b or a face left over (the end of a path). Between each two places next to each
// other on one path or cycle the edge whose faces meet at the sharpest angle is left unjoined:
// the surface gets a slit there, along a crease where one shows least. Of the two ends, the one
// that needs fewer such edges; none when the sheets already part at one end. False when between
// two places at both ends there is no manifold edge (`non_manifold` lists the other
// non-manifold edges).
bool parting_edges(const Soup& soup, const std::vector<int>& neighbor, UnionFind& fans,
                   std::uint64_t key, const std::vector<std::uint32_t>& slots,
                   const std::unordered_set<std::uint64_t>& non_manifold,
                   std::vector<std::uint64_t>& parting) {
  const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
  const auto edge_key = [&](std::uint32_t slot) {
    const Triangle3& t = soup.triangles[slot / 3];
    const auto x = static_cast<std::uint64_t>(t[slot % 3]);
    const auto y = static_cast<std::uint64_t>(t[(slot % 3 + 1) % 3]);
    return std::min(x, y) << 32 | std::max(x, y);
  };
  // The places (one slot each: a pair by its lower slot) and, per end, each one's fan.
  std::vector<std::uint32_t> places;
  for (std::uint32_t slot : slots) {
    const int other = neighbor[slot];
    if (other < 0) {
      places.push_back(slot);
    } else {
      // the partner's slot on this edge
      const auto partner = std::find_if(slots.begin(), slots.end(), [&](std::uint32_t s) {
        return s / 3 == static_cast<std::uint32_t>(other);
      });
      if (partner != slots.end() && slot < *partner) places.push_back(slot);
    }
  }
  const auto fan_at = [&](std::uint32_t slot, int v) {
    const std::uint32_t t = slot / 3;
    return fans.find(3 * t + static_cast<std::uint32_t>(corner_of(soup.triangles[t], v)));
  };
  bool parted = true;  // every two places are in different fans at a or at b
  for (std::size_t i = 0; i < places.size() && parted; ++i)
    for (std::size_t j = i + 1; j < places.size() && parted; ++j)
      parted = fan_at(places[i], a) != fan_at(places[j], a) ||
               fan_at(places[i], b) != fan_at(places[j], b);
  if (parted) return true;

  // The edges to leave unjoined at end v, or nothing when some two places have none between.
  const auto cuts_at = [&](int v) -> std::optional<std::vector<std::uint64_t>> {
    // The two edge uses of face t at v: from v, and into v.
    const auto at_v = [&](std::uint32_t t) {
      const int k = corner_of(soup.triangles[t], v);
      return std::array<std::uint32_t, 2>{3 * t + static_cast<std::uint32_t>(k),
                                          3 * t + static_cast<std::uint32_t>((k + 2) % 3)};
    };
    const auto far_end = [&](std::uint32_t slot) {  // the edge's corner other than v
      const Triangle3& t = soup.triangles[slot / 3];
      return t[slot % 3] == v ? t[(slot % 3 + 1) % 3] : t[slot % 3];
    };
    // From face t, leaving by `out`: the next face and the slot it leaves by, or nothing.
    const auto step = [&](std::uint32_t out) -> std::optional<std::uint32_t> {
      const int u = neighbor[out];
      if (u < 0) return std::nullopt;
      const auto ends = at_v(static_cast<std::uint32_t>(u));
      return far_end(ends[0]) == far_end(out) ? ends[1] : ends[0];
    };
    std::vector<std::uint64_t> cuts;
    std::set<std::size_t> done;  // fans walked
    const std::size_t limit = 3 * soup.triangles.size();
    for (std::uint32_t place : places) {
      const std::size_t fan = fan_at(place, v);
      if (!done.insert(fan).second) continue;
      // Walk back from the place's face to an end of the path, or around the cycle.
      const std::uint32_t t0 = place / 3;
      std::uint32_t out = at_v(t0)[1];
      bool cycle = false;
      for (std::size_t n = 0;; ++n) {
        if (n > limit) return std::nullopt;
        const auto next = step(out);
        if (!next) break;
        if (*next / 3 == t0) {
          cycle = true;
          break;
        }
        out = *next;
      }
      // The walk forward: the leaving slot of each face, starting from the path's end (whose
      // other slot is open) or from t0.
      std::uint32_t leave =
          cycle ? at_v(t0)[0] : (at_v(out / 3)[0] == out ? at_v(out / 3)[1] : at_v(out / 3)[0]);
      std::vector<std::uint32_t> links;  // joined edges in order
      std::vector<int> mark;             // per link: 1 a place, 0 a candidate, -1 neither
      std::vector<std::size_t> at;       // positions of places: 2 i for face i, 2 i + 1 for link i
      for (std::size_t n = 0;; ++n) {
        if (n > limit) return std::nullopt;
        const std::uint32_t t = leave / 3;
        const auto ends = at_v(t);
        const std::uint32_t enter = ends[0] == leave ? ends[1] : ends[0];
        if (neighbor[enter] < 0 && edge_key(enter) == key)
          at.push_back(2 * links.size());  // a face left over: the path's first face
        if (neighbor[leave] < 0) {
          if (edge_key(leave) == key) at.push_back(2 * links.size());  // left over, last face
          break;
        }
        const std::uint64_t k = edge_key(leave);
        mark.push_back(k == key ? 1 : (non_manifold.count(k) ? -1 : 0));
        if (k == key) at.push_back(2 * links.size() + 1);
        links.push_back(leave);
        const auto next = step(leave);
        if (cycle && *next / 3 == t0) break;
        leave = *next;
      }
      if (at.size() < 2) continue;
      // One cut between each two places next to each other (around a cycle also the last and
      // the first).
      const std::size_t gaps = cycle ? at.size() : at.size() - 1;
      for (std::size_t g = 0; g < gaps; ++g) {
        const std::size_t from = at[g],
                          to = g + 1 < at.size() ? at[g + 1] : at[0] + 2 * links.size();
        std::optional<std::size_t> best;
        double sharpest = std::numeric_limits<double>::infinity();
        for (std::size_t pos = from + 1; pos < to; ++pos) {
          if (pos % 2 == 0) continue;
          const std::size_t link = (pos / 2) % links.size();
          if (mark[link] != 0) continue;
          const double angle = opening_angle(soup, neighbor, links[link]);
          if (angle < sharpest) sharpest = angle, best = link;
        }
        if (!best) return std::nullopt;
        cuts.push_back(edge_key(links[*best]));
      }
    }
    return cuts;
  };
  std::optional<std::vector<std::uint64_t>> at_a = cuts_at(a), at_b = cuts_at(b);
  if (!at_a && !at_b) return false;
  const auto& cuts = !at_b || (at_a && at_a->size() <= at_b->size()) ? *at_a : *at_b;
  parting.insert(parting.end(), cuts.begin(), cuts.end());
  return true;
}

}  // namespace

// Moves each copy of a vertex (at `first_copy` and after, copy c made from vertex copied_from[c])
// whose original `on_cut_edge` marks into
// its own fan, toward the mean of its faces' centroids, by 1e-7 of the mesh's bounding-box
// diagonal or a thousandth of its shortest edge, whichever is less: sheets cut apart at a
// non-manifold edge then share no point, so no later step can take one sheet's edge for the
// other's. Returns the largest move.
double move_copies_apart(Soup& soup, const std::vector<char>& on_cut_edge, std::size_t first_copy,
                         const std::vector<int>& copied_from) {
  Vec3d low = soup.positions.front(), high = low;
  for (const Vec3d& p : soup.positions) low.minimize(p), high.maximize(p);
  const double step = 1e-7 * OpenMesh::norm(high - low);
  const std::size_t copies = soup.positions.size() - first_copy;
  std::vector<Vec3d> toward(copies, Vec3d(0, 0, 0));
  std::vector<double> shortest(copies, std::numeric_limits<double>::infinity());
  for (const Triangle3& t : soup.triangles) {
    const Vec3d centroid =
        (soup.positions[t[0]] + soup.positions[t[1]] + soup.positions[t[2]]) / 3.0;
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(t[k]);
      if (v < first_copy) continue;
      toward[v - first_copy] += centroid - soup.positions[v];
      for (int other : {t[(k + 1) % 3], t[(k + 2) % 3]})
        shortest[v - first_copy] = std::min(
            shortest[v - first_copy], OpenMesh::norm(soup.positions[other] - soup.positions[v]));
    }
  }
  double moved = 0.0;
  for (std::size_t c = 0; c < copies; ++c) {
    const std::size_t v = first_copy + c;
    if (!on_cut_edge[copied_from[c]]) continue;
    const double length = OpenMesh::norm(toward[c]);
    if (!(length > 0.0)) continue;
    const double by = std::min(step, 1e-3 * shortest[c]);
    soup.positions[v] += toward[c] * (by / length);
    moved = std::max(moved, by);
  }
  return moved;
}

// A volume mesh (the cells of a grid or a tetrahedralisation, each inner face written once) is
// no surface to print: nearly every edge inside it is shared by three or more faces, where a
// surface has them only where sheets touch by accident. Cut apart, its cells would print as
// thousands of closed boxes, after a refinement of many minutes (libigl's cube_40k: 8,000
// cubes, over 400 s). Refused when more than kVolumeShare of its edges (and at least
// kVolumeEdges) are shared by three or more faces. `uses` sorted by key.
void check_not_a_volume_mesh(const std::vector<EdgeUse>& uses, const std::string& file) {
  constexpr double kVolumeShare = 0.25;
  constexpr std::uint64_t kVolumeEdges = 64;
  std::uint64_t edges = 0, shared = 0;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    ++edges;
    shared += j - i >= 3;
    i = j;
  }
  if (shared < kVolumeEdges || static_cast<double>(shared) <= kVolumeShare * edges) return;
  throw_invalid(file, std::to_string(shared) + " of its " + std::to_string(edges) +
                          " edges are shared by three or more faces: this looks like a volume "
                          "mesh (cells with their inner faces), not a surface; export the "
                          "outer surface of the model instead");
}

// Where the mesh has a non-manifold edge: the faces of each part joined across edges of exactly
// two faces flipped to agree with their neighbours (the part's majority way kept), before its
// non-manifold edges are paired into sheets. A part that cannot agree (a Moebius strip) is left
// as it is, for the check after the pairing to name. `uses` sorted by key, as
// check_topology_and_orient sorts them. Returns the number of faces flipped.
std::uint64_t orient_across_manifold_edges(Soup& soup, const std::vector<EdgeUse>& uses) {
  const std::size_t triangles = soup.triangles.size();
  bool any_non_manifold = false;
  for (std::size_t i = 0; i + 2 < uses.size() && !any_non_manifold; ++i)
    any_non_manifold = uses[i].key == uses[i + 2].key;
  if (!any_non_manifold) return 0;
  std::vector<int> across(3 * triangles, -1);  // slot -> the other slot of its two-face edge
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 2) {
      across[uses[i].slot] = static_cast<int>(uses[i + 1].slot);
      across[uses[i + 1].slot] = static_cast<int>(uses[i].slot);
    }
    i = j;
  }
  std::vector<char> seen(triangles, 0), flip(triangles, 0);
  std::vector<std::uint32_t> members, stack;
  std::uint64_t flipped = 0;
  for (std::size_t seed = 0; seed < triangles; ++seed) {
    if (seen[seed]) continue;
    seen[seed] = 1;
    members.clear();
    stack.assign(1, static_cast<std::uint32_t>(seed));
    bool agrees = true;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      members.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int other = across[3 * t + k];
        if (other < 0) continue;
        const auto u = static_cast<std::uint32_t>(other / 3);
        // Two faces agree where they run their shared edge opposite ways.
        const bool same_way = soup.triangles[u][other % 3] == soup.triangles[t][k];
        const char wanted = static_cast<char>(flip[t] ^ (same_way ? 1 : 0));
        if (!seen[u]) {
          seen[u] = 1;
          flip[u] = wanted;
          stack.push_back(u);
        } else if (flip[u] != wanted) {
          agrees = false;
        }
      }
    }
    std::size_t flips = 0;
    for (std::uint32_t t : members) flips += flip[t];
    const bool minority = 2 * flips <= members.size();
    if (!agrees) continue;
    for (std::uint32_t t : members) {
      if (static_cast<bool>(flip[t]) != minority) continue;
      std::swap(soup.triangles[t][1], soup.triangles[t][2]);
      if (!soup.corner_uv.empty()) std::swap(soup.corner_uv[t][1], soup.corner_uv[t][2]);
      ++flipped;
    }
  }
  return flipped;
}

// Checks manifoldness; with `repair`, makes the orientation consistent and closed components face
// outwards. neighbor[3 t + k] is the triangle across edge k (t[k] -> t[k+1]) or -1.
void check_topology_and_orient(Soup& soup, bool repair, const std::string& file,
                               std::vector<std::string>& repairs) {
  const std::size_t triangles = soup.triangles.size();
  // Every edge use, sorted by (key, slot): bucketed by the lower vertex in slot order (a
  // counting sort), then each bucket, a vertex's few edges, stably sorted by the higher vertex.
  std::vector<EdgeUse> uses(3 * triangles);
  const auto sort_uses = [&] {
    std::vector<std::uint32_t> start(soup.positions.size() + 1, 0);
    auto lower = [&](std::size_t slot) {
      const int a = soup.triangles[slot / 3][slot % 3];
      const int b = soup.triangles[slot / 3][(slot % 3 + 1) % 3];
      return static_cast<std::uint32_t>(std::min(a, b));
    };
    for (std::size_t slot = 0; slot < uses.size(); ++slot) ++start[lower(slot) + 1];
    for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t slot = 0; slot < uses.size(); ++slot) {
      const auto a = static_cast<std::uint32_t>(soup.triangles[slot / 3][slot % 3]);
      const auto b = static_cast<std::uint32_t>(soup.triangles[slot / 3][(slot % 3 + 1) % 3]);
      uses[fill[std::min(a, b)]++] = {(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b),
                                      static_cast<std::uint32_t>(slot)};
    }
    for (std::size_t v = 0; v + 1 < start.size(); ++v)
      std::stable_sort(uses.begin() + start[v], uses.begin() + start[v + 1],
                       [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
  };
  sort_uses();
  if (repair) check_not_a_volume_mesh(uses, file);
  // The faces around a non-manifold edge are paired into sheets by the way they run, which means
  // something only where they agree with their neighbours: a two-sided surface keeps one face of
  // each pair whichever way it faces, and paired as they lay its sheets made a Moebius strip
  // (trimesh's chair_model). So first the faces are made to agree across the edges of two faces.
  std::uint64_t pre_oriented = 0;
  if (repair) {
    pre_oriented = orient_across_manifold_edges(soup, uses);
    if (pre_oriented > 0) sort_uses();
  }

  auto edge_vertices = [&](std::uint64_t key) {
    return std::to_string(soup.source_vertex[key >> 32]) + "-" +
           std::to_string(soup.source_vertex[key & 0xffffffffu]);
  };
  auto face_of_slot = [&](std::uint32_t slot) {
    return std::to_string(soup.source_face[slot / 3]);
  };
  std::vector<int> neighbor;
  UnionFind fans(0);
  std::uint64_t non_manifold = 0, inconsistent = 0, cut_apart = 0;
  std::size_t first_non_manifold = 0, first_inconsistent = 0;
  // The two faces of edge uses s1 and s2 (at uses[i]) as neighbours across it.
  const auto join = [&](std::uint32_t s1, std::uint32_t s2, std::size_t i) {
    const std::uint32_t t1 = s1 / 3, t2 = s2 / 3;
    neighbor[s1] = static_cast<int>(t2);
    neighbor[s2] = static_cast<int>(t1);
    const Triangle3& a = soup.triangles[t1];
    const Triangle3& b = soup.triangles[t2];
    const int from = a[s1 % 3];
    const int to = a[(s1 % 3 + 1) % 3];
    if (b[s2 % 3] == from && inconsistent++ == 0) first_inconsistent = i;
    // The two faces are neighbours in the fans of both edge ends.
    fans.unite(s1 - s1 % 3 + corner_of(a, from), s2 - s2 % 3 + corner_of(b, from));
    fans.unite(s1 - s1 % 3 + corner_of(a, to), s2 - s2 % 3 + corner_of(b, to));
  };
  std::vector<char> on_cut_edge;
  std::vector<std::size_t> cut_edges;  // where each edge cut apart starts in `uses`
  // Manifold edges left unjoined so that the sheets of a cut edge part at one of its ends.
  std::vector<std::uint64_t> parting;
  for (int pass = 0; pass < 2; ++pass) {
    neighbor.assign(3 * triangles, -1);
    fans = UnionFind(3 * triangles);
    non_manifold = inconsistent = cut_apart = 0;
    on_cut_edge.assign(repair ? soup.positions.size() : 0, 0);
    cut_edges.clear();
    for (std::uint64_t key : parting) on_cut_edge[key >> 32] = on_cut_edge[key & 0xffffffffu] = 1;
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i + 1;
      while (j < uses.size() && uses[j].key == uses[i].key) ++j;
      if (j - i >= 3) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> sheets;
        if (repair) sheets = sheets_around_edge(soup, uses[i].key, slots_of(uses, i, j));
        if (sheets.empty()) {
          if (non_manifold++ == 0) first_non_manifold = i;
        } else {
          for (const auto& [s1, s2] : sheets) join(s1, s2, i);
          on_cut_edge[uses[i].key >> 32] = on_cut_edge[uses[i].key & 0xffffffffu] = 1;
          cut_edges.push_back(i);
          ++cut_apart;
        }
      } else if (j - i == 2 && !std::binary_search(parting.begin(), parting.end(), uses[i].key)) {
        join(uses[i].slot, uses[i + 1].slot, i);
      }
      i = j;
    }
    if (pass == 1 || non_manifold > 0 || cut_edges.empty()) break;
    std::unordered_set<std::uint64_t> cut_keys;
    for (std::size_t i : cut_edges) cut_keys.insert(uses[i].key);
    for (std::size_t i : cut_edges) {
      std::size_t j = i + 1;
      while (j < uses.size() && uses[j].key == uses[i].key) ++j;
      parting_edges(soup, neighbor, fans, uses[i].key, slots_of(uses, i, j), cut_keys, parting);
    }
    std::sort(parting.begin(), parting.end());
    parting.erase(std::unique(parting.begin(), parting.end()), parting.end());
    if (parting.empty()) break;
  }
  if (non_manifold > 0) {
    std::string faces;
    for (std::size_t k = first_non_manifold;
         k < uses.size() && uses[k].key == uses[first_non_manifold].key; ++k) {
      faces += (faces.empty() ? "" : ", ") + face_of_slot(uses[k].slot);
    }
    throw_invalid(file, "mesh has " +
                            counted(non_manifold, "non-manifold edge", "non-manifold edges") +
                            " (shared by 3 or more faces), first at vertices " +
                            edge_vertices(uses[first_non_manifold].key) + " (faces " + faces + ")");
  }

  const std::size_t vertices = soup.positions.size();
  std::vector<std::int64_t> fan_of_vertex(vertices, -1);
  std::vector<char> bad_vertex(vertices, 0);
  for (std::size_t slot = 0; slot < 3 * triangles; ++slot) {
    const int v = soup.triangles[slot / 3][slot % 3];
    const auto root = static_cast<std::uint32_t>(fans.find(slot));
    if (fan_of_vertex[v] < 0) {
      fan_of_vertex[v] = root;
    } else if (fan_of_vertex[v] != root) {
      bad_vertex[v] = 1;
    }
  }
  const auto non_manifold_vertices =
      static_cast<std::uint64_t>(std::count(bad_vertex.begin(), bad_vertex.end(), 1));
  if (non_manifold_vertices > 0 && repair) {
    // Every fan of a vertex after its first gets a copy of the vertex (same position, same
    // input vertex): the surface is unchanged and becomes manifold, pieces merely touch there.
    // A fan root is a slot, so it names one fan of one vertex.
    std::unordered_map<std::uint32_t, int> copy_of_fan;
    std::vector<int> copied_from;
    for (std::size_t slot = 0; slot < 3 * triangles; ++slot) {
      int& corner = soup.triangles[slot / 3][slot % 3];
      const int v = corner;
      if (!bad_vertex[v]) continue;
      const auto root = static_cast<std::uint32_t>(fans.find(slot));
      if (fan_of_vertex[v] == root) continue;
      const auto [it, added] =
          copy_of_fan.try_emplace(root, static_cast<int>(soup.positions.size()));
      if (added) {
        soup.positions.push_back(soup.positions[v]);
        soup.source_vertex.push_back(soup.source_vertex[v]);
        copied_from.push_back(v);
      }
      corner = it->second;
    }
    if (cut_apart > 0) {
      const double moved = move_copies_apart(soup, on_cut_edge, vertices, copied_from);
      std::ostringstream what;
      what << "cut " << counted(cut_apart, "non-manifold edge", "non-manifold edges")
           << " apart (the faces on each paired into sheets that each pass it as a surface does; "
              "the copies of its ends moved into their own sheet by at most "
           << moved << ", so the sheets do not share a point)";
      repairs.push_back(what.str());
    }
    if (!parting.empty()) {
      repairs.push_back(
          "opened " + counted(parting.size(), "edge", "edges") +
          " next to non-manifold edges whose sheets met again around both ends (at one end, "
          "between each two sheets, the edge of the sharpest crease), so those sheets part there");
    }
    repairs.push_back(
        "split " + counted(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") +
        " into one vertex per fan (" + counted(copy_of_fan.size(), "copy", "copies") + " added)");
  }
  // A cut edge whose sheets still meet at both of its ends (their fans there joined by other
  // faces) is still one edge of three or more faces: an error, as without the cut.
  std::uint64_t still_joined = 0;
  std::size_t first_joined = 0;
  for (std::size_t i : cut_edges) {
    std::map<std::pair<int, int>, int> faces_on;
    bool joined = false;
    for (std::size_t k = i; k < uses.size() && uses[k].key == uses[i].key; ++k) {
      const Triangle3& t = soup.triangles[uses[k].slot / 3];
      const int from = t[uses[k].slot % 3], to = t[(uses[k].slot % 3 + 1) % 3];
      joined = joined || ++faces_on[{std::min(from, to), std::max(from, to)}] > 2;
    }
    if (joined && still_joined++ == 0) first_joined = i;
  }
  if (still_joined > 0) {
    std::string faces;
    for (std::size_t k = first_joined; k < uses.size() && uses[k].key == uses[first_joined].key;
         ++k)
      faces += (faces.empty() ? "" : ", ") + face_of_slot(uses[k].slot);
    throw_invalid(file, "mesh has " +
                            counted(still_joined, "non-manifold edge", "non-manifold edges") +
                            " (shared by 3 or more faces) whose sheets meet again at both ends, "
                            "so they cannot be cut apart there, first at vertices " +
                            edge_vertices(uses[first_joined].key) + " (faces " + faces + ")");
  }
  if (non_manifold_vertices > 0 && !repair) {
    int first = INT_MAX;
    for (std::size_t v = 0; v < vertices; ++v) {
      if (bad_vertex[v]) first = std::min(first, soup.source_vertex[v]);
    }
    throw_invalid(
        file, "mesh has " +
                  counted(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") +
                  " (their faces form more than one fan), first vertex " + std::to_string(first));
  }

  if (inconsistent > 0 && !repair) {
    throw_invalid(file, "mesh is not consistently oriented: " +
                            counted(inconsistent, "edge is", "edges are") +
                            " traversed in the same direction by both of its faces, first at "
                            "vertices " +
                            edge_vertices(uses[first_inconsistent].key) + " (faces " +
                            face_of_slot(uses[first_inconsistent].slot) + ", " +
                            face_of_slot(uses[first_inconsistent + 1].slot) + ")");
  }
  if (!repair) return;

  // Components through manifold edges; flip[t] makes every neighbour pair agree (paper-free
  // standard breadth-first propagation), keeping each component's majority orientation.
  std::vector<int> component(triangles, -1);
  std::vector<char> flip(triangles, 0);
  std::vector<std::uint32_t> members;
  std::vector<std::uint32_t> stack;
  std::uint64_t reoriented = 0, flipped_components = 0, flipped_faces = 0;
  int components = 0;
  for (std::size_t seed = 0; seed < triangles; ++seed) {
    if (component[seed] >= 0) continue;
    members.clear();
    component[seed] = components;
    stack.push_back(static_cast<std::uint32_t>(seed));
    bool closed = true;
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      members.push_back(t);
      const Triangle3& tri = soup.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const int u = neighbor[3 * t + k];
        if (u < 0) {
          closed = false;
          continue;
        }
        const Triangle3& other = soup.triangles[u];
        const int from = tri[k];
        const int ku = corner_of(other, from);
        const bool same_direction = other[(ku + 1) % 3] == tri[(k + 1) % 3];
        const char wanted = static_cast<char>(flip[t] ^ (same_direction ? 1 : 0));
        if (component[u] < 0) {
          component[u] = components;
          flip[u] = wanted;
          stack.push_back(static_cast<std::uint32_t>(u));
        } else if (flip[u] != wanted) {
          throw_invalid(file,
                        "mesh has a non-orientable component (like a Moebius strip), "
                        "containing face " +
                            std::to_string(soup.source_face[t]));
        }
      }
    }
    std::size_t flips = 0;
    for (std::uint32_t t : members) flips += flip[t];
    if (2 * flips > members.size()) {
      for (std::uint32_t t : members) flip[t] ^= 1;
      flips = members.size() - flips;
    }
    reoriented += flips;
    if (closed) {
      // Signed volume (divergence theorem), relative to a point of the component for precision.
      const Vec3d origin = soup.positions[soup.triangles[members.front()][0]];
      double volume = 0.0;
      for (std::uint32_t t : members) {
        const Triangle3& tri = soup.triangles[t];
        const Vec3d a = soup.positions[tri[0]] - origin;
        Vec3d b = soup.positions[tri[1]] - origin;
        Vec3d c = soup.positions[tri[2]] - origin;
        if (flip[t]) std::swap(b, c);
        volume += OpenMesh::dot(a, cross(b, c));
      }
      if (volume < 0.0) {
        for (std::uint32_t t : members) flip[t] ^= 1;
        ++flipped_components;
        flipped_faces += members.size();
        reoriented -= flips;
      }
    }
    ++components;
  }
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!flip[t]) continue;
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
    if (!soup.corner_uv.empty()) std::swap(soup.corner_uv[t][1], soup.corner_uv[t][2]);
  }
  reoriented += pre_oriented;
  if (reoriented > 0) {
    repairs.push_back("reoriented " + counted(reoriented, "face", "faces") +
                      " to agree with their neighbours");
  }
  if (flipped_components > 0) {
    repairs.push_back(
        "flipped " +
        counted(flipped_components, "closed component that faced", "closed components that faced") +
        " inwards (" + counted(flipped_faces, "face", "faces") + ")");
  }
}

}  // namespace papercraft::load_internal
