#include "core/piece_effort.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "core/flat_boundary.h"
#include "core/seams.h"

namespace papercraft {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The trapezoid `height` high on the segment a -> b (the piece on its left), its ends at 75
// degrees, pushed `shift` further out, as two triangles; false where it overlaps `piece`.
bool trapezoid_clear(const Vec2& a, const Vec2& b, double shift, TriangleGrid2& piece,
                     double height) {
  const double length = (b - a).norm();
  const double inset = height / std::tan(75.0 * kDegree);
  if (!(0.9 * length >= 2.0 * inset)) return false;
  const Vec2 d = (b - a) / length;
  const Vec2 n(d.y(), -d.x());  // the right normal: away from the piece
  const Vec2 a0 = a + shift * n, b0 = b + shift * n;
  const Vec2 a1 = a0 + height * n + inset * d, b1 = b0 + height * n - inset * d;
  constexpr double kTolerance = 1e-6;  // mm: a flap touching the piece along its base is clear
  return !piece.overlaps({a0, b0, b1}, kTolerance) && !piece.overlaps({a0, b1, a1}, kTolerance);
}

// Whether the run points[first..last] has room for a flap: on its chord, pushed past its bulge.
bool run_has_room(const std::vector<Vec2>& points, std::size_t first, std::size_t last,
                  TriangleGrid2& piece, double height) {
  const Vec2 a = points[first], b = points[last];
  const double length = (b - a).norm();
  if (length <= 0.0) return false;
  const Vec2 d = (b - a) / length;
  const Vec2 n(d.y(), -d.x());
  double shift = 0.0;
  for (std::size_t i = first + 1; i < last; ++i) shift = std::max(shift, (points[i] - a).dot(n));
  if (trapezoid_clear(a, b, shift, piece, height)) return true;
  // One long edge with no room along all of it (one side of a narrow V) may have some on part.
  if (last != first + 1 || length < 4.0 * height) return false;
  constexpr std::pair<double, double> kParts[] = {
      {0.5, 1.0}, {0.0, 0.5}, {0.75, 1.0}, {0.0, 0.25}, {0.25, 0.75}};
  for (const auto& [t0, t1] : kParts)
    if (trapezoid_clear(a + t0 * (b - a), a + t1 * (b - a), 0.0, piece, height)) return true;
  return false;
}

// The strip's boundary loops (flat_boundary chains each loop's edges in order), as points.
std::vector<std::vector<Vec2>> outline_loops(const FlatStrip& strip, double scale) {
  std::vector<std::vector<Vec2>> loops;
  for (std::size_t e = 0; e < strip.boundary.size(); ++e) {
    const BoundaryEdge& edge = strip.boundary[e];
    if (e == 0 || strip.boundary[e - 1].v1 != edge.v0) loops.emplace_back();
    loops.back().push_back(scale * strip.vertices2d[edge.v0]);
  }
  return loops;
}

std::unique_ptr<TriangleGrid2> grid_in_mm(const FlatStrip& strip, double scale) {
  double sum = 0.0;
  for (const Triangle& t : strip.triangles)
    for (int k = 0; k < 3; ++k)
      sum += (strip.vertices2d[t[(k + 1) % 3]] - strip.vertices2d[t[k]]).norm();
  const double mean = strip.triangles.empty() ? 0.0 : scale * sum / (3.0 * strip.triangles.size());
  auto grid = std::make_unique<TriangleGrid2>(mean > 0.0 && std::isfinite(mean) ? mean : 1.0);
  for (const Triangle& t : strip.triangles)
    grid->insert({scale * strip.vertices2d[t[0]], scale * strip.vertices2d[t[1]],
                  scale * strip.vertices2d[t[2]]});
  return grid;
}

}  // namespace

