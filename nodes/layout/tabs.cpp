// Glue tabs: flaps planned along seam chains, kept clear of their piece, textured across the seam.
#include "nodes/layout/tabs.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <utility>

#include "core/edge_map.h"
#include "nodes/layout/piece_shapes.h"
#include "nodes/layout/polygon_2d.h"

namespace papercraft::layout_internal {
namespace {

struct TabGeometry {
  double width;
  double angle;  // radians
  double min_height;
  double overlap_depth;
};

// The flap of height h along base[0..k] (strip on the left, the flap on the right): the
// mitred offset band cut by the end lines at start_angle and end_angle to the base. Returns
// its convex slices (one per base edge, counter-clockwise in the strip frame) and sets
// `outer` to the flap's outer chain; empty if a slice would be degenerate or not convex.
std::vector<std::vector<Vec2>> flap_slices(const std::vector<Vec2>& base, double h,
                                           double start_angle, double end_angle,
                                           std::vector<Vec2>* outer,
                                           std::vector<int>* slice_edges) {
  slice_edges->clear();
  const std::size_t k = base.size() - 1;
  std::vector<Vec2> d(k), n(k), offset(k + 1);
  for (std::size_t i = 0; i < k; ++i) {
    d[i] = (base[i + 1] - base[i]).normalized();
    n[i] = right_normal(d[i]);
  }
  offset[0] = base[0] + h * n[0];
  offset[k] = base[k] + h * n[k - 1];
  for (std::size_t j = 1; j < k; ++j)
    offset[j] = base[j] + h * (n[j - 1] + n[j]) / (1.0 + n[j - 1].dot(n[j]));
  const Vec2 start_dir = std::cos(start_angle) * d[0] + std::sin(start_angle) * n[0];
  const Vec2 end_dir = -std::cos(end_angle) * d[k - 1] + std::sin(end_angle) * n[k - 1];
  auto after_start = [&](const Vec2& x) { return cross(start_dir, x - base[0]); };
  auto before_end = [&](const Vec2& x) { return -cross(end_dir, x - base[k]); };

  std::vector<std::vector<Vec2>> slices;
  for (std::size_t j = 0; j < k; ++j) {
    const std::vector<Vec2> quad{base[j + 1], base[j], offset[j], offset[j + 1]};
    for (int i = 0; i < 4; ++i) {
      const Vec2 e1 = quad[(i + 1) % 4] - quad[i], e2 = quad[(i + 2) % 4] - quad[(i + 1) % 4];
      if (e1.norm() < 1e-9 || cross(e1, e2) <= 1e-9 * e1.norm() * e2.norm()) return {};
    }
    std::vector<Vec2> slice = clip(clip(quad, after_start), before_end);
    if (slice.size() >= 3 && std::abs(signed_area(slice)) > 1e-12) {
      slices.push_back(slice);
      slice_edges->push_back(static_cast<int>(j));
    }
  }
  std::vector<Vec2> band(base.rbegin(), base.rend());
  band.insert(band.end(), offset.begin(), offset.end());
  std::vector<Vec2> flap = clip(clip(band, after_start), before_end);
  // The base must survive the cut whole; the rest is the outer chain.
  if (flap.size() < k + 2) return {};
  for (std::size_t j = 0; j <= k; ++j)
    if ((flap[j] - base[k - j]).norm() > 1e-9) return {};
  outer->assign(flap.begin() + static_cast<std::ptrdiff_t>(k + 1), flap.end());
  return slices;
}

// The signed turning angle from direction a to direction b.
double turn_between(const Vec2& a, const Vec2& b) {
  return std::atan2(cross(a, b), a.dot(b));
}

// A chain's edges (`edges`, in order; `direction(e)` the flat vector of edge e) cut into the
// runs a flap can fold along: broken at a joint turning over 15 degrees, after 30 degrees of
// turning in all, and at zero-length edges (which belong to no run). A closed chain starts at
// its sharpest joint, so that a run breaks there.
template <class Direction>
std::vector<std::vector<int>> flap_runs(std::vector<int> edges, bool closed,
                                        const Direction& direction) {
  auto turn = [&](int e0, int e1) { return turn_between(direction(e0), direction(e1)); };
  const double max_joint = 15 * kDegree, max_run = 30 * kDegree;
  const int count = static_cast<int>(edges.size());
  if (closed) {
    int best = 0;
    double sharpest = -1;
    for (int i = 0; i < count; ++i) {
      const double t = std::abs(turn(edges[(i + count - 1) % count], edges[i]));
      if (t > sharpest) {
        sharpest = t;
        best = i;
      }
    }
    std::rotate(edges.begin(), edges.begin() + best, edges.end());
  }
  std::vector<std::vector<int>> runs;
  double accumulated = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const bool degenerate = direction(edges[i]).norm() < 1e-9;
    if (degenerate) {
      accumulated = 0;
      if (!runs.empty() && !runs.back().empty()) runs.emplace_back();
      continue;
    }
    if (runs.empty() || runs.back().empty()) {
      if (runs.empty()) runs.emplace_back();
      runs.back().push_back(edges[i]);
      accumulated = 0;
      continue;
    }
    const double t = turn(runs.back().back(), edges[i]);
    accumulated += std::abs(t);
    if (std::abs(t) > max_joint || accumulated > max_run) {
      runs.emplace_back();
      accumulated = 0;
    }
    runs.back().push_back(edges[i]);
  }
  return runs;
}

// Flaps along a chain: one per nearly straight run of edges (a flap cannot fold along a
// bend), each as high as fits up to the tab width, dropped where none fits. With `part`
// (t0, t1), the chain is one edge and its one flap lies on that part of it.
std::vector<FlapPlan> plan_flaps(const StripData& data, const Piece& piece, const Chain& chain,
                                 const TabGeometry& geometry, PieceShapes& shapes,
                                 const std::pair<double, double>* part = nullptr) {
  const std::vector<PieceEdge>& loop = piece.loops[chain.loop];
  const int n = static_cast<int>(loop.size());
  std::vector<int> edges;
  for (int i = 0; i < chain.count; ++i) edges.push_back((chain.start + i) % n);
  auto point = [&](int v) { return data.points[v]; };
  auto direction = [&](int e) { return Vec2(point(loop[e].v1) - point(loop[e].v0)); };
  auto turn = [&](int e0, int e1) { return turn_between(direction(e0), direction(e1)); };
  const std::vector<std::vector<int>> runs = flap_runs(edges, chain.closed, direction);
  std::vector<FlapPlan> plans;
  const int run_count = static_cast<int>(runs.size());
  for (int r = 0; r < run_count; ++r) {
    const std::vector<int>& run = runs[r];
    if (run.empty()) continue;
    // At a joint to a neighbouring run the flaps' ends must not cross: the tab side of
    // the joint is 180 degrees less a right turn, shared by both flaps.
    // Where the boundary turns right (into the tab's side) at an end of the flap, the flap
    // keeps to its half of the corner: the tab side of the corner is 180 degrees less the
    // turn, shared with the neighbouring flap or edge (a cone's apex leaves a narrow gap).
    auto end_angle = [&](bool at_start, double base_angle) {
      double angle = base_angle;
      const bool chain_end =
          at_start ? (r == 0 && !chain.closed) : (r == run_count - 1 && !chain.closed);
      double t = 0;
      if (chain_end) {
        const int neighbour = at_start ? (run.front() + n - 1) % n : (run.back() + 1) % n;
        if (direction(neighbour).norm() < 1e-9) return angle;
        t = at_start ? turn(neighbour, run.front()) : turn(run.back(), neighbour);
      } else {
        const int neighbour_run = at_start ? (r + run_count - 1) % run_count : (r + 1) % run_count;
        if (runs[neighbour_run].empty()) return angle;
        t = at_start ? turn(runs[neighbour_run].back(), run.front())
                     : turn(run.back(), runs[neighbour_run].front());
      }
      if (t < 0) angle = std::min(angle, 0.5 * (std::numbers::pi + t) - 0.5 * kDegree);
      return angle;
    };
    FlapPlan plan;
    plan.edges = run;
    plan.base.push_back(point(loop[run.front()].v0));
    double length = 0;
    for (int e : run) {
      plan.base.push_back(point(loop[e].v1));
      length += direction(e).norm();
    }
    // The tallest flap (up to the tab width, down to the smallest height) on `base` with
    // ends at these angles that covers nothing; false if none does.
    auto try_base = [&](const std::vector<Vec2>& base, double along, double start_angle,
                        double stop_angle) {
      const double chord = (base.back() - base.front()).norm();
      const double h0 =
          std::min(geometry.width, 0.9 * std::min(along, chord) /
                                       (1 / std::tan(start_angle) + 1 / std::tan(stop_angle)));
      for (double factor : {1.0, 0.7, 0.5, 0.35}) {
        const double h = h0 * factor;
        if (h < geometry.min_height) break;
        std::vector<Vec2> outer;
        std::vector<int> slice_edges;
        auto slices = flap_slices(base, h, start_angle, stop_angle, &outer, &slice_edges);
        if (slices.empty() || slices_collide(slices, shapes, geometry.overlap_depth)) continue;
        plan.base = base;
        plan.outer = std::move(outer);
        plan.slices = std::move(slices);
        plan.slice_edges = std::move(slice_edges);
        return true;
      }
      return false;
    };
    if (part) {
      const Vec2 a = plan.base.front(), b = plan.base.back();
      const auto [t0, t1] = *part;
      for (const double base_angle : {geometry.angle, 60 * kDegree, 75 * kDegree}) {
        if (base_angle < geometry.angle || !plan.slices.empty()) continue;
        const double start_angle = t0 > 0 ? base_angle : end_angle(true, base_angle);
        const double stop_angle = t1 < 1 ? base_angle : end_angle(false, base_angle);
        if (start_angle <= 2 * kDegree || stop_angle <= 2 * kDegree) break;
        try_base({a + t0 * (b - a), a + t1 * (b - a)}, (t1 - t0) * length, start_angle, stop_angle);
      }
    }
    // The configured angle first; a seam too short for a flap of the smallest height at that
    // angle gets steeper ends (a taller flap on the same base).
    for (const double base_angle : {geometry.angle, 60 * kDegree, 75 * kDegree}) {
      if (part) break;
      if (base_angle < geometry.angle || !plan.slices.empty()) continue;
      const double start_angle = end_angle(true, base_angle);
      const double stop_angle = end_angle(false, base_angle);
      if (start_angle <= 2 * kDegree || stop_angle <= 2 * kDegree) break;
      try_base(plan.base, length, start_angle, stop_angle);
    }
    // A single edge with no room along its whole length (one side of a narrow V, a seam
    // running into a notch) takes a flap on part of it: the halves, then quarters, each end
    // first (where a V opens), the flap's own ends at the configured angle away from corners.
    if (!part && plan.slices.empty() && run.size() == 1 && length >= 4 * geometry.min_height) {
      const Vec2 a = plan.base.front(), b = plan.base.back();
      for (const auto& [t0, t1] : std::initializer_list<std::pair<double, double>>{
               {0.5, 1.0}, {0.0, 0.5}, {0.75, 1.0}, {0.0, 0.25}, {0.25, 0.75}}) {
        const double start_angle = t0 > 0 ? geometry.angle : end_angle(true, geometry.angle);
        const double stop_angle = t1 < 1 ? geometry.angle : end_angle(false, geometry.angle);
        if (start_angle <= 2 * kDegree || stop_angle <= 2 * kDegree) continue;
        if (try_base({a + t0 * (b - a), a + t1 * (b - a)}, (t1 - t0) * length, start_angle,
                     stop_angle))
          break;
      }
    }
    if (plan.slices.empty()) continue;
    for (const auto& slice : plan.slices) {
      Box2 box;
      for (const Vec2& c : slice) box.add(c);
      shapes.slices.push_back(slice);
      shapes.slice_boxes.push_back(box);
    }
    plans.push_back(std::move(plan));
  }
  return plans;
}

void commit_flaps(Piece& piece, const Chain& chain, const std::string& printed,
                  std::vector<FlapPlan>& plans,
                  const std::function<std::optional<TexturePatch>(int)>& edge_texture) {
  PieceTab tab;
  tab.label = printed;
  const int tab_index = static_cast<int>(piece.tabs.size());
  for (FlapPlan& plan : plans) {
    const int flap_index = static_cast<int>(piece.flaps.size());
    Flap flap{plan.base, plan.outer, tab_index, {}};
    for (std::size_t k = 0; k < plan.slices.size(); ++k)
      if (auto patch = edge_texture(plan.edges[plan.slice_edges[k]])) {
        patch->clip = plan.slices[k];
        flap.texture.push_back(std::move(*patch));
      }
    piece.flaps.push_back(std::move(flap));
    tab.flaps.push_back(flap_index);
    if (plan.edges.size() == 1) {
      // Kept in order along the edge (the bases of its flaps all run along it).
      std::vector<int>& on_edge = piece.loops[chain.loop][plan.edges[0]].edge_flaps;
      const Vec2 along = plan.base.back() - plan.base.front();
      auto at = [&](int f) { return along.dot(piece.flaps[f].base.front()); };
      on_edge.insert(std::upper_bound(on_edge.begin(), on_edge.end(), flap_index,
                                      [&](int a, int b) { return at(a) < at(b); }),
                     flap_index);
      continue;
    }
    for (std::size_t i = 0; i < plan.edges.size(); ++i) {
      PieceEdge& edge = piece.loops[chain.loop][plan.edges[i]];
      edge.flap = flap_index;
      edge.flap_first = (i == 0);
    }
  }
  piece.tabs.push_back(std::move(tab));
}

// The texture for a tab along loop edge `edge` of `piece`'s loop `loop`, the tab lying on
// the edge's right. A tab is glued under the neighbouring piece, so it shows what continues
// there: the partner triangle across the seam, unfolded onto the tab's side (its own uvs,
// which also carries the texture across a uv seam of the atlas). Without a partner (or
// partner uvs), the piece's own triangle at the edge, its affine map extended.
std::optional<TexturePatch> tab_texture(const std::vector<Piece>& pieces,
                                        const std::vector<StripData>& strips,
                                        const SeamEdges& seams, int piece_index, int loop,
                                        int edge) {
  const Piece& piece = pieces[piece_index];
  const StripData& data = strips[piece.strip];
  const PieceEdge& e = piece.loops[loop][edge];
  const Vec2 a = data.points[e.v0], b = data.points[e.v1];
  auto third = [](const FlatStrip& strip, int t, int u, int v) {
    for (int w : strip.triangles[t])
      if (w != u && w != v) return w;
    return -1;
  };
  const int id = seams.id[piece_index][loop][edge];
  const int partner = id >= 0 ? seams.partner[id] : -1;
  if (partner >= 0) {
    const auto [p2, l2, i2] = seams.refs[partner];
    const StripData& other = strips[pieces[p2].strip];
    const PieceEdge& f = pieces[p2].loops[l2][i2];
    const FlatStrip& strip2 = *other.strip;
    auto owner = other.owner.find(directed_edge_key(f.v0, f.v1));
    if (owner != other.owner.end()) {
      const int d = third(strip2, owner->second, f.v0, f.v1);
      const Vec2 p0 = other.points[f.v0], p1 = other.points[f.v1], q = other.points[d];
      const double length = (p1 - p0).norm(), own_length = (a - b).norm();
      if (d >= 0 && length > 0 && own_length > 0) {
        // f runs v0 -> v1 glued to this edge's v1 -> v0: the same frame along (b -> a).
        const Vec2 along = (p1 - p0) / length, own_along = (a - b) / own_length;
        const double s = (q - p0).dot(along), t = cross(along, q - p0);
        const Vec2 unfolded = b + s * own_along + t * Vec2(-own_along.y(), own_along.x());
        TexturePatch patch{{b, a, unfolded}, {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()}, {}};
        if (!strip2.uvs.empty()) patch.uvs = {strip2.uvs[f.v0], strip2.uvs[f.v1], strip2.uvs[d]};
        patch.points3d = {strip2.vertices3d[f.v0], strip2.vertices3d[f.v1], strip2.vertices3d[d]};
        return patch;
      }
    }
  }
  const FlatStrip& strip = *data.strip;
  auto owner = data.owner.find(directed_edge_key(e.v0, e.v1));
  if (owner == data.owner.end()) return std::nullopt;
  const int c = third(strip, owner->second, e.v0, e.v1);
  if (c < 0) return std::nullopt;
  TexturePatch patch{{a, b, data.points[c]}, {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()}, {}};
  if (!strip.uvs.empty()) patch.uvs = {strip.uvs[e.v0], strip.uvs[e.v1], strip.uvs[c]};
  patch.points3d = {strip.vertices3d[e.v0], strip.vertices3d[e.v1], strip.vertices3d[c]};
  return patch;
}

}  // namespace

