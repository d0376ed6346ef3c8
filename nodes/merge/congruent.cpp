#include "nodes/merge/congruent.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include "core/dual_cuts.h"
#include "core/errors.h"
#include "core/flat_boundary.h"
#include "core/overlap_2d.h"
#include "core/piece_width.h"
#include "core/seams.h"
#include "core/union_find.h"

namespace papercraft {
namespace {

// A shared boundary of strips X and Y: x[i] in X and y[i] in Y are the same 3D point.
struct Chain {
  std::vector<int> x;
  std::vector<int> y;
  double length = 0.0;
};

struct PairCandidate {
  int x = -1;  // strip indices, x < y
  int y = -1;
  std::vector<Chain> chains;
  double total_length = 0.0;
};

struct RigidMotion {
  double cos = 1.0, sin = 0.0;
  Vec2 translation = Vec2::Zero();
  Vec2 operator()(const Vec2& p) const {
    return Vec2(cos * p.x() - sin * p.y(), sin * p.x() + cos * p.y()) + translation;
  }
};

void validate(const std::vector<FlatStrip>& strips, const MergeOptions& options) {
  if (!(options.congruence_tolerance >= 0.0) || !(options.overlap_tolerance >= 0.0))
    throw InvalidInputException("merge: tolerances must be >= 0");
  for (const FlatStrip& strip : strips) {
    const std::size_t n = strip.vertices3d.size();
    std::string name = "merge: flat strip " + std::to_string(strip.id);
    if (strip.vertices2d.size() != n)
      throw InvalidInputException(name + " has " + std::to_string(strip.vertices2d.size()) +
                                  " 2D vertices for " + std::to_string(n) + " 3D vertices");
    if (!strip.uvs.empty() && strip.uvs.size() != n)
      throw InvalidInputException(name + " has " + std::to_string(strip.uvs.size()) + " uvs for " +
                                  std::to_string(n) + " vertices");
    for (const Triangle& t : strip.triangles)
      for (int v : t)
        if (v < 0 || static_cast<std::size_t>(v) >= n)
          throw InvalidInputException(name + " has a triangle vertex " + std::to_string(v) +
                                      " out of range [0, " + std::to_string(n) + ")");
  }
}

std::array<double, 6> exact_key(const Vec3& p, const Vec3& q) {
  std::array<double, 3> a{p.x(), p.y(), p.z()}, b{q.x(), q.y(), q.z()};
  if (b < a) std::swap(a, b);
  return {a[0], a[1], a[2], b[0], b[1], b[2]};
}

// The 3D edges (exact_key) of a strip's boundary.
std::set<std::array<double, 6>> rim_of(const FlatStrip& strip) {
  std::set<std::array<double, 6>> rim;
  for (const BoundaryEdge& e : strip.boundary)
    rim.insert(exact_key(strip.vertices3d[e.v0], strip.vertices3d[e.v1]));
  return rim;
}

// Chains of boundary edges glued (opposite directions) between every pair of strips, or,
// given `with`, only the pairs strips[with] is in (the same pairs, in the same order, as the
// whole list has; the edges of the others are looked at only where they lie on its rim).
std::vector<PairCandidate> shared_boundaries(const std::vector<FlatStrip>& strips, int with = -1) {
  const std::set<std::array<double, 6>> rim =
      with >= 0 ? rim_of(strips[with]) : std::set<std::array<double, 6>>{};
  std::map<std::array<double, 6>, std::vector<std::pair<int, int>>> groups;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    for (int e = 0; e < static_cast<int>(strips[s].boundary.size()); ++e) {
      const BoundaryEdge& edge = strips[s].boundary[e];
      const auto key = exact_key(strips[s].vertices3d[edge.v0], strips[s].vertices3d[edge.v1]);
      if (with < 0 || rim.count(key)) groups[key].push_back({s, e});
    }
  // (x, y) -> glued edge pairs (edge of x, edge of y).
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> glued;
  for (const auto& [key, group] : groups) {
    for (std::size_t i = 0; i < group.size(); ++i) {
      for (std::size_t j = i + 1; j < group.size(); ++j) {
        auto [si, ei] = group[i];
        auto [sj, ej] = group[j];
        if (si == sj || (with >= 0 && si != with && sj != with)) continue;
        const BoundaryEdge& a = strips[si].boundary[ei];
        const BoundaryEdge& b = strips[sj].boundary[ej];
        if (strips[si].vertices3d[a.v0] != strips[sj].vertices3d[b.v1] ||
            strips[si].vertices3d[a.v1] != strips[sj].vertices3d[b.v0])
          continue;
        if (si < sj)
          glued[{si, sj}].push_back({ei, ej});
        else
          glued[{sj, si}].push_back({ej, ei});
      }
    }
  }

  std::vector<PairCandidate> result;
  for (auto& glued_pair : glued) {
    // Named references, not a structured binding: clang before 16 cannot capture one.
    const auto& strip_pair = glued_pair.first;
    auto& pairs = glued_pair.second;
    const FlatStrip& x = strips[strip_pair.first];
    const FlatStrip& y = strips[strip_pair.second];
    std::sort(pairs.begin(), pairs.end());
    const int n = static_cast<int>(pairs.size());
    // Successor of a glued pair: the next edge of X along its boundary, whose partner in
    // Y is the previous edge of Y (they share the Y vertex at the junction).
    std::multimap<int, int> by_x_start;  // X edge v0 -> pair index
    for (int k = 0; k < n; ++k) by_x_start.emplace(x.boundary[pairs[k].first].v0, k);
    std::vector<int> next(n, -1), previous_count(n, 0);
    for (int k = 0; k < n; ++k) {
      const BoundaryEdge& ex = x.boundary[pairs[k].first];
      const BoundaryEdge& ey = y.boundary[pairs[k].second];
      auto [begin, end] = by_x_start.equal_range(ex.v1);
      for (auto it = begin; it != end; ++it) {
        if (y.boundary[pairs[it->second].second].v1 != ey.v0 || previous_count[it->second] > 0)
          continue;
        next[k] = it->second;
        ++previous_count[it->second];
        break;
      }
    }
    PairCandidate candidate;
    candidate.x = strip_pair.first;
    candidate.y = strip_pair.second;
    std::vector<bool> used(n, false);
    auto walk = [&](int k) {
      Chain chain;
      chain.x.push_back(x.boundary[pairs[k].first].v0);
      chain.y.push_back(y.boundary[pairs[k].second].v1);
      while (k >= 0 && !used[k]) {
        used[k] = true;
        const BoundaryEdge& ex = x.boundary[pairs[k].first];
        chain.x.push_back(ex.v1);
        chain.y.push_back(y.boundary[pairs[k].second].v0);
        chain.length += (x.vertices3d[ex.v1] - x.vertices3d[ex.v0]).norm();
        k = next[k];
      }
      candidate.total_length += chain.length;
      candidate.chains.push_back(std::move(chain));
    };
    for (int k = 0; k < n; ++k)
      if (previous_count[k] == 0) walk(k);
    for (int k = 0; k < n; ++k)  // closed loops
      if (!used[k]) walk(k);
    result.push_back(std::move(candidate));
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const PairCandidate& a, const PairCandidate& b) {
                     return a.total_length > b.total_length;
                   });
  return result;
}

// Best rotation + translation taking the points of Y onto those of X (2D Procrustes
// without reflection; Umeyama 1991 restricted to det R = +1).
RigidMotion fit(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  Vec2 from_centre = Vec2::Zero(), to_centre = Vec2::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) from_centre += from[i], to_centre += to[i];
  from_centre /= static_cast<double>(from.size());
  to_centre /= static_cast<double>(to.size());
  double dot = 0.0, cross = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    Vec2 p = from[i] - from_centre, q = to[i] - to_centre;
    dot += p.dot(q);
    cross += p.x() * q.y() - p.y() * q.x();
  }
  RigidMotion motion;
  double norm = std::hypot(dot, cross);
  if (norm > 0.0) motion.cos = dot / norm, motion.sin = cross / norm;
  motion.translation = Vec2::Zero();
  motion.translation = to_centre - motion(from_centre);
  return motion;
}

double chain_residual(const FlatStrip& x, const FlatStrip& y, const Chain& chain,
                      const RigidMotion& motion) {
  double residual = 0.0;
  for (std::size_t i = 0; i < chain.x.size(); ++i)
    residual =
        std::max(residual, (motion(y.vertices2d[chain.y[i]]) - x.vertices2d[chain.x[i]]).norm());
  return residual;
}

