#include "core/effort.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "core/piece_width.h"

namespace papercraft {

std::string EffortWeights::invalid() const {
  const std::pair<const char*, double> all[] = {{"piece", piece},
                                                {"seam", seam},
                                                {"glue_per_metre", glue_per_metre},
                                                {"sawtooth", sawtooth},
                                                {"small_piece", small_piece},
                                                {"narrow_piece", narrow_piece}};
  for (const auto& [name, value] : all)
    if (!std::isfinite(value) || value < 0.0) return name;
  return "";
}

double effort_total(const EffortTerms& t, const EffortWeights& w) {
  return w.piece * t.things_to_cut + w.seam * t.seam_chains +
         w.glue_per_metre * t.glue_length_mm / 1000.0 + w.sawtooth * t.sawtooth_corners +
         w.small_piece * t.small_pieces + w.narrow_piece * t.narrow_pieces;
}

std::vector<int> sawtooth_corners(const std::vector<Vec2>& loop, double turn_degrees,
                                  double reach_mm) {
  std::vector<Vec2> points;
  std::vector<int> index;  // of each point kept, in `loop`
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (!points.empty() && (loop[i] - points.back()).norm() <= 1e-9) {
      index.back() = static_cast<int>(i);
      continue;
    }
    points.push_back(loop[i]);
    index.push_back(static_cast<int>(i));
  }
  while (points.size() > 1 && (points.front() - points.back()).norm() <= 1e-9) {
    points.pop_back();
    index.pop_back();
  }
  const std::size_t n = points.size();
  if (n < 3) return {};
  // turn[i]: signed turn at point i (radians, counter-clockwise positive); along[i]: the
  // outline's length from point 0 to point i.
  std::vector<double> turn(n), along(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 in = points[i] - points[(i + n - 1) % n];
    const Vec2 out = points[(i + 1) % n] - points[i];
    turn[i] = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
    along[i + 1] = along[i] + out.norm();
  }
  const double perimeter = along[n];
  const double sharp = turn_degrees * std::numbers::pi / 180.0;
  std::vector<char> marked(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::abs(turn[i]) <= sharp) continue;
    // Forward from i, while within reach (pairs are found from their first corner).
    for (std::size_t k = 1; k < n; ++k) {
      const std::size_t j = (i + k) % n;
      double distance = along[j] - along[i];
      if (distance < 0) distance += perimeter;
      if (distance > reach_mm) break;
      if (std::abs(turn[j]) > sharp && (turn[j] > 0) != (turn[i] > 0)) {
        marked[i] = marked[j] = 1;
      }
    }
  }
  std::vector<int> corners;
  for (std::size_t i = 0; i < n; ++i)
    if (marked[i]) corners.push_back(index[i]);
  return corners;
}

int count_sawtooth_corners(const std::vector<Vec2>& loop, double turn_degrees, double reach_mm) {
  return static_cast<int>(sawtooth_corners(loop, turn_degrees, reach_mm).size());
}

namespace {

double piece_area_mm2(const PlacedPiece& piece) {
  double area = 0.0;
  for (const Triangle& t : piece.triangles) {
    const Vec2 a = piece.vertices[t[1]] - piece.vertices[t[0]];
    const Vec2 b = piece.vertices[t[2]] - piece.vertices[t[0]];
    area += 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
  }
  return area;
}

}  // namespace

AssemblyEffort assembly_effort(const PatternLayout& layout, const EffortLimits& limits,
                               const EffortWeights& weights) {
  AssemblyEffort effort;
  effort.weights = weights;
  EffortTerms& t = effort.terms;
  // Per printed seam label: the length of its edges over every side, and its sides.
  std::map<std::string, std::pair<double, int>> seams;
  std::set<std::string> self;
  for (const Page& page : layout.pages) {
    t.joining_strips += static_cast<int>(page.joints.size());
    for (const PlacedPiece& piece : page.pieces) {
      ++t.printed_pieces;
      for (const PieceSeam& seam : piece.seams) {
        ++seams[seam.label].second;
        if (seam.partner == piece.name) self.insert(seam.label);
      }
      for (const PlacedEdge& edge : piece.edges)
        if (edge.kind == EdgeKind::Seam && !edge.label.empty())
          seams[edge.label].first += (edge.b - edge.a).norm();
      for (const auto& loop : piece.outline) t.sawtooth_corners += count_sawtooth_corners(loop);
      if (limits.min_area_mm2 > 0.0 && piece_area_mm2(piece) < limits.min_area_mm2)
        ++t.small_pieces;
      if (limits.min_width_mm > 0.0 && !piece.triangles.empty() &&
          narrow_area_fraction(piece.vertices, piece.triangles, limits.min_width_mm) >
              limits.max_narrow_share)
        ++t.narrow_pieces;
    }
  }
  t.things_to_cut = t.printed_pieces + t.joining_strips;
  t.self_seams = static_cast<int>(self.size());
  for (const auto& [label, length_sides] : seams) {
    if (length_sides.second == 0) continue;  // an edge label no piece lists (none expected)
    ++t.seam_chains;
    t.glue_length_mm += length_sides.first / length_sides.second;
  }
  effort.total = effort_total(t, weights);
  return effort;
}

}  // namespace papercraft
