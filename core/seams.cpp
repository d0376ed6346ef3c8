#include "core/seams.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

#include "core/errors.h"
#include "core/union_find.h"

namespace papercraft {
namespace {

using PointKey = std::array<double, 3>;
using EdgeKey = std::array<double, 6>;

PointKey key_of(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

EdgeKey directed_key(const Vec3& p, const Vec3& q) {
  return {p.x(), p.y(), p.z(), q.x(), q.y(), q.z()};
}

void check_ranges(const std::vector<FlatStrip>& strips) {
  for (const FlatStrip& strip : strips) {
    const int count = static_cast<int>(strip.vertices3d.size());
    for (std::size_t e = 0; e < strip.boundary.size(); ++e) {
      const BoundaryEdge& edge = strip.boundary[e];
      if (edge.v0 < 0 || edge.v0 >= count || edge.v1 < 0 || edge.v1 >= count)
        throw InvalidInputException("seams: strip " + std::to_string(strip.id) + " boundary edge " +
                                    std::to_string(e) + " has a vertex out of range [0, " +
                                    std::to_string(count) + ")");
    }
  }
}

struct EdgeRef {
  int strip;
  int edge;
};

std::vector<EdgeRef> all_edges(const std::vector<FlatStrip>& strips) {
  std::vector<EdgeRef> refs;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    for (int e = 0; e < static_cast<int>(strips[s].boundary.size()); ++e) refs.push_back({s, e});
  return refs;
}

std::int64_t cell_of(double coordinate, double cell) {
  return static_cast<std::int64_t>(std::floor(std::clamp(coordinate / cell, -1e9, 1e9)));
}

struct CellKeyHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : k) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// Splits strip.boundary[edge] at `points` (3D, sorted by `fractions` along the edge).
// False when no triangle of the strip has the directed edge.
bool split_edge(FlatStrip& strip, int edge, const std::vector<std::pair<double, Vec3>>& points) {
  const BoundaryEdge original = strip.boundary[edge];
  int triangle = -1, corner = -1;
  for (int f = 0; f < static_cast<int>(strip.triangles.size()) && triangle < 0; ++f) {
    const Triangle& t = strip.triangles[f];
    for (int k = 0; k < 3; ++k) {
      if (t[k] == original.v0 && t[(k + 1) % 3] == original.v1) {
        triangle = f;
        corner = k;
        break;
      }
    }
  }
  if (triangle < 0) return false;
  const int apex = strip.triangles[triangle][(corner + 2) % 3];
  const Vec2 a2 = strip.vertices2d[original.v0], b2 = strip.vertices2d[original.v1];
  const bool with_uvs = strip.uvs.size() == strip.vertices3d.size() && !strip.uvs.empty();
  std::vector<int> chain{original.v0};
  for (const auto& [t, point] : points) {
    chain.push_back(static_cast<int>(strip.vertices3d.size()));
    strip.vertices3d.push_back(point);
    strip.vertices2d.push_back(a2 + t * (b2 - a2));
    if (with_uvs) {
      strip.uvs.push_back(strip.uvs[original.v0] +
                          t * (strip.uvs[original.v1] - strip.uvs[original.v0]));
    }
  }
  chain.push_back(original.v1);
  strip.triangles[triangle] = {chain[0], chain[1], apex};
  for (std::size_t i = 1; i + 1 < chain.size(); ++i)
    strip.triangles.push_back({chain[i], chain[i + 1], apex});
  std::vector<BoundaryEdge> pieces;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    BoundaryEdge piece = original;
    piece.v0 = chain[i];
    piece.v1 = chain[i + 1];
    pieces.push_back(piece);
  }
  strip.boundary.erase(strip.boundary.begin() + edge);
  strip.boundary.insert(strip.boundary.begin() + edge, pieces.begin(), pieces.end());
  return true;
}

}  // namespace