double mean_edge_length(const FlatStrip& strip) {
  double sum = 0.0;
  for (const Triangle& t : strip.triangles)
    for (int i = 0; i < 3; ++i)
      sum += (strip.vertices2d[t[(i + 1) % 3]] - strip.vertices2d[t[i]]).norm();
  return strip.triangles.empty() ? 0.0 : sum / (3.0 * strip.triangles.size());
}

// No directed edge is used by two triangles.
bool consistently_oriented(const std::vector<Triangle>& triangles) {
  std::vector<std::pair<int, int>> directed;
  directed.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) directed.emplace_back(t[i], t[(i + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  return std::adjacent_find(directed.begin(), directed.end()) == directed.end();
}

// X's triangles in a grid, for the overlap tests of try_merge. The trials of one join try the
// same strip against many partners (every hinge of a band onto one neighbour, every cut of it),
// so the grids of the strips tried last are kept, per thread, and found again by their exact
// contents. Which stored triangles a query penetrates does not depend on the grid's cells, so
// one grid serves every partner.
std::shared_ptr<TriangleGrid2> grid_of(const FlatStrip& x) {
  struct Entry {
    std::vector<Vec2> points;
    std::vector<Triangle> triangles;
    std::shared_ptr<TriangleGrid2> grid;
  };
  constexpr std::size_t kKept = 8;
  thread_local std::vector<Entry> kept;  // the one used last at the back
  const auto same = [&](const Entry& e) {
    return e.points.size() == x.vertices2d.size() && e.triangles.size() == x.triangles.size() &&
           std::memcmp(e.points.data(), x.vertices2d.data(), x.vertices2d.size() * sizeof(Vec2)) ==
               0 &&
           std::memcmp(e.triangles.data(), x.triangles.data(),
                       x.triangles.size() * sizeof(Triangle)) == 0;
  };
  for (auto it = kept.begin(); it != kept.end(); ++it)
    if (same(*it)) {
      std::rotate(it, it + 1, kept.end());
      return kept.back().grid;
    }
  const double cell = mean_edge_length(x);
  auto grid = std::make_shared<TriangleGrid2>(cell > 0.0 ? cell : 1.0);
  for (const Triangle& t : x.triangles)
    grid->insert({x.vertices2d[t[0]], x.vertices2d[t[1]], x.vertices2d[t[2]]});
  if (kept.size() == kKept) kept.erase(kept.begin());
  kept.push_back({x.vertices2d, x.triangles, grid});
  return grid;
}

// Y moved onto X along one of their chains and welded, or false when no chain gives a
// congruent, overlap-free union. Without `with_boundary` the union's boundary is left empty
// (a caller that tries many unions and keeps one finds the boundary of that one).
bool try_merge(const FlatStrip& x, const FlatStrip& y, std::vector<Chain> chains,
               const MergeOptions& options, FlatStrip& merged, bool with_boundary = true) {
  std::stable_sort(chains.begin(), chains.end(),
                   [](const Chain& a, const Chain& b) { return a.length > b.length; });
  const double mean_edge = 0.5 * (mean_edge_length(x) + mean_edge_length(y));
  std::shared_ptr<TriangleGrid2> grid;  // X's, once a chain is congruent
  for (std::size_t seed = 0; seed < chains.size(); ++seed) {
    const Chain& chain = chains[seed];
    std::vector<Vec2> from, to;
    for (std::size_t i = 0; i < chain.x.size(); ++i) {
      from.push_back(y.vertices2d[chain.y[i]]);
      to.push_back(x.vertices2d[chain.x[i]]);
    }
    RigidMotion motion = fit(from, to);
    double residual = chain_residual(x, y, chain, motion);
    if (residual > options.congruence_tolerance * chain.length) continue;

    std::vector<Vec2> moved(y.vertices2d.size());
    for (std::size_t v = 0; v < moved.size(); ++v) moved[v] = motion(y.vertices2d[v]);
    if (!grid) grid = grid_of(x);
    const double tolerance = options.overlap_tolerance * mean_edge + 4.0 * residual;
    bool overlap = false;
    for (const Triangle& t : y.triangles)
      if ((overlap = grid->overlaps({moved[t[0]], moved[t[1]], moved[t[2]]}, tolerance))) break;
    if (overlap) continue;

    // Weld the seed and every other chain that lands on its partner, keeping the map from
    // Y's vertices to X's one-to-one (a chain that would break that stays a seam).
    std::vector<int> weld(y.vertices2d.size(), -1);
    std::vector<bool> taken(x.vertices2d.size(), false);
    bool seed_welded = false;
    for (std::size_t c = 0; c < chains.size(); ++c) {
      std::size_t k = c == 0 ? seed : (c <= seed ? c - 1 : c);
      const Chain& candidate = chains[k];
      if (k != seed &&
          chain_residual(x, y, candidate, motion) > options.congruence_tolerance * candidate.length)
        continue;
      std::vector<int> trial = weld;
      std::vector<bool> trial_taken = taken;
      bool consistent = true;
      for (std::size_t i = 0; i < candidate.x.size() && consistent; ++i) {
        int yi = candidate.y[i], xi = candidate.x[i];
        if (trial[yi] == xi) continue;
        consistent = trial[yi] < 0 && !trial_taken[xi];
        trial[yi] = xi;
        trial_taken[xi] = true;
      }
      if (!consistent) continue;
      weld = std::move(trial);
      taken = std::move(trial_taken);
      if (k == seed) seed_welded = true;
    }
    if (!seed_welded) continue;

    merged = x;
    const bool keep_uvs =
        x.uvs.size() == x.vertices2d.size() && y.uvs.size() == y.vertices2d.size();
    if (!keep_uvs) merged.uvs.clear();
    std::vector<int> index(y.vertices2d.size());
    for (std::size_t v = 0; v < index.size(); ++v) {
      if (weld[v] >= 0) {
        index[v] = weld[v];
        continue;
      }
      index[v] = static_cast<int>(merged.vertices2d.size());
      merged.vertices2d.push_back(moved[v]);
      merged.vertices3d.push_back(y.vertices3d[v]);
      if (keep_uvs) merged.uvs.push_back(y.uvs[v]);
    }
    for (const Triangle& t : y.triangles)
      merged.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    // The fit leaves up to congruence_tolerance of the chain's length between Y's seam points
    // and X's, which a short edge beside the seam would take whole.
    std::vector<Vec2> welded = moved;
    for (std::size_t v = 0; v < welded.size(); ++v)
      if (weld[v] >= 0) welded[v] = x.vertices2d[weld[v]];
    if (!weld_keeps_lengths(y.vertices3d, y.triangles, moved, welded)) continue;
    // Welding must keep the strip a consistently oriented manifold: a directed edge used by
    // two triangles means the chains were glued the wrong way round somewhere; and welding
    // snaps y's seam vertices onto x's, so a thin triangle next to the seam must not flip.
    if (!consistently_oriented(merged.triangles) ||
        first_clockwise_triangle(merged.vertices2d, merged.triangles, 1e-10) >= 0)
      continue;
    merged.boundary.clear();
    if (with_boundary) merged.boundary = flat_boundary(merged.triangles);
    return true;
  }
  return false;
}

}  // namespace

std::vector<FlatStrip> merge_congruent(std::vector<FlatStrip> strips, const MergeOptions& options) {
  validate(strips, options);
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);

  // A pair that failed is not tried again until one of its strips changes.
  std::vector<int> version(strips.size());
  for (std::size_t i = 0; i < strips.size(); ++i) version[i] = static_cast<int>(i);
  int next_version = static_cast<int>(strips.size());
  std::set<std::pair<int, int>> failed;
  for (bool merged_any = true; merged_any;) {
    merged_any = false;
    for (PairCandidate& candidate : shared_boundaries(strips)) {
      std::pair<int, int> key{version[candidate.x], version[candidate.y]};
      if (failed.count(key)) continue;
      FlatStrip merged;
      if (!try_merge(strips[candidate.x], strips[candidate.y], std::move(candidate.chains), options,
                     merged)) {
        failed.insert(key);
        continue;
      }
      strips[candidate.x] = std::move(merged);
      version[candidate.x] = next_version++;
      strips.erase(strips.begin() + candidate.y);
      version.erase(version.begin() + candidate.y);
      merged_any = true;
      break;
    }
  }
  label_seams(strips);
  return strips;
}