TabPlanner::TabPlanner(std::vector<Piece>& pieces, const std::vector<StripData>& strips,
                       const SeamEdges& seams, const LayoutOptions& options)
    : pieces_(pieces),
      strips_(strips),
      seams_(seams),
      width_(options.tab_width_mm),
      angle_(options.tab_angle_degrees * kDegree),
      min_height_(std::min(1.0, 0.2 * options.tab_width_mm)),
      overlap_depth_(1e-6),
      shapes_(pieces.size()) {}

PieceShapes& TabPlanner::shapes_of(int piece) {
  if (!shapes_[piece]) shapes_[piece] = piece_shapes(strips_[pieces_[piece].strip], pieces_[piece]);
  return *shapes_[piece];
}

std::vector<FlapPlan> TabPlanner::plan(const Chain& chain) {
  const TabGeometry geometry{width_, angle_, min_height_, overlap_depth_};
  const Piece& piece = pieces_[chain.piece];
  const StripData& data = strips_[piece.strip];
  PieceShapes& shapes = shapes_of(chain.piece);
  const std::size_t before = shapes.slices.size();
  std::vector<FlapPlan> plans = plan_flaps(data, piece, chain, geometry, shapes);
  // Where a run of the chain takes none, flaps on each of its edges alone (several small
  // tabs along a curved or crowded seam).
  const int n = static_cast<int>(piece.loops[chain.loop].size());
  std::vector<char> covered(n, 0);
  for (const FlapPlan& p : plans)
    for (int e : p.edges) covered[e] = 1;
  for (int i = 0; i < chain.count; ++i) {
    const int e = (chain.start + i) % n;
    if (covered[e]) continue;
    Chain single = chain;
    single.start = e;
    single.count = 1;
    single.closed = false;
    for (FlapPlan& p : plan_flaps(data, piece, single, geometry, shapes)) {
      for (int f : p.edges) covered[f] = 1;
      plans.push_back(std::move(p));
    }
  }
  shapes.slices.resize(before);
  shapes.slice_boxes.resize(before);
  return plans;
}