int split_t_junctions(std::vector<FlatStrip>& strips, const SeamOptions& options) {
  check_ranges(strips);
  const std::vector<EdgeRef> refs = all_edges(strips);
  auto start = [&](const EdgeRef& r) -> const Vec3& {
    return strips[r.strip].vertices3d[strips[r.strip].boundary[r.edge].v0];
  };
  auto end = [&](const EdgeRef& r) -> const Vec3& {
    return strips[r.strip].vertices3d[strips[r.strip].boundary[r.edge].v1];
  };
  std::map<EdgeKey, int> directed;
  for (const EdgeRef& r : refs) ++directed[directed_key(start(r), end(r))];
  std::vector<int> unmatched;
  double length_sum = 0.0;
  for (int g = 0; g < static_cast<int>(refs.size()); ++g) {
    if (directed.count(directed_key(end(refs[g]), start(refs[g])))) continue;
    const double length = (end(refs[g]) - start(refs[g])).norm();
    if (!(length > 0.0)) continue;
    unmatched.push_back(g);
    length_sum += length;
  }
  if (unmatched.size() < 2) return 0;

  // The end points of unmatched edges, once each, in a uniform grid.
  std::vector<Vec3> points;
  {
    std::map<PointKey, int> seen;
    for (int g : unmatched) {
      for (const Vec3* p : {&start(refs[g]), &end(refs[g])}) {
        if (seen.emplace(key_of(*p), static_cast<int>(points.size())).second) points.push_back(*p);
      }
    }
  }
  const double cell = length_sum / static_cast<double>(unmatched.size());
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<int>, CellKeyHash> grid;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    grid[{cell_of(points[i].x(), cell), cell_of(points[i].y(), cell), cell_of(points[i].z(), cell)}]
        .push_back(i);

  // Per strip: edge index -> the points on it, with their fractions along it.
  std::vector<std::map<int, std::vector<std::pair<double, Vec3>>>> splits(strips.size());
  constexpr std::int64_t kMaxCells = 4096;
  for (int g : unmatched) {
    const Vec3& p = start(refs[g]);
    const Vec3& q = end(refs[g]);
    const Vec3 d = q - p;
    const double length2 = d.squaredNorm();
    const double length = std::sqrt(length2);
    const double reach = options.t_junction_tolerance * length;
    std::vector<std::pair<double, Vec3>> found;
    auto consider = [&](int i) {
      const Vec3& v = points[i];
      const double t = (v - p).dot(d) / length2;
      if (!(t * length > reach && (1.0 - t) * length > reach)) return;
      if ((v - p - t * d).norm() > reach) return;
      found.emplace_back(t, v);
    };
    const Vec3 lo = p.cwiseMin(q) - Vec3::Constant(reach),
               hi = p.cwiseMax(q) + Vec3::Constant(reach);
    std::array<std::int64_t, 3> c0{cell_of(lo.x(), cell), cell_of(lo.y(), cell),
                                   cell_of(lo.z(), cell)};
    std::array<std::int64_t, 3> c1{cell_of(hi.x(), cell), cell_of(hi.y(), cell),
                                   cell_of(hi.z(), cell)};
    const std::int64_t cells = (c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
    if (cells > kMaxCells) {
      for (int i = 0; i < static_cast<int>(points.size()); ++i) consider(i);
    } else {
      for (auto x = c0[0]; x <= c1[0]; ++x)
        for (auto y = c0[1]; y <= c1[1]; ++y)
          for (auto z = c0[2]; z <= c1[2]; ++z) {
            const auto it = grid.find({x, y, z});
            if (it == grid.end()) continue;
            for (int i : it->second) consider(i);
          }
    }
    if (found.empty()) continue;
    std::sort(found.begin(), found.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    splits[refs[g].strip][refs[g].edge] = std::move(found);
  }

  int inserted = 0;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    // Last edge first, so the indices of the edges still to split stay valid.
    for (auto it = splits[s].rbegin(); it != splits[s].rend(); ++it) {
      if (split_edge(strips[s], it->first, it->second))
        inserted += static_cast<int>(it->second.size());
    }
  }
  return inserted;
}

void label_seams(std::vector<FlatStrip>& strips, const SeamOptions& options) {
  check_ranges(strips);
  (void)options;
  const std::vector<EdgeRef> refs = all_edges(strips);
  const int edge_count = static_cast<int>(refs.size());
  std::vector<int> first_of_strip(strips.size() + 1, 0);
  for (std::size_t s = 0; s < strips.size(); ++s)
    first_of_strip[s + 1] = first_of_strip[s] + static_cast<int>(strips[s].boundary.size());
  auto edge = [&](int g) -> BoundaryEdge& { return strips[refs[g].strip].boundary[refs[g].edge]; };
  auto start = [&](int g) -> const Vec3& { return strips[refs[g].strip].vertices3d[edge(g).v0]; };
  auto end = [&](int g) -> const Vec3& { return strips[refs[g].strip].vertices3d[edge(g).v1]; };

  // Partners: edges with the same two end points, the other way first.
  std::vector<int> partner(edge_count, -1);
  {
    std::map<EdgeKey, std::vector<int>> by_ends;  // undirected: the smaller point first
    for (int g = 0; g < edge_count; ++g) {
      const PointKey a = key_of(start(g)), b = key_of(end(g));
      by_ends[a < b ? EdgeKey{a[0], a[1], a[2], b[0], b[1], b[2]}
                    : EdgeKey{b[0], b[1], b[2], a[0], a[1], a[2]}]
          .push_back(g);
    }
    for (const auto& [key, group] : by_ends) {
      if (group.size() < 2) continue;
      for (bool opposite : {true, false}) {
        for (std::size_t i = 0; i < group.size(); ++i) {
          if (partner[group[i]] >= 0) continue;
          for (std::size_t j = i + 1; j < group.size(); ++j) {
            if (partner[group[j]] >= 0) continue;
            const bool reversed = start(group[j]) == end(group[i]);
            if (reversed != opposite) continue;
            if (start(group[i]) == end(group[i])) continue;  // zero length: never glued
            partner[group[i]] = group[j];
            partner[group[j]] = group[i];
            break;
          }
        }
      }
    }
  }

  // Chains: an edge and the next one along its strip's boundary share a label when both are
  // glued to one strip where their partners are consecutive too: the other way round, or, for
  // partners that run the same way (strips of opposite orientation), the same way.
  UnionFind chains(static_cast<std::size_t>(edge_count));
  for (int g = 0; g < edge_count; ++g)
    if (partner[g] >= 0) chains.unite(g, partner[g]);
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    const FlatStrip& strip = strips[s];
    std::unordered_multimap<int, int> outgoing;
    for (int e = 0; e < static_cast<int>(strip.boundary.size()); ++e)
      outgoing.emplace(strip.boundary[e].v0, first_of_strip[s] + e);
    for (int e = 0; e < static_cast<int>(strip.boundary.size()); ++e) {
      const int g = first_of_strip[s] + e;
      if (partner[g] < 0) continue;
      const auto [from, to] = outgoing.equal_range(strip.boundary[e].v1);
      for (auto it = from; it != to; ++it) {
        const int h = it->second;
        if (partner[h] < 0 || refs[partner[h]].strip != refs[partner[g]].strip) continue;
        const bool same_way = start(partner[g]) == start(g) && start(partner[h]) == start(h);
        if (same_way ? edge(partner[h]).v0 != edge(partner[g]).v1
                     : edge(partner[h]).v1 != edge(partner[g]).v0)
          continue;
        chains.unite(g, h);
      }
    }
  }

  std::vector<int> label_of(edge_count, 0);
  int labels = 0;
  for (int g = 0; g < edge_count; ++g) {
    BoundaryEdge& e = edge(g);
    if (partner[g] < 0) {
      e.kind = EdgeKind::Open;
      e.neighbour_strip = -1;
      e.partner_edge = -1;
      e.label.clear();
      continue;
    }
    const std::size_t root = chains.find(g);
    if (label_of[root] == 0) label_of[root] = ++labels;
    e.kind = EdgeKind::Seam;
    e.neighbour_strip = strips[refs[partner[g]].strip].id;
    e.partner_edge = refs[partner[g]].edge;
    e.label = "A" + std::to_string(label_of[root]);
  }
}