namespace {

// Single-edge hinges of the pairs `wanted` picks, the longest first:
// (pair index, edge) over shared_boundaries(strips), and whether the edge is at an end of an
// open chain (the chain's other edges then all lie on one side of it).
struct Hinge {
  int pair;
  Chain edge;
  bool chain_end = false;
};

std::vector<Hinge> hinges_of(const std::vector<PairCandidate>& pairs,
                             const std::vector<FlatStrip>& strips,
                             const std::function<bool(const PairCandidate&)>& wanted) {
  std::vector<Hinge> hinges;
  for (int p = 0; p < static_cast<int>(pairs.size()); ++p) {
    if (!wanted(pairs[p])) continue;
    const FlatStrip& x = strips[pairs[p].x];
    for (const Chain& chain : pairs[p].chains)
      for (std::size_t i = 0; i + 1 < chain.x.size(); ++i) {
        Chain edge;
        edge.x = {chain.x[i], chain.x[i + 1]};
        edge.y = {chain.y[i], chain.y[i + 1]};
        edge.length = (x.vertices3d[chain.x[i + 1]] - x.vertices3d[chain.x[i]]).norm();
        const bool open = chain.x.front() != chain.x.back();
        hinges.push_back({p, std::move(edge), open && (i == 0 || i + 2 == chain.x.size())});
      }
  }
  std::stable_sort(hinges.begin(), hinges.end(),
                   [](const Hinge& a, const Hinge& b) { return a.edge.length > b.edge.length; });
  return hinges;
}

// The triangles `chosen` of `strip` as a strip of their own, laid out as they lie, their
// vertices renumbered (unused ones dropped); its boundary left empty without `with_boundary`.
FlatStrip sub_strip(const FlatStrip& strip, const std::vector<Triangle>& chosen,
                    bool with_boundary = true) {
  FlatStrip part;
  part.id = strip.id;
  part.source_strip = strip.source_strip;
  const bool has_uvs = strip.uvs.size() == strip.vertices2d.size();
  std::vector<int> index(strip.vertices2d.size(), -1);
  for (Triangle t : chosen) {
    for (int& v : t) {
      if (index[v] < 0) {
        index[v] = static_cast<int>(part.vertices2d.size());
        part.vertices2d.push_back(strip.vertices2d[v]);
        part.vertices3d.push_back(strip.vertices3d[v]);
        if (has_uvs) part.uvs.push_back(strip.uvs[v]);
      }
      v = index[v];
    }
    part.triangles.push_back(t);
  }
  if (with_boundary) part.boundary = flat_boundary(part.triangles);
  return part;
}

// The indices of the strips with a boundary edge on strip `index`'s rim (its neighbours), in
// order.
std::vector<int> strips_beside(const std::vector<FlatStrip>& strips, int index) {
  const FlatStrip& strip = strips[index];
  const std::set<std::array<double, 6>> rim = rim_of(strip);
  std::vector<int> around;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    if (s == index) continue;
    for (const BoundaryEdge& e : strips[s].boundary)
      if (rim.count(exact_key(strips[s].vertices3d[e.v0], strips[s].vertices3d[e.v1]))) {
        around.push_back(s);
        break;
      }
  }
  return around;
}

// A strip no neighbour takes whole, taken apart into its triangles, each hinged to a
// neighbour across one of its edges (a triangle whose neighbours are all its own siblings
// waits until a sibling has been taken): where the union of the whole would overlap a
// neighbour (a notch narrower in the plane than on the surface, at a saddle), single
// triangles often still fold out on the free side. Kept only when every triangle finds a
// place and at most one of the strip's inner edges is opened; otherwise `strips` is left as
// it was and false returned.
bool absorb_by_triangles(std::vector<FlatStrip>& strips, int small, const MergeOptions& options) {
  constexpr std::size_t kMostTriangles = 64;
  constexpr int kMostOpened = 1;
  const FlatStrip& crumb = strips[small];
  if (crumb.triangles.size() < 2 || crumb.triangles.size() > kMostTriangles) return false;
  // Only the crumb's neighbours (a boundary edge on its rim) can take its triangles: they
  // and the triangles are worked on apart from the other strips, then put back.
  const std::vector<int> around = strips_beside(strips, small);
  if (around.empty()) return false;
  // trial: the neighbours at 0..n-1, then the triangles not yet taken. A triangle taken is
  // welded into the neighbour (the lower index keeps its place and id) and erased, so the
  // neighbours never move and the rest of `trial` is always the triangles left.
  const int n = static_cast<int>(around.size());
  std::vector<FlatStrip> trial;
  trial.reserve(around.size() + crumb.triangles.size());
  for (int s : around) trial.push_back(strips[s]);
  for (const Triangle& t : crumb.triangles) trial.push_back(sub_strip(crumb, {t}));
  std::vector<bool> touched(around.size(), false);  // neighbours that took a triangle
  while (static_cast<int>(trial.size()) > n) {
    const std::vector<PairCandidate> pairs = shared_boundaries(trial);
    // A neighbour (x, the lower index) and a triangle (y).
    const auto hinges = hinges_of(
        pairs, trial, [&](const PairCandidate& pair) { return pair.x < n && pair.y >= n; });
    bool taken = false;
    for (const Hinge& hinge : hinges) {
      const PairCandidate& pair = pairs[hinge.pair];
      FlatStrip merged;
      if (!try_merge(trial[pair.x], trial[pair.y], {hinge.edge}, options, merged)) continue;
      touched[pair.x] = true;
      trial[pair.x] = std::move(merged);
      trial.erase(trial.begin() + pair.y);
      taken = true;
      break;
    }
    if (!taken) return false;
  }
  // Each edge between two of the crumb's triangles that the plane no longer joins is one more
  // seam to glue (often a tiny one in a notch, with no room for a tab): at most one.
  std::map<std::array<double, 6>, int> inner;  // the crumb's inner edges
  for (const Triangle& t : crumb.triangles)
    for (int k = 0; k < 3; ++k)
      ++inner[exact_key(crumb.vertices3d[t[k]], crumb.vertices3d[t[(k + 1) % 3]])];
  int opened = 0;
  for (const auto& [key, count] : inner) opened += count > 1;
  for (int i = 0; i < n; ++i) {
    if (!touched[i]) continue;
    const FlatStrip& strip = trial[i];
    std::map<std::pair<int, int>, int> uses;
    for (const Triangle& t : strip.triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        ++uses[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& [edge, count] : uses) {
      if (count < 2) continue;
      auto it = inner.find(exact_key(strip.vertices3d[edge.first], strip.vertices3d[edge.second]));
      if (it != inner.end() && it->second > 1) {
        it->second = 0;  // still joined in the plane
        --opened;
      }
    }
  }
  if (opened > kMostOpened) return false;
  for (int i = 0; i < n; ++i) strips[around[i]] = std::move(trial[i]);
  strips.erase(strips.begin() + small);
  return true;
}

// Triangle `t` of `strip` by its 3D corners, sorted: the same key wherever a triangle on those
// points is printed.
std::array<double, 9> corners_key(const FlatStrip& strip, const Triangle& t) {
  std::array<std::array<double, 3>, 3> c;
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = strip.vertices3d[t[k]];
    c[k] = {p.x(), p.y(), p.z()};
  }
  std::sort(c.begin(), c.end());
  return {c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]};
}

// Whether the triangles around `vertex` form one fan (each joined to the next across an
// edge), not two fans meeting at a point.
bool one_fan(const std::vector<Triangle>& triangles, int vertex) {
  std::vector<const Triangle*> fan;
  for (const Triangle& t : triangles)
    if (std::find(t.begin(), t.end(), vertex) != t.end()) fan.push_back(&t);
  UnionFind around(fan.size());
  for (std::size_t i = 0; i < fan.size(); ++i)
    for (std::size_t j = i + 1; j < fan.size(); ++j) {
      int common = 0;
      for (int a : *fan[i]) common += std::find(fan[j]->begin(), fan[j]->end(), a) != fan[j]->end();
      if (common >= 2) around.unite(i, j);
    }
  for (std::size_t i = 1; i < fan.size(); ++i)
    if (around.find(i) != around.find(0)) return false;
  return true;
}

