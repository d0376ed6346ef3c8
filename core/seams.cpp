#include "core/seams.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

#include "core/errors.h"

namespace papercraft {
namespace {

struct EdgeRef {
  int strip;
  int edge;
};

struct Partner {
  int edge;  // global edge index
  double overlap;
};

class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int x, int y) {
    x = find(x), y = find(y);
    if (x != y) parent_[std::max(x, y)] = std::min(x, y);
  }

 private:
  std::vector<int> parent_;
};

std::array<double, 6> exact_key(const Vec3& p, const Vec3& q) {
  std::array<double, 3> a{p.x(), p.y(), p.z()}, b{q.x(), q.y(), q.z()};
  if (b < a) std::swap(a, b);
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}

// Intervals [lo, hi] along the longer edge (a, b) where the shorter edge (r, s) lies on it
// within `tolerance` * |ab|; the overlap length, 0 when not collinear.
double collinear_overlap(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1,
                         double tolerance) {
  bool p_longer = (p1 - p0).squaredNorm() >= (q1 - q0).squaredNorm();
  const Vec3& a = p_longer ? p0 : q0;
  const Vec3& b = p_longer ? p1 : q1;
  const Vec3& r = p_longer ? q0 : p0;
  const Vec3& s = p_longer ? q1 : p1;
  double length = (b - a).norm();
  if (length == 0.0) return 0.0;
  Vec3 u = (b - a) / length;
  double tr = (r - a).dot(u), ts = (s - a).dot(u);
  if ((r - a - tr * u).norm() > tolerance * length || (s - a - ts * u).norm() > tolerance * length)
    return 0.0;
  double overlap = std::min(length, std::max(tr, ts)) - std::max(0.0, std::min(tr, ts));
  return overlap > tolerance * length ? overlap : 0.0;
}

std::int64_t cell_index(double coordinate, double cell) {
  return static_cast<std::int64_t>(std::floor(std::clamp(coordinate / cell, -1e6, 1e6)));
}

}  // namespace