std::vector<SeamChain> labelled_chains(const std::vector<FlatStrip>& strips) {
  std::map<int, int> index_of_id;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) index_of_id[strips[s].id] = s;
  std::vector<SeamChain> chains;
  std::map<std::string, int> chain_of_label;
  std::vector<std::vector<char>> taken(strips.size());
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    taken[s].assign(strips[s].boundary.size(), 0);
  // Walks one side: from edge e of strip s backwards to the chain's first edge, then forwards,
  // never stepping onto an edge's own partner (the two sides of a cone's opened ruling meet
  // at the apex).
  auto side_of = [&](int s, int e) {
    const FlatStrip& strip = strips[s];
    const std::string& label = strip.boundary[e].label;
    std::unordered_multimap<int, int> outgoing, incoming;
    for (int k = 0; k < static_cast<int>(strip.boundary.size()); ++k) {
      if (strip.boundary[k].kind != EdgeKind::Seam || strip.boundary[k].label != label) continue;
      outgoing.emplace(strip.boundary[k].v0, k);
      incoming.emplace(strip.boundary[k].v1, k);
    }
    auto glued = [&](int a, int b) {
      return strip.boundary[a].neighbour_strip == strip.id && strip.boundary[a].partner_edge == b;
    };
    int first = e;
    for (std::size_t steps = 0; steps < strip.boundary.size(); ++steps) {
      const auto it = incoming.find(strip.boundary[first].v0);
      if (it == incoming.end() || it->second == e || glued(it->second, first)) break;
      first = it->second;
    }
    SeamSide side;
    side.strip = strip.id;
    for (int k = first; k >= 0 && !taken[s][k];) {
      taken[s][k] = 1;
      side.edges.push_back(k);
      const auto it = outgoing.find(strip.boundary[k].v1);
      k = it == outgoing.end() || glued(k, it->second) ? -1 : it->second;
    }
    return side;
  };
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    for (int e = 0; e < static_cast<int>(strips[s].boundary.size()); ++e) {
      const BoundaryEdge& edge = strips[s].boundary[e];
      if (edge.kind != EdgeKind::Seam || taken[s][e]) continue;
      const auto found = chain_of_label.find(edge.label);
      if (found == chain_of_label.end()) {
        SeamChain chain;
        chain.label = edge.label;
        chain.sides[0] = side_of(s, e);
        // The other side starts at the partner of the side's last edge.
        const int last = chain.sides[0].edges.back();
        const BoundaryEdge& tail = strips[s].boundary[last];
        const auto other = index_of_id.find(tail.neighbour_strip);
        if (other != index_of_id.end() && tail.partner_edge >= 0 &&
            !taken[other->second][tail.partner_edge]) {
          chain.sides[1] = side_of(other->second, tail.partner_edge);
        }
        chain_of_label[edge.label] = static_cast<int>(chains.size());
        chains.push_back(std::move(chain));
      } else {
        // A chain whose two sides lie on one loop of one strip and meet (a closed self-seam):
        // the rest of it.
        SeamSide more = side_of(s, e);
        SeamSide& side = chains[found->second].sides[1];
        if (side.strip < 0) side.strip = more.strip;
        side.edges.insert(side.edges.end(), more.edges.begin(), more.edges.end());
      }
    }
  }
  return chains;
}

}  // namespace papercraft