// Triangle `gone` of `strip` taken away, with whatever it alone held to the rest (a ruled
// strip is a path of triangles: taking one takes the end beyond it too): `rest` is the
// largest piece left (by area), `taken` the triangle with the smaller pieces. False when
// nothing is left or the rest would meet the part taken only at a point of its own.
bool take_triangle(const FlatStrip& strip, std::size_t gone, FlatStrip& rest, FlatStrip& taken) {
  const int n = static_cast<int>(strip.triangles.size());
  if (n < 2) return false;
  // The triangles left, joined across the edges they share: (edge, triangle), sorted.
  std::vector<std::pair<std::pair<int, int>, int>> by_edge;
  by_edge.reserve(3 * n);
  for (int t = 0; t < n; ++t) {
    if (t == static_cast<int>(gone)) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = strip.triangles[t][k], b = strip.triangles[t][(k + 1) % 3];
      by_edge.push_back({{std::min(a, b), std::max(a, b)}, t});
    }
  }
  std::sort(by_edge.begin(), by_edge.end());
  UnionFind pieces(n);
  for (std::size_t i = 1; i < by_edge.size(); ++i)
    if (by_edge[i].first == by_edge[i - 1].first)
      pieces.unite(by_edge[i - 1].second, by_edge[i].second);
  std::map<std::size_t, double> area;
  for (int t = 0; t < n; ++t) {
    if (t == static_cast<int>(gone)) continue;
    const Triangle& tri = strip.triangles[t];
    const Vec2 u = strip.vertices2d[tri[1]] - strip.vertices2d[tri[0]];
    const Vec2 v = strip.vertices2d[tri[2]] - strip.vertices2d[tri[0]];
    area[pieces.find(t)] += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
  }
  std::size_t largest = 0;
  double most = -1.0;
  for (const auto& [root, a] : area)
    if (a > most) largest = root, most = a;
  std::vector<Triangle> kept, moved;
  std::set<int> moved_corners;
  for (int t = 0; t < n; ++t) {
    const bool stays = t != static_cast<int>(gone) && pieces.find(t) == largest;
    (stays ? kept : moved).push_back(strip.triangles[t]);
    if (!stays) moved_corners.insert(strip.triangles[t].begin(), strip.triangles[t].end());
  }
  for (int corner : moved_corners)
    if (!one_fan(kept, corner)) return false;
  rest = sub_strip(strip, kept, false);  // its boundary is found only if it is kept
  taken = sub_strip(strip, moved);
  return true;
}

// A strip grown from its neighbours (a crumb no neighbour takes, a band no hinge takes): it
// takes their triangles that share an edge with it, one at a time, each folded out of it
// across every edge it shares; of those that find a place, the one leaving it most compact
// (with `least_narrow_first`, of those leaving it narrow over the least share, the most
// compact). A triangle takes with it the part of its strip it alone held on (the end of a ruled
// strip). It is taken only where it lands on no triangle of the strip, every edge shared welds (no
// slit opens in the strip) and what is left of the neighbour is at least min_area. Grows
// until the strip reaches min_area (kMinArea) or is narrower than min_width over at most
// narrow_share of its area (kWide), and neither the strip nor a neighbour it took from is
// narrower than min_width over more than narrow_share of its area (or more than it was).
// Kept only when that is reached within kMostTaken triangles; otherwise `strips` is left as
// it was and false returned.
enum class GrowUntil { kMinArea, kWide };

bool grow_from_neighbours(std::vector<FlatStrip>& strips, int index, GrowUntil until,
                          double min_area, double min_width, double narrow_share,
                          const MergeOptions& options, bool least_narrow_first = false) {
  constexpr std::size_t kMostTaken = 128;
  auto share_of = [&](const FlatStrip& strip) {
    return min_width > 0.0 ? narrow_area_fraction(strip.vertices2d, strip.triangles, min_width)
                           : 0.0;
  };
  FlatStrip grown = strips[index];
  const std::size_t first_size = grown.triangles.size();
  const double grown_share = share_of(grown);
  std::map<int, FlatStrip> donors;  // strip index -> what is left of it
  auto current = [&](int s) -> const FlatStrip& {
    auto it = donors.find(s);
    return it == donors.end() ? strips[s] : it->second;
  };
  std::set<std::array<double, 9>> refused;  // triangles (their 3D corners) that found no place
  struct Candidate {
    int strip;
    std::size_t triangle;
  };
  // A growth is acceptable when neither the strip nor a neighbour it took from is narrower
  // than min_width over more of its area than before (or than narrow_share). The shares of
  // the neighbours, before and as left, are kept as they are measured.
  std::map<int, double> share_before, share_left;
  auto acceptable = [&](double share) {
    if (share > std::max(grown_share, narrow_share)) return false;
    for (const auto& [s, rest] : donors) {
      if (!share_before.count(s)) share_before[s] = share_of(strips[s]);
      if (!share_left.count(s)) share_left[s] = share_of(rest);
      if (share_left[s] > std::max(share_before[s], narrow_share)) return false;
    }
    return true;
  };
  // A crumb stops at the first acceptable growth past min_area; one that is not (a neighbour
  // it took from got narrower) goes on growing, within the same kMostTaken, until one is. A
  // band stops once it is narrow over at most narrow_share and acceptable. Either gives up
  // once kPatience triangles in a row bring it no closer: a band that stays narrow (a strip
  // along a thin feature) would only pay for the rest of kMostTaken and fail anyway.
  constexpr int kPatience = 16;
  double least_share = grown_share;
  int since_least = 0;
  while (true) {
    if (until == GrowUntil::kWide || flat_area(grown) >= min_area) {
      const double share = share_of(grown);
      if ((until == GrowUntil::kMinArea || share <= narrow_share) && acceptable(share)) break;
      if (until == GrowUntil::kWide && share < least_share) {
        least_share = share, since_least = 0;
      } else if (++since_least >= kPatience) {
        return false;
      }
    }
    const std::set<std::array<double, 6>> rim = rim_of(grown);
    // The neighbours' triangles on the rim: those with a boundary edge on it.
    std::vector<Candidate> candidates;
    for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
      if (s == index) continue;
      const FlatStrip& strip = current(s);
      std::set<std::pair<int, int>> on_rim;  // boundary edges (v0, v1) on the rim
      for (const BoundaryEdge& e : strip.boundary)
        if (rim.count(exact_key(strip.vertices3d[e.v0], strip.vertices3d[e.v1])))
          on_rim.insert({e.v0, e.v1});
      if (on_rim.empty()) continue;
      for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
        const Triangle& tri = strip.triangles[t];
        bool shares = false;
        for (int k = 0; k < 3; ++k) shares = shares || on_rim.count({tri[k], tri[(k + 1) % 3]});
        if (shares && !refused.count(corners_key(strip, tri))) candidates.push_back({s, t});
      }
    }
    // Of the triangles that find a place, the one leaving the strip most compact (the least
    // squared perimeter per area in the plane: a round piece is wide, a long one narrow); with
    // least_narrow_first, of those leaving it narrower than min_width over the least share of
    // its area.
    FlatStrip best, best_rest;
    int best_strip = -1;
    std::pair<double, double> best_score{0.0, 0.0};
    for (const Candidate& candidate : candidates) {
      const FlatStrip& donor = current(candidate.strip);
      const Triangle& tri = donor.triangles[candidate.triangle];
      FlatStrip rest, part;
      const std::vector<PairCandidate> pairs =
          take_triangle(donor, candidate.triangle, rest, part) && flat_area(rest) >= min_area &&
                  grown.triangles.size() + part.triangles.size() <= first_size + kMostTaken
              ? shared_boundaries({grown, part})
              : std::vector<PairCandidate>{};
      // Every shared edge welds: the strip gains only the part's corners off its rim.
      std::set<int> on_rim;
      for (const PairCandidate& pair : pairs)
        for (const Chain& chain : pair.chains) on_rim.insert(chain.y.begin(), chain.y.end());
      FlatStrip merged;
      if (pairs.empty() || !try_merge(grown, part, pairs[0].chains, options, merged) ||
          merged.vertices2d.size() !=
              grown.vertices2d.size() + part.vertices2d.size() - on_rim.size()) {
        refused.insert(corners_key(donor, tri));
        continue;
      }
      double perimeter = 0.0;
      for (const BoundaryEdge& e : merged.boundary)
        perimeter += (merged.vertices2d[e.v1] - merged.vertices2d[e.v0]).norm();
      const std::pair<double, double> score{least_narrow_first ? share_of(merged) : 0.0,
                                            perimeter * perimeter / flat_area(merged)};
      if (best_strip >= 0 && score >= best_score) continue;
      best = std::move(merged);
      best_rest = std::move(rest);
      best_strip = candidate.strip, best_score = score;
    }
    if (best_strip < 0) return false;
    grown = std::move(best);
    best_rest.boundary = flat_boundary(best_rest.triangles);
    donors[best_strip] = std::move(best_rest);
    share_left.erase(best_strip);
  }
  strips[index] = std::move(grown);
  for (auto& [s, rest] : donors) strips[s] = std::move(rest);
  return true;
}