void label_seams(std::vector<FlatStrip>& strips, const SeamOptions& options) {
  std::vector<EdgeRef> refs;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    const FlatStrip& strip = strips[s];
    const int vertex_count = static_cast<int>(strip.vertices3d.size());
    for (int e = 0; e < static_cast<int>(strip.boundary.size()); ++e) {
      const BoundaryEdge& edge = strip.boundary[e];
      if (edge.v0 < 0 || edge.v0 >= vertex_count || edge.v1 < 0 || edge.v1 >= vertex_count)
        throw InvalidInputException("label_seams: strip " + std::to_string(strip.id) +
                                    " boundary edge " + std::to_string(e) +
                                    " has a vertex out of range [0, " +
                                    std::to_string(vertex_count) + ")");
      refs.push_back({s, e});
    }
  }
  const int edge_count = static_cast<int>(refs.size());
  auto boundary = [&](int g) -> BoundaryEdge& {
    return strips[refs[g].strip].boundary[refs[g].edge];
  };
  auto start = [&](int g) -> const Vec3& {
    return strips[refs[g].strip].vertices3d[boundary(g).v0];
  };
  auto end = [&](int g) -> const Vec3& { return strips[refs[g].strip].vertices3d[boundary(g).v1]; };

  std::vector<std::vector<Partner>> partners(edge_count);
  std::vector<bool> seam(edge_count, false);
  DisjointSets sets(edge_count);

  // Exact matches by endpoints.
  std::map<std::array<double, 6>, std::vector<int>> groups;
  for (int g = 0; g < edge_count; ++g) groups[exact_key(start(g), end(g))].push_back(g);
  for (const auto& [key, group] : groups) {
    if (group.size() < 2) continue;
    const int n = static_cast<int>(group.size());
    std::vector<int> pair(n, -1);
    for (bool opposite : {true, false}) {
      for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n && pair[i] < 0; ++j) {
          if (pair[j] >= 0) continue;
          bool reversed = start(group[j]) == end(group[i]) && end(group[j]) == start(group[i]);
          if (reversed != opposite) continue;
          pair[i] = j, pair[j] = i;
        }
      }
    }
    for (int i = 0; i < n; ++i) {
      int other = pair[i] >= 0 ? pair[i] : (i == 0 ? 1 : 0);
      int g = group[i];
      partners[g].push_back({group[other], (end(g) - start(g)).norm()});
      seam[g] = true;
      sets.unite(g, group[0]);
    }
  }

  // Collinear matches among the edges still unmatched, found through a uniform 3D grid.
  if (options.match_collinear) {
    std::vector<int> unmatched;
    double length_sum = 0.0;
    for (int g = 0; g < edge_count; ++g) {
      double length = (end(g) - start(g)).norm();
      if (seam[g] || length == 0.0) continue;
      unmatched.push_back(g);
      length_sum += length;
    }
    if (unmatched.size() >= 2) {
      const double cell = length_sum / unmatched.size();
      constexpr std::int64_t kMaxCells = 512;
      std::map<std::array<std::int64_t, 3>, std::vector<int>> grid;
      std::vector<int> oversized;
      std::vector<std::array<std::int64_t, 6>> ranges(unmatched.size());
      for (std::size_t k = 0; k < unmatched.size(); ++k) {
        Vec3 lo = start(unmatched[k]).cwiseMin(end(unmatched[k]));
        Vec3 hi = start(unmatched[k]).cwiseMax(end(unmatched[k]));
        auto& r = ranges[k];
        for (int d = 0; d < 3; ++d)
          r[d] = cell_index(lo[d], cell), r[d + 3] = cell_index(hi[d], cell);
        if ((r[3] - r[0] + 1) * (r[4] - r[1] + 1) * (r[5] - r[2] + 1) > kMaxCells) {
          oversized.push_back(static_cast<int>(k));
          continue;
        }
        for (auto x = r[0]; x <= r[3]; ++x)
          for (auto y = r[1]; y <= r[4]; ++y)
            for (auto z = r[2]; z <= r[5]; ++z) grid[{x, y, z}].push_back(static_cast<int>(k));
      }
      std::vector<std::vector<Partner>> candidates(unmatched.size());
      std::vector<int> seen(unmatched.size(), -1);
      auto consider = [&](int k, int m) {
        if (m <= k || seen[m] == k) return;
        seen[m] = k;
        int g = unmatched[k], h = unmatched[m];
        double overlap =
            collinear_overlap(start(g), end(g), start(h), end(h), options.collinear_tolerance);
        if (overlap <= 0.0) return;
        candidates[k].push_back({m, overlap});
        candidates[m].push_back({k, overlap});
      };
      for (int k = 0; k < static_cast<int>(unmatched.size()); ++k) {
        const auto& r = ranges[k];
        for (int m : oversized) consider(k, m);
        if ((r[3] - r[0] + 1) * (r[4] - r[1] + 1) * (r[5] - r[2] + 1) > kMaxCells) {
          for (int m = k + 1; m < static_cast<int>(unmatched.size()); ++m) consider(k, m);
          continue;
        }
        for (auto x = r[0]; x <= r[3]; ++x)
          for (auto y = r[1]; y <= r[4]; ++y)
            for (auto z = r[2]; z <= r[5]; ++z) {
              auto it = grid.find({x, y, z});
              if (it == grid.end()) continue;
              for (int m : it->second) consider(k, m);
            }
      }
      // An edge is a seam when the union of its partners' intervals covers it.
      std::vector<bool> covered(unmatched.size(), false);
      for (std::size_t k = 0; k < unmatched.size(); ++k) {
        int g = unmatched[k];
        Vec3 a = start(g);
        double length = (end(g) - a).norm();
        Vec3 u = (end(g) - a) / length;
        std::vector<std::pair<double, double>> intervals;
        for (const Partner& p : candidates[k]) {
          int h = unmatched[p.edge];
          double t0 = (start(h) - a).dot(u), t1 = (end(h) - a).dot(u);
          intervals.push_back(
              {std::max(0.0, std::min(t0, t1)), std::min(length, std::max(t0, t1))});
        }
        std::sort(intervals.begin(), intervals.end());
        double reach = 0.0;
        for (const auto& [lo, hi] : intervals) {
          if (lo > reach + options.collinear_tolerance * length) break;
          reach = std::max(reach, hi);
        }
        covered[k] = reach >= length * (1.0 - options.collinear_tolerance);
      }
      for (std::size_t k = 0; k < unmatched.size(); ++k) {
        if (!covered[k]) continue;
        int g = unmatched[k];
        seam[g] = true;
        for (const Partner& p : candidates[k]) {
          partners[g].push_back({unmatched[p.edge], p.overlap});
          if (covered[p.edge]) sets.unite(g, unmatched[p.edge]);
        }
      }
    }
  }

  // Neighbour: the partner strip covering most of the edge (the first on ties).
  std::vector<int> neighbour_index(edge_count, -1);
  for (int g = 0; g < edge_count; ++g) {
    double best = -1.0;
    for (const Partner& p : partners[g])
      if (p.overlap > best) best = p.overlap, neighbour_index[g] = refs[p.edge].strip;
  }

  // One label per shared boundary: join consecutive seam edges whose partners touch at the
  // same 3D point in the same strip.
  auto touch = [&](int g, int h, const Vec3& junction) {
    for (const Partner& p : partners[g]) {
      for (const Partner& q : partners[h]) {
        if (refs[p.edge].strip != refs[q.edge].strip) continue;
        const FlatStrip& other = strips[refs[p.edge].strip];
        const BoundaryEdge& pe = boundary(p.edge);
        const BoundaryEdge& qe = boundary(q.edge);
        for (int w : {pe.v0, pe.v1})
          if ((w == qe.v0 || w == qe.v1) && other.vertices3d[w] == junction) return true;
      }
    }
    return false;
  };
  for (int s = 0, first = 0; s < static_cast<int>(strips.size()); ++s) {
    const FlatStrip& strip = strips[s];
    const int count = static_cast<int>(strip.boundary.size());
    std::unordered_multimap<int, int> outgoing;
    for (int e = 0; e < count; ++e) outgoing.emplace(strip.boundary[e].v0, first + e);
    for (int e = 0; e < count; ++e) {
      int g = first + e;
      if (!seam[g]) continue;
      auto [begin, stop] = outgoing.equal_range(strip.boundary[e].v1);
      for (auto it = begin; it != stop; ++it) {
        int h = it->second;
        if (!seam[h] || neighbour_index[h] != neighbour_index[g] || sets.find(g) == sets.find(h))
          continue;
        if (touch(g, h, strip.vertices3d[strip.boundary[e].v1])) sets.unite(g, h);
      }
    }
    first += count;
  }

  std::vector<int> label_of(edge_count, 0);
  int labels = 0;
  for (int g = 0; g < edge_count; ++g) {
    BoundaryEdge& edge = boundary(g);
    if (!seam[g]) {
      edge.kind = EdgeKind::Open;
      edge.neighbour_strip = -1;
      edge.label.clear();
      continue;
    }
    int root = sets.find(g);
    if (label_of[root] == 0) label_of[root] = ++labels;
    edge.kind = EdgeKind::Seam;
    edge.neighbour_strip = strips[neighbour_index[g]].id;
    edge.label = "A" + std::to_string(label_of[root]);
  }
}

}  // namespace papercraft