std::vector<FlapPlan> TabPlanner::plan_part(const Chain& edge, double t0, double t1) {
  const TabGeometry geometry{width_, angle_, min_height_, overlap_depth_};
  const Piece& piece = pieces_[edge.piece];
  PieceShapes& shapes = shapes_of(edge.piece);
  const std::size_t before = shapes.slices.size();
  Chain single = edge;
  single.count = 1;
  single.closed = false;
  const std::pair<double, double> part{t0, t1};
  std::vector<FlapPlan> plans =
      plan_flaps(strips_[piece.strip], piece, single, geometry, shapes, &part);
  shapes.slices.resize(before);
  shapes.slice_boxes.resize(before);
  return plans;
}

void TabPlanner::reserve(const Chain& chain, const std::vector<FlapPlan>& plans) {
  PieceShapes& shapes = shapes_of(chain.piece);
  for (const FlapPlan& plan : plans)
    for (const auto& slice : plan.slices) {
      Box2 box;
      for (const Vec2& c : slice) box.add(c);
      shapes.slices.push_back(slice);
      shapes.slice_boxes.push_back(box);
    }
}

void TabPlanner::commit(const Chain& chain, std::vector<FlapPlan>& plans,
                        const std::string& label) {
  commit_flaps(pieces_[chain.piece], chain, label, plans, [&](int edge) {
    return tab_texture(pieces_, strips_, seams_, chain.piece, chain.loop, edge);
  });
}