// How much of the seam a hinge leaves between the two strips `merged` joined is a slit: the
// number of points it took from the second strip (at `first_added` and after) that lie closer
// than `width` in the plane to a point of the first with the same 3D point. A band folded
// out beside the edge it shares runs along it with a thin wedge between them, too narrow for
// a tab over its length; one that leaves the edge at an angle opens at once.
int slit_points(const FlatStrip& merged, std::size_t first_added, double width) {
  // The added points by 3D point (a join adds few), then one pass over the first strip's.
  std::map<std::array<double, 3>, std::vector<int>> added;
  for (std::size_t v = first_added; v < merged.vertices2d.size(); ++v) {
    const Vec3& p = merged.vertices3d[v];
    added[{p.x(), p.y(), p.z()}].push_back(static_cast<int>(v));
  }
  std::vector<char> slit(merged.vertices2d.size(), 0);
  for (std::size_t u = 0; u < first_added && !added.empty(); ++u) {
    const Vec3& p = merged.vertices3d[u];
    auto it = added.find({p.x(), p.y(), p.z()});
    if (it == added.end()) continue;
    for (int v : it->second)
      if ((merged.vertices2d[u] - merged.vertices2d[v]).norm() < width) slit[v] = 1;
  }
  return static_cast<int>(std::count(slit.begin(), slit.end(), 1));
}

// How narrow strips[neighbour] was and `joined` (it with triangles appended, its own in
// place: a union keeps the first strip's frame) is: the shares narrower than `min_width`,
// both on the neighbour's raster (narrow_raster; `rasters` keeps them by index into `strips`,
// once measured). The union differs from the neighbour only within min_width of what it took,
// so only that box is rastered again: the share is exactly the one the whole union has on
// that grid.
std::pair<double, double> shares_before_and_joined(const std::vector<FlatStrip>& strips,
                                                   int neighbour, const FlatStrip& joined,
                                                   double min_width,
                                                   std::map<int, NarrowRaster>& rasters) {
  const FlatStrip& before = strips[neighbour];
  auto it = rasters.find(neighbour);
  if (it == rasters.end())
    it = rasters.emplace(neighbour, narrow_raster(before.vertices2d, before.triangles, min_width))
             .first;
  const NarrowRaster& raster = it->second;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t t = before.triangles.size(); t < joined.triangles.size(); ++t)
    for (int v : joined.triangles[t])
      lo = lo.cwiseMin(joined.vertices2d[v]), hi = hi.cwiseMax(joined.vertices2d[v]);
  if (!(lo.x() <= hi.x())) return {raster.fraction(), raster.fraction()};  // nothing taken
  lo -= Vec2::Constant(min_width), hi += Vec2::Constant(min_width);
  const NarrowRaster was =
      narrow_raster_in_box(before.vertices2d, before.triangles, min_width, lo, hi, raster);
  const NarrowRaster is =
      narrow_raster_in_box(joined.vertices2d, joined.triangles, min_width, lo, hi, raster);
  NarrowRaster result = raster;
  result.inside += is.inside - was.inside;
  result.narrow += is.narrow - was.narrow;
  return {raster.fraction(), result.fraction()};
}

