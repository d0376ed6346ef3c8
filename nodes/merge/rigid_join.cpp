// Joining two flat strips along shared chains: a rigid fit, an overlap test on a grid and a
// weld that keeps the union a consistently oriented manifold.
#include "nodes/merge/rigid_join.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <utility>

#include "core/flat_boundary.h"
#include "core/overlap_2d.h"

namespace papercraft::merge_detail {
namespace {

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

}  // namespace

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

bool try_merge(const FlatStrip& x, const FlatStrip& y, std::vector<Chain> chains,
               const MergeOptions& options, FlatStrip& merged, bool with_boundary) {
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

}  // namespace papercraft::merge_detail
