// Non-manifold edges cut apart: the faces on each paired into sheets, the edges that let the
// sheets part, the copies of their ends moved apart; volume meshes refused; faces made to agree
// across manifold edges first.
#include "nodes/load/non_manifold_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>

#include "nodes/load/messages.h"

namespace papercraft::load_internal {

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

namespace {

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

}  // namespace

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
}  // namespace papercraft::load_internal