// A band no hinge takes whole (its neighbours' edges bend where it is straight in the plane:
// any hinge lays the rest of it over the neighbour), cut in two across one of its inner edges
// and each half hinged onto a neighbour, the halves folding onto different edges. Cuts are
// tried the most even first (at most 48, evenly spread over the rest), each half's
// shared edges the longest first (at most kMostHinges with each neighbour): a half is kept on a
// hinge that gives a union `keeps_wide` accepts (given the neighbour's index in `strips` and the
// union, which may hold the other half too), of those the one leaving the least slit. Kept only
// when both halves find a place; then the band is erased from `strips` and the neighbours that took
// a half are replaced by the unions, their indices (after the erase) going to `changed`. Where no
// cut places both halves and `cuts_after` > 0, a half that finds a place is kept and the other
// half cut in two again, with one cut fewer after it (a band whose neighbours turn more than once
// along it: into at most options.most_band_pieces, as a wall round a square hole is cut at
// three of its corners into four). Otherwise `strips` is left as it was and false returned.
bool hinge_in_two(std::vector<FlatStrip>& strips, int band, double min_width,
                  const MergeOptions& options,
                  const std::function<bool(int, const FlatStrip&)>& keeps_wide,
                  std::vector<int>& changed, int cuts_after = -1) {
  const int most_cuts_after = std::max(0, options.most_band_pieces - 2);
  const bool whole_band = cuts_after < 0;
  if (whole_band) cuts_after = most_cuts_after;
  const bool in_three = cuts_after > 0;
  // A half cut again tries fewer cuts: see "In three" below.
  const int most_cuts = whole_band ? 48 : 4;
  constexpr int kMostHinges = 12;
  // Checking a half's width rasters a box the size of the half: on a strip of thousands of
  // triangles (a large piece narrow along much of its rim; ChineseDragon's 3,629) the checks
  // took 12 s of its 18 s merge (harness), for the same pieces as without them (6 s). Such a
  // strip is left to the growth.
  constexpr int kMostTriangles = 2048;
  const FlatStrip& strip = strips[band];
  const int count = static_cast<int>(strip.triangles.size());
  if (count < 2 || count > kMostTriangles) return false;
  // The band's neighbours (a boundary edge on its rim), worked on apart from the other strips:
  // trial holds them at 0..n-1, then a half of the band at n.
  const std::vector<int> around = strips_beside(strips, band);
  if (around.empty()) return false;
  const int n = static_cast<int>(around.size());

  // Each edge the band shares with a neighbour, as a hinge of the whole band: its triangle,
  // and the band's triangles that its motion lays over that neighbour. A half folds over it
  // only when it holds the triangle and none of those (the neighbour alone; a half folding
  // onto a neighbour that took the other half is checked in full).
  struct Fold {
    int triangle = -1;
    std::vector<int> over;
  };
  std::map<std::pair<int, std::array<double, 6>>, Fold> folds;  // (neighbour, 3D edge)
  {
    std::vector<FlatStrip> whole;
    for (int s : around) whole.push_back(strips[s]);
    whole.push_back(strip);
    const std::vector<PairCandidate> pairs = shared_boundaries(whole, n);
    const auto hinges = hinges_of(
        pairs, whole, [&](const PairCandidate& pair) { return pair.x < n && pair.y == n; });
    const double band_edge = mean_edge_length(strip);
    std::map<int, TriangleGrid2> grids;
    for (const Hinge& hinge : hinges) {
      const int i = pairs[hinge.pair].x;
      const FlatStrip& neighbour = whole[i];
      const double mean_edge = 0.5 * (mean_edge_length(neighbour) + band_edge);
      auto grid = grids.find(i);
      if (grid == grids.end()) {
        grid = grids.emplace(i, TriangleGrid2(mean_edge > 0.0 ? mean_edge : 1.0)).first;
        for (const Triangle& t : neighbour.triangles)
          grid->second.insert(
              {neighbour.vertices2d[t[0]], neighbour.vertices2d[t[1]], neighbour.vertices2d[t[2]]});
      }
      const Chain& edge = hinge.edge;
      const RigidMotion motion =
          fit({strip.vertices2d[edge.y[0]], strip.vertices2d[edge.y[1]]},
              {neighbour.vertices2d[edge.x[0]], neighbour.vertices2d[edge.x[1]]});
      // Looser than try_merge's bound, which it only screens for.
      const double tolerance = 2.0 * options.overlap_tolerance * mean_edge +
                               8.0 * chain_residual(neighbour, strip, edge, motion);
      Fold fold;
      for (int t = 0; t < count; ++t) {
        const Triangle& tri = strip.triangles[t];
        int on_edge = 0;
        for (int v : tri) on_edge += v == edge.y[0] || v == edge.y[1];
        if (on_edge == 2) fold.triangle = t;
        if (grid->second.overlaps(
                {motion(strip.vertices2d[tri[0]]), motion(strip.vertices2d[tri[1]]),
                 motion(strip.vertices2d[tri[2]])},
                tolerance))
          fold.over.push_back(t);
      }
      const std::array<double, 6> key =
          exact_key(strip.vertices3d[edge.y[0]], strip.vertices3d[edge.y[1]]);
      if (fold.triangle >= 0) folds.emplace(std::make_pair(i, key), std::move(fold));
    }
  }
  if (folds.empty()) return false;

  // The band's inner edges, as the two triangles they join.
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (int t = 0; t < count; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = strip.triangles[t][k], b = strip.triangles[t][(k + 1) % 3];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  std::vector<std::pair<int, int>> inner;
  for (const auto& [edge, ts] : by_edge)
    if (ts.size() == 2) inner.emplace_back(ts[0], ts[1]);
  // A cut leaves exactly two halves where its edge is a bridge of the band's dual graph.
  const DualCuts cuts(count, inner);
  if (!cuts.connected()) return false;  // a band in pieces: every cut leaves more than two
  // Which side of a cut each triangle lies on (true: the first triangle's), or nothing where
  // the band stays one piece (around an inner vertex).
  auto sides = [&](std::size_t cut, std::vector<bool>& first) {
    if (!cuts.splits(cut)) return false;
    first.assign(count, false);
    for (int t = 0; t < count; ++t) first[t] = cuts.on_first_side(cut, t);
    return true;
  };
  // Whether a half may fold over (neighbour, edge): it holds the hinge's triangle and none of
  // the band's triangles the hinge lays over the neighbour.
  auto may_fold = [&](const std::vector<bool>& first, bool side, int neighbour,
                      const std::array<double, 6>& key) {
    auto it = folds.find({neighbour, key});
    if (it == folds.end() || first[it->second.triangle] != side) return false;
    for (int t : it->second.over)
      if (first[t] == side) return false;
    return true;
  };
  auto any_fold = [&](const std::vector<bool>& first, bool side) {
    for (const auto& [where, fold] : folds)
      if (may_fold(first, side, where.first, where.second)) return true;
    return false;
  };
  // Cuts by how evenly they share the band, the most even first; only those where each half
  // has a hinge that may take it.
  // And, for a cut in three, those where one half has such a hinge (the other cut again).
  std::vector<std::pair<int, std::size_t>> order, order_one;  // (imbalance, cut)
  for (std::size_t e = 0; e < inner.size(); ++e) {
    std::vector<bool> first;
    if (!sides(e, first)) continue;
    const bool first_folds = any_fold(first, true), second_folds = any_fold(first, false);
    const int imbalance = std::abs(2 * cuts.first_side_size(e) - count);
    if (first_folds && second_folds) order.emplace_back(imbalance, e);
    if (in_three && (first_folds || second_folds)) order_one.emplace_back(imbalance, e);
  }
  const auto most_even = [&](std::vector<std::pair<int, std::size_t>>& cut_order) {
    std::stable_sort(cut_order.begin(), cut_order.end());
    if (static_cast<int>(cut_order.size()) <= most_cuts) return;
    std::vector<std::pair<int, std::size_t>> spread;
    for (int i = 0; i < most_cuts; ++i)
      spread.push_back(cut_order[i * cut_order.size() / most_cuts]);
    cut_order = std::move(spread);
  };
  most_even(order);
  most_even(order_one);

  // Hinges the half at trial[n] (the `side` of `first`) onto a neighbour in `trial`: the union
  // replaces the neighbour and the half is erased. Returns the slit left, or -1 where no hinge
  // takes it.
  auto place = [&](std::vector<FlatStrip>& trial, std::vector<bool>& took,
                   const std::vector<bool>& first, bool side, bool check_wide) {
    const FlatStrip& half = trial[n];
    const std::vector<PairCandidate> pairs = shared_boundaries(trial, n);
    const auto hinges = hinges_of(
        pairs, trial, [&](const PairCandidate& pair) { return pair.x < n && pair.y == n; });
    // The unions that place it, the least slit first; with `check_wide`, the first of those
    // keeps_wide accepts.
    std::vector<std::pair<int, int>> placed;        // (slit, index into unions)
    std::vector<std::pair<int, FlatStrip>> unions;  // (neighbour in trial, union)
    std::vector<int> tried(n, 0);  // per neighbour: the floor's edges must not use up the
                                   // tries before the ceiling's
    for (const Hinge& hinge : hinges) {
      const PairCandidate& pair = pairs[hinge.pair];
      if (tried[pair.x] == kMostHinges) continue;
      const std::array<double, 6> key =
          exact_key(half.vertices3d[hinge.edge.y[0]], half.vertices3d[hinge.edge.y[1]]);
      if (!may_fold(first, side, pair.x, key)) continue;
      ++tried[pair.x];
      FlatStrip merged;
      if (!try_merge(trial[pair.x], half, {hinge.edge}, options, merged, false)) continue;
      const int slit = slit_points(merged, trial[pair.x].vertices2d.size(), min_width);
      placed.emplace_back(slit, static_cast<int>(unions.size()));
      unions.emplace_back(pair.x, std::move(merged));
    }
    std::stable_sort(placed.begin(), placed.end());
    int best_x = -1, best_slit = 0;
    FlatStrip best;
    for (const auto& [slit, u] : placed) {
      if (check_wide && !keeps_wide(around[unions[u].first], unions[u].second)) continue;
      best_x = unions[u].first, best_slit = slit, best = std::move(unions[u].second);
      break;
    }
    if (best_x < 0) return -1;
    best.boundary = flat_boundary(best.triangles);
    trial[best_x] = std::move(best);
    took[best_x] = true;
    trial.erase(trial.begin() + n);
    return best_slit;
  };
  auto neighbours = [&] {  // a trial's start: the band's neighbours at 0..n-1
    std::vector<FlatStrip> trial;
    for (int s : around) trial.push_back(strips[s]);
    return trial;
  };
  auto half_of = [&](const std::vector<bool>& first, bool side) {
    std::vector<Triangle> chosen;
    for (int t = 0; t < count; ++t)
      if (first[t] == side) chosen.push_back(strip.triangles[t]);
    return sub_strip(strip, chosen);
  };
  std::vector<FlatStrip> kept;
  std::vector<bool> kept_took;
  int kept_slit = -1;
  // Both halves placed at `cut` (the slit they leave), or -1. Measuring width is what costs:
  // it is checked only where both halves find a place without it.
  auto split_at = [&](std::size_t cut, bool check_wide, std::vector<FlatStrip>& trial,
                      std::vector<bool>& took) {
    std::vector<bool> first;
    sides(cut, first);
    trial = neighbours();
    took.assign(n, false);  // the neighbours that took a half
    trial.push_back(half_of(first, true));
    const int slit_first = place(trial, took, first, true, check_wide);
    if (slit_first < 0) return -1;
    trial.push_back(half_of(first, false));
    const int slit_second = place(trial, took, first, false, check_wide);
    return slit_second < 0 ? -1 : slit_first + slit_second;
  };
  // Placing costs little; measuring width is what costs. So the width is checked only where
  // both halves find a place without it and might leave less slit than the split kept (the
  // check only takes choices away), at most kMostChecks times before one passes and
  // kMostBetter times after.
  constexpr int kMostChecks = 32;
  constexpr int kMostBetter = 8;
  int checks = 0, better = 0;
  for (const auto& [imbalance, cut] : order) {
    std::vector<FlatStrip> trial;
    std::vector<bool> took;
    const int unchecked = split_at(cut, false, trial, took);
    if (unchecked < 0 || (kept_slit >= 0 && unchecked >= kept_slit)) continue;
    if (kept_slit < 0 ? ++checks > kMostChecks : ++better > kMostBetter) break;
    const int slit = split_at(cut, true, trial, took);
    if (slit < 0 || (kept_slit >= 0 && slit >= kept_slit)) continue;
    kept = std::move(trial), kept_took = std::move(took), kept_slit = slit;
    if (kept_slit == 0) break;
  }
  // In three, where no cut placed both halves (a band whose neighbours turn twice along it:
  // each half of any cut turns with them somewhere): one half placed, width checked, and the
  // other cut in two again (trying at most 4 cuts, as it is tried for several first halves), and
  // so on while `cuts_after` lasts: the rest of a band whose neighbours turn three times is cut
  // in three again. The cuts where one half may fold, the most even first; at most kMostThirds
  // first halves placed.
  constexpr int kMostThirds = 4;
  int thirds = 0;
  for (auto cut = order_one.begin(); kept_slit < 0 && cut != order_one.end(); ++cut) {
    std::vector<bool> first;
    sides(cut->second, first);
    for (const bool side : {true, false}) {
      std::vector<FlatStrip> trial = neighbours();
      std::vector<bool> took(n, false);
      trial.push_back(half_of(first, side));
      if (place(trial, took, first, side, true) < 0) continue;
      if (++thirds > kMostThirds) break;
      trial.push_back(half_of(first, !side));
      const auto keeps_wide_in_trial = [&](int i, const FlatStrip& joined) {
        return keeps_wide(around[i], joined);
      };
      std::vector<int> took_rest;
      if (!hinge_in_two(trial, n, min_width, options, keeps_wide_in_trial, took_rest,
                        cuts_after - 1))
        continue;
      for (int i : took_rest) took[i] = true;
      kept = std::move(trial), kept_took = std::move(took), kept_slit = 0;
      break;
    }
    if (thirds > kMostThirds) break;
  }
  if (kept_slit < 0) return false;
  changed.clear();
  for (int i = 0; i < n; ++i) {
    if (!kept_took[i]) continue;
    strips[around[i]] = std::move(kept[i]);
    changed.push_back(around[i] > band ? around[i] - 1 : around[i]);
  }
  strips.erase(strips.begin() + band);
  return true;
}

}  // namespace