bool flap_fits(const std::vector<Vec2>& side, TriangleGrid2& piece, double height) {
  if (side.size() < 2 || !(height > 0.0)) return false;
  // Runs as the layout cuts them: at a joint turning over 15 degrees, after 30 degrees of turning
  // in all, and at zero-length edges.
  const double max_joint = 15.0 * kDegree, max_run = 30.0 * kDegree;
  std::size_t first = 0;
  double turned = 0.0;
  for (std::size_t i = 1; i < side.size(); ++i) {
    const Vec2 out = side[i] - side[i - 1];
    bool breaks = out.norm() <= 1e-9;
    if (!breaks && i > first + 1) {
      const Vec2 in = side[i - 1] - side[i - 2];
      const double turn = std::atan2(cross2(in, out), in.dot(out));
      turned += std::abs(turn);
      breaks = std::abs(turn) > max_joint || turned > max_run;
    }
    if (breaks) {
      if (i - 1 > first && run_has_room(side, first, i - 1, piece, height)) return true;
      first = out.norm() <= 1e-9 ? i : i - 1;
      turned = 0.0;
    }
  }
  return side.size() - 1 > first && run_has_room(side, first, side.size() - 1, piece, height);
}

EffortTerms local_effort_terms(const std::vector<FlatStrip>& strips, const std::vector<int>& set,
                               const PieceEffortOptions& options) {
  const double scale = options.mm_per_unit;
  EffortTerms terms;
  std::map<int, int> index_of_id;
  for (int s = 0; s < static_cast<int>(strips.size()); ++s)
    if (!index_of_id.emplace(strips[s].id, s).second)
      throw InvalidInputException("local_effort: two strips have id " + std::to_string(strips[s].id));
  std::vector<char> in_set(strips.size(), 0);
  for (int s : set) in_set[s] = 1;
  std::map<int, std::unique_ptr<TriangleGrid2>> grids;
  const auto grid_of = [&](int s) -> TriangleGrid2& {
    auto& grid = grids[s];
    if (!grid) grid = grid_in_mm(strips[s], scale);
    return *grid;
  };
  for (const SeamChain& chain : labelled_chains(strips)) {
    int index[2] = {-1, -1};
    for (int k = 0; k < 2; ++k) {
      const auto it = index_of_id.find(chain.sides[k].strip);
      if (it != index_of_id.end() && !chain.sides[k].edges.empty()) index[k] = it->second;
    }
    if (!((index[0] >= 0 && in_set[index[0]]) || (index[1] >= 0 && in_set[index[1]]))) continue;
    ++terms.seam_chains;
    if (index[0] == index[1]) ++terms.self_seams;
    bool room = false;
    double length = 0.0;
    for (int k = 0; k < 2 && !room; ++k) {
      if (index[k] < 0) continue;
      const FlatStrip& strip = strips[index[k]];
      std::vector<Vec2> side;
      side.push_back(scale * strip.vertices2d[strip.boundary[chain.sides[k].edges.front()].v0]);
      for (int e : chain.sides[k].edges) side.push_back(scale * strip.vertices2d[strip.boundary[e].v1]);
      if (length == 0.0)
        for (std::size_t i = 1; i < side.size(); ++i) length += (side[i] - side[i - 1]).norm();
      room = flap_fits(side, grid_of(index[k]), options.flap_height_mm);
    }
    terms.glue_length_mm += length;
    if (!room) ++terms.joining_strips;
  }
  for (int s : set) {
    const FlatStrip& strip = strips[s];
    ++terms.printed_pieces;
    for (const auto& loop : outline_loops(strip, scale))
      terms.sawtooth_corners += count_sawtooth_corners(loop);
    if (options.min_area_mm2 > 0.0 && flat_area(strip) * scale * scale < options.min_area_mm2)
      ++terms.small_pieces;
  }
  terms.things_to_cut = terms.printed_pieces + terms.joining_strips;
  return terms;
}

double local_effort(const std::vector<FlatStrip>& strips, const std::vector<int>& set,
                    const PieceEffortOptions& options) {
  return effort_total(local_effort_terms(strips, set, options), options.weights);
}

}  // namespace papercraft