std::vector<Chain> TabPlanner::partner_parts(const Chain& from, const std::vector<char>& along_from,
                                             const Chain& to) const {
  const int n = static_cast<int>(pieces_[from.piece].loops[from.loop].size());
  const int m = static_cast<int>(pieces_[to.piece].loops[to.loop].size());
  std::vector<char> wanted(m, 0);
  for (int i = 0; i < from.count; ++i) {
    if (!along_from[i]) continue;
    const int e = (from.start + i) % n;
    const int id = seams_.id[from.piece][from.loop][e];
    const int partner = id >= 0 ? seams_.partner[id] : -1;
    if (partner < 0) continue;
    const auto& ref = seams_.refs[partner];
    if (ref[0] == to.piece && ref[1] == to.loop) wanted[ref[2]] = 1;
  }
  std::vector<Chain> parts;
  for (int i = 0; i < to.count; ++i) {
    const int e = (to.start + i) % m;
    const int before = (to.start + i + m - 1) % m;
    if (!wanted[e] || (i > 0 && wanted[before])) continue;
    int count = 1;
    while (i + count < to.count && wanted[(to.start + i + count) % m]) ++count;
    Chain part = to;
    part.start = e;
    part.count = count;
    part.closed = false;
    parts.push_back(part);
  }
  return parts;
}

std::vector<char> covered_positions(const Chain& chain, const Piece& piece,
                                    const std::vector<FlapPlan>& plans) {
  const int n = static_cast<int>(piece.loops[chain.loop].size());
  std::vector<char> covered(n, 0), along(chain.count, 0);
  for (const FlapPlan& p : plans)
    for (int e : p.edges) covered[e] = 1;
  for (int i = 0; i < chain.count; ++i) along[i] = covered[(chain.start + i) % n];
  return along;
}

}  // namespace papercraft::layout_internal