namespace {

// Strip `s` hinged whole onto a neighbour over one shared edge, where the union overlaps
// nowhere: the union replaces the lower index of the two and the other is erased. Edges are
// tried those at an end of an open shared chain first, then the longest; of the first that
// lays it flat and the kMostWholeHinges tried after it, the one leaving the least slit
// (slit_points at `slit_width`; the earlier on a tie) is kept: a hinge in the middle of a chain
// that does not weld opens a thin wedge on both sides of it, one at its end only on one.
// `slit_width` <= 0: the first that lays it flat. False (strips unchanged) when no hinge lays
// it flat.
bool hinge_whole(std::vector<FlatStrip>& strips, int s, const MergeOptions& options,
                 double slit_width) {
  constexpr int kMostWholeHinges = 16;
  const std::vector<PairCandidate> pairs = shared_boundaries(strips, s);
  auto hinges = hinges_of(pairs, strips,
                          [&](const PairCandidate& pair) { return pair.x == s || pair.y == s; });
  std::stable_partition(hinges.begin(), hinges.end(), [](const Hinge& h) { return h.chain_end; });
  FlatStrip best;
  int best_pair = -1, best_slit = 0, tried = 0;
  for (const Hinge& hinge : hinges) {
    if (best_pair >= 0 && (slit_width <= 0.0 || ++tried > kMostWholeHinges)) break;
    const PairCandidate& pair = pairs[hinge.pair];
    FlatStrip merged;
    if (!try_merge(strips[pair.x], strips[pair.y], {hinge.edge}, options, merged, false)) continue;
    const int slit =
        slit_width > 0.0 ? slit_points(merged, strips[pair.x].vertices2d.size(), slit_width) : 0;
    if (best_pair >= 0 && slit >= best_slit) continue;
    best = std::move(merged), best_pair = hinge.pair, best_slit = slit;
    if (slit == 0) break;
  }
  if (best_pair < 0) return false;
  const PairCandidate& pair = pairs[best_pair];
  best.boundary = flat_boundary(best.triangles);
  strips[pair.x] = std::move(best);
  strips.erase(strips.begin() + pair.y);
  return true;
}

// The index of the smallest strip of less than `bound` whose id is not in `given_up`, or -1.
int smallest_below(const std::vector<FlatStrip>& strips, double bound,
                   const std::set<int>& given_up) {
  int smallest = -1;
  double least = bound;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s) {
    const double area = flat_area(strips[s]);
    if (area < least && !given_up.count(strips[s].id)) smallest = s, least = area;
  }
  return smallest;
}

}  // namespace

std::vector<FlatStrip> drop_double_covered_triangles(std::vector<FlatStrip> strips,
                                                     std::size_t* dropped) {
  validate(strips, {});
  if (dropped) *dropped = 0;
  // Each triangle by its sorted 3D corners; every occurrence after the first is marked.
  std::set<std::array<double, 9>> seen;
  std::vector<std::vector<char>> twice(strips.size());
  bool any = false;
  for (std::size_t s = 0; s < strips.size(); ++s) {
    const FlatStrip& strip = strips[s];
    twice[s].assign(strip.triangles.size(), 0);
    for (std::size_t t = 0; t < strip.triangles.size(); ++t)
      if (!seen.insert(corners_key(strip, strip.triangles[t])).second) twice[s][t] = any = 1;
  }
  if (!any) return strips;
  int next_id = 0;
  for (const FlatStrip& strip : strips) next_id = std::max(next_id, strip.id + 1);
  std::vector<FlatStrip> result;
  result.reserve(strips.size());
  for (std::size_t s = 0; s < strips.size(); ++s) {
    FlatStrip& strip = strips[s];
    const std::size_t count =
        static_cast<std::size_t>(std::count(twice[s].begin(), twice[s].end(), 1));
    if (count == 0) {
      result.push_back(std::move(strip));
      continue;
    }
    std::vector<Triangle> kept;
    std::set<int> touched;  // corners of the triangles dropped
    for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
      if (!twice[s][t])
        kept.push_back(strip.triangles[t]);
      else
        touched.insert(strip.triangles[t].begin(), strip.triangles[t].end());
    }
    if (kept.empty()) {  // printed whole by the strips before it
      if (dropped) *dropped += count;
      continue;
    }
    // What is left, in its pieces joined across edges (a strip the triangles crossed falls
    // apart: each piece is a strip, the largest keeping the id, the others new ids). Kept only
    // where each piece is a surface at every corner the triangles dropped had (no two fans
    // meeting at a point).
    std::map<std::pair<int, int>, std::size_t> edge_of;
    UnionFind pieces(kept.size());
    for (std::size_t t = 0; t < kept.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = kept[t][k], b = kept[t][(k + 1) % 3];
        const auto [it, added] = edge_of.try_emplace({std::min(a, b), std::max(a, b)}, t);
        if (!added) pieces.unite(it->second, t);
      }
    std::map<std::size_t, std::vector<Triangle>> by_piece;
    for (std::size_t t = 0; t < kept.size(); ++t) by_piece[pieces.find(t)].push_back(kept[t]);
    bool surface = true;
    for (const auto& [root, triangles] : by_piece)
      for (int corner : touched) {
        const bool has = std::any_of(triangles.begin(), triangles.end(), [&](const Triangle& t) {
          return std::find(t.begin(), t.end(), corner) != t.end();
        });
        surface = surface && (!has || one_fan(triangles, corner));
      }
    if (!surface) {
      result.push_back(std::move(strip));
      continue;
    }
    std::vector<std::vector<Triangle>> ordered;
    for (auto& [root, triangles] : by_piece) ordered.push_back(std::move(triangles));
    std::stable_sort(ordered.begin(), ordered.end(),
                     [](const auto& x, const auto& y) { return x.size() > y.size(); });
    for (std::size_t k = 0; k < ordered.size(); ++k) {
      result.push_back(sub_strip(strip, ordered[k]));
      if (k > 0) result.back().id = next_id++;
    }
    if (dropped) *dropped += count;
  }
  return result;
}

std::vector<FlatStrip> join_small_strips(std::vector<FlatStrip> strips, double min_area,
                                         const MergeOptions& options, std::vector<int>* left,
                                         double min_width) {
  validate(strips, options);
  if (left) left->clear();
  if (!(min_area > 0.0)) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  std::set<int> given_up;  // ids of small strips no neighbour takes
  while (true) {
    // The smallest strip still to place.
    const int small = smallest_below(strips, min_area, given_up);
    if (small < 0) break;
    // Hinged whole over one of its shared edges, the one leaving the least slit.
    bool joined = hinge_whole(strips, small, options, min_width);
    if (!joined) joined = absorb_by_triangles(strips, small, options);
    if (!joined && min_width > 0.0) {
      // Cut in two, each half hinged onto a neighbour that gets no narrower than it was (or
      // than narrow_join_share).
      std::map<int, NarrowRaster> rasters;
      const auto keeps_wide = [&](int neighbour, const FlatStrip& joined_strip) {
        const auto [was, is] =
            shares_before_and_joined(strips, neighbour, joined_strip, min_width, rasters);
        return is <= std::max(was, options.narrow_join_share);
      };
      std::vector<int> changed;
      joined = hinge_in_two(strips, small, min_width, options, keeps_wide, changed);
    }
    if (!joined)
      joined = grow_from_neighbours(strips, small, GrowUntil::kMinArea, min_area, min_width,
                                    options.narrow_join_share, options);
    // Grown the most compact way it ends narrower than it began (a neighbour's fan gives thin
    // triangles whose tips add narrow area): grown again, taking first what leaves it narrow
    // over the least share.
    if (!joined && min_width > 0.0)
      joined = grow_from_neighbours(strips, small, GrowUntil::kMinArea, min_area, min_width,
                                    options.narrow_join_share, options, true);
    if (!joined) given_up.insert(strips[small].id);
  }
  if (left) left->assign(given_up.begin(), given_up.end());
  label_seams(strips);
  return strips;
}

std::vector<FlatStrip> join_narrow_strips(std::vector<FlatStrip> strips, double min_width,
                                          double narrow_share, const MergeOptions& options,
                                          int most_hinges, double min_area) {
  validate(strips, options);
  if (!(min_width > 0.0) || !(narrow_share >= 0.0) || most_hinges < 1) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  auto share_of = [&](const FlatStrip& strip) {
    return narrow_area_fraction(strip.vertices2d, strip.triangles, min_width);
  };
  std::vector<double> share(strips.size());
  for (std::size_t s = 0; s < strips.size(); ++s) share[s] = share_of(strips[s]);
  std::set<int> given_up;  // ids of narrow strips no neighbour takes
  // A strip given up beside a union is tried again: the union is less narrow than the
  // neighbour it folded onto was, or has new edges for a hinge.
  const auto retry_beside = [&](const FlatStrip& joined) {
    const std::set<std::array<double, 6>> rim = rim_of(joined);
    for (const FlatStrip& strip : strips) {
      if (!given_up.count(strip.id)) continue;
      for (const BoundaryEdge& e : strip.boundary)
        if (rim.count(exact_key(strip.vertices3d[e.v0], strip.vertices3d[e.v1]))) {
          given_up.erase(strip.id);
          break;
        }
    }
  };
  while (true) {
    // The narrowest strip still to place.
    int narrow = -1;
    for (int s = 0; s < static_cast<int>(strips.size()); ++s)
      if (share[s] > narrow_share && !given_up.count(strips[s].id) &&
          (narrow < 0 || share[s] > share[narrow]))
        narrow = s;
    if (narrow < 0) break;
    const std::vector<PairCandidate> pairs = shared_boundaries(strips, narrow);
    const auto hinges = hinges_of(pairs, strips, [&](const PairCandidate& pair) {
      return pair.x == narrow || pair.y == narrow;
    });
    // Of the hinges that give a union less narrow than the strip, and either no narrower than
    // the neighbour was (or than the bound) or narrow over no more area than the two together
    // (a band kept whole beside a wide neighbour: one seam fewer, no tab on the band), the one
    // that leaves the least slit.
    FlatStrip best;
    int best_hinge = -1, best_slit = 0;
    double best_share = 0.0;
    const int tries = std::min(static_cast<int>(hinges.size()), most_hinges);
    for (int h = 0; h < tries; ++h) {
      const PairCandidate& pair = pairs[hinges[h].pair];
      const int other = pair.x == narrow ? pair.y : pair.x;
      FlatStrip merged;
      if (!try_merge(strips[pair.x], strips[pair.y], {hinges[h].edge}, options, merged, false))
        continue;
      const int slit = slit_points(merged, strips[pair.x].vertices2d.size(), min_width);
      if (best_hinge >= 0 && slit >= best_slit) continue;
      const double joined_share = share_of(merged);
      if (!(joined_share < share[narrow])) continue;
      if (joined_share > std::max(share[other], narrow_share) &&
          joined_share * flat_area(merged) >
              share[narrow] * flat_area(strips[narrow]) + share[other] * flat_area(strips[other]))
        continue;
      best = std::move(merged);
      best_hinge = h, best_slit = slit, best_share = joined_share;
      if (slit == 0) break;
    }
    if (best_hinge < 0) {
      // No hinge takes it whole: cut in two, each half hinged onto a neighbour, where the
      // union is less narrow than the strip and no narrower than the neighbour was (or than
      // the bound).
      std::vector<int> changed;
      std::map<int, NarrowRaster> rasters;
      const auto keeps_wide = [&](int neighbour, const FlatStrip& joined) {
        const auto [was, is] =
            shares_before_and_joined(strips, neighbour, joined, min_width, rasters);
        return is < share[narrow] && is <= std::max(was, narrow_share);
      };
      if (hinge_in_two(strips, narrow, min_width, options, keeps_wide, changed)) {
        share.erase(share.begin() + narrow);
        for (int s : changed) share[s] = share_of(strips[s]);
        for (int s : changed) retry_beside(strips[s]);
      } else {
        given_up.insert(strips[narrow].id);
      }
      continue;
    }
    const PairCandidate& pair = pairs[hinges[best_hinge].pair];
    best.boundary = flat_boundary(best.triangles);
    strips[pair.x] = std::move(best);
    share[pair.x] = best_share;
    strips.erase(strips.begin() + pair.y);
    share.erase(share.begin() + pair.y);
    retry_beside(strips[pair.x]);  // x < y: the union kept x's place
  }
  // A strip still narrow grows instead, as a crumb does, until it is no longer narrow (a
  // neighbour it takes from keeps min_area and gets no narrower than it was or than the
  // bound). share[] of a neighbour taken from goes stale but stays an upper bound.
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    if (share[s] > narrow_share)
      grow_from_neighbours(strips, s, GrowUntil::kWide, min_area, min_width, narrow_share, options);
  label_seams(strips);
  return strips;
}

std::vector<FlatStrip> hinge_modest_strips(std::vector<FlatStrip> strips, double below_area,
                                           const MergeOptions& options, double min_width) {
  validate(strips, options);
  if (!(below_area > 0.0)) return strips;
  for (FlatStrip& strip : strips) strip.boundary = flat_boundary(strip.triangles);
  std::set<int> given_up;  // ids of strips no neighbour takes
  while (true) {
    const int modest = smallest_below(strips, below_area, given_up);
    if (modest < 0) break;
    if (!hinge_whole(strips, modest, options, min_width)) given_up.insert(strips[modest].id);
  }
  label_seams(strips);
  return strips;
}

std::vector<FlatStrip> join_small_and_narrow_strips(std::vector<FlatStrip> strips, double min_area,
                                                    double min_width, const MergeOptions& options,
                                                    std::vector<int>* left) {
  std::vector<int> small;
  strips = join_small_strips(std::move(strips), min_area, options, &small, min_width);
  strips = join_narrow_strips(std::move(strips), min_width, options.narrow_join_share, options, 256,
                              min_area);
  if (!small.empty())
    strips = join_small_strips(std::move(strips), min_area, options, &small, min_width);
  if (options.modest_join_factor > 1.0)
    strips = hinge_modest_strips(std::move(strips), options.modest_join_factor * min_area, options,
                                 min_width);
  if (left) {
    // The crumbs left are those of `small` still under min_area (a hinge above may have
    // joined one).
    left->clear();
    for (const FlatStrip& strip : strips)
      if (std::find(small.begin(), small.end(), strip.id) != small.end() &&
          flat_area(strip) < min_area)
        left->push_back(strip.id);
  }
  return strips;
}

}  // namespace papercraft
