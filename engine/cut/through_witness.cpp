#include "engine/cut/through_witness.h"

#include <algorithm>
#include <limits>

#include "core/graph_distance.h"

namespace papercraft {

namespace {

// Accepts a cut if it splits the part into pieces none of which is a sliver, and if the
// iso-line crosses the part rather than running along nearly every triangle (which is what
// an iso-line does lengthwise through a band one triangle wide: the pieces would be the
// same band, thinner, with more triangles, and the refinement would never end).
bool makes_progress(const Mesh& part, const std::vector<Mesh>& pieces, double area,
                    double min_fraction) {
  if (pieces.size() < 2) return false;
  std::size_t faces = 0;
  for (const Mesh& p : pieces) faces += p.n_faces();
  if (faces > part.n_faces() + part.n_faces() / 2 + 16) return false;
  for (const Mesh& p : pieces) {
    const double piece_area = surface_area(p);
    if (piece_area < min_fraction * area || !(piece_area > 0.0)) return false;
  }
  return true;
}

double median(const Eigen::VectorXd& field) {
  std::vector<double> values(field.data(), field.data() + field.size());
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace

double piece_shortfall_ahead(const Mesh& piece, const PieceLimits& limits,
                             const OneStrip& one_strip) {
  const double shortfall = piece_shortfall(piece, limits);
  const double least = limits.min_area;
  if (!one_strip || !(least > 0.0)) return shortfall;
  const double area = surface_area(piece);
  if (area < least || area >= 2.0 * least || shortfall >= 1.0) return shortfall;
  // Too small to be cut in two pieces that both reach min_area: it must be one strip, and
  // that strip must reach min_area on paper.
  const std::optional<double> paper = one_strip(piece);
  if (!paper) return std::max(shortfall, 1.0 - area / (2.0 * least));
  return std::max(shortfall, 1.0 - std::min(*paper, least) / least);
}

double cut_shortfall(const std::vector<Mesh>& pieces, const PieceLimits& limits,
                     const OneStrip& one_strip) {
  double worst = 0.0;
  for (const Mesh& piece : pieces)
    worst = std::max(worst, piece_shortfall_ahead(piece, limits, one_strip));
  return worst;
}

WitnessCut cut_through_witness(const Mesh& part, const std::vector<int>& first,
                               const std::vector<int>& second, const Vec3& witness,
                               const WitnessCutOptions& options, const OneStrip& one_strip) {
  const double area = surface_area(part);
  const double lo = options.margin, hi = 1.0 - options.margin;
  // A fan whose apex lies on its own base loop has no field between its boundaries.
  std::vector<char> in_first(part.n_vertices(), 0);
  for (int v : first) in_first[v] = 1;
  const bool disjoint =
      std::none_of(second.begin(), second.end(), [&](int v) { return in_first[v] != 0; });
  Eigen::VectorXd f;
  if (disjoint) f = harmonic_field(part, first, second, options.harmonic);
  const double f_witness = disjoint ? field_value_at(part, f, witness) : -1.0;
  // The field across the part (between its farthest vertices) costs a sweep and a second
  // solve: it is computed only when the cuts along f do not split the part.
  bool across_ready = false;
  Eigen::VectorXd g;
  auto across = [&]() -> const Eigen::VectorXd* {
    if (!across_ready) {
      across_ready = true;
      const auto [from, to] = farthest_vertex_pair(part, 4);
      if (from != to) g = harmonic_field(part, {from}, {to}, options.harmonic);
    }
    return g.size() > 0 ? &g : nullptr;
  };
  struct Attempt {
    bool across;
    bool at_witness;  // else at 0.5, or for g without f at its median
  };
  // In order: f through the witness (when it lies inside the margins), g through the
  // witness, f at 0.5, g at 0.5.
  // Without f (a fan whose apex lies on its base loop: typically a band one triangle wide,
  // every vertex on its one boundary loop) the worst point is usually on the fan, far from
  // the part, and a cut through it only shaves a tip off the band, again and again. g, fixed
  // at two single vertices, is close to 0.5 nearly everywhere, so 0.5 shaves a tip too:
  // halve the band at the median of g over the vertices instead.
  std::vector<Attempt> attempts;
  if (f_witness >= lo && f_witness <= hi) attempts.push_back({false, true});
  if (disjoint) {
    attempts.push_back({true, true});
    attempts.push_back({false, false});
    attempts.push_back({true, false});
  } else {
    attempts.push_back({true, false});
    attempts.push_back({true, true});
  }
  // Slivers are refused first; on a small part where nothing else splits, any split is
  // still progress. With limits, a cut that makes progress but leaves a piece too narrow or
  // too small is remembered, and the nearest iso-values of its field are tried first.
  // When no cut meets them, the paper's cut (the first that makes progress) stands, unless
  // another falls far less short: a part thinner than the bound everywhere (a thin tube)
  // gains nothing from a worse cut, which would only cost strips.
  WitnessCut paper_cut, fallback;
  double paper_shortfall = std::numeric_limits<double>::infinity();
  double fallback_shortfall = std::numeric_limits<double>::infinity();
  auto shortfall_of = [&](const std::vector<Mesh>& pieces) {
    return cut_shortfall(pieces, options.limits, one_strip);
  };
  // A straightened cut (CutOptions::straighten_passes) that leaves a piece short of the limits
  // gives way to the exact iso-line where that falls less short: straightening moves a cut
  // across thin triangles, which can leave a narrow band the exact line does not.
  const auto cut_at = [&](const Eigen::VectorXd& field, double at) {
    std::vector<Mesh> pieces = cut_along_isoline(part, field, at, options.cut);
    if (!options.limits.active() || options.cut.straighten_passes == 0) return pieces;
    const double straightened = shortfall_of(pieces);
    if (straightened == 0.0) return pieces;
    CutOptions exact = options.cut;
    exact.straighten_passes = 0;
    std::vector<Mesh> along = cut_along_isoline(part, field, at, exact);
    return shortfall_of(along) < straightened ? along : pieces;
  };
  for (const double min_fraction : {options.min_piece_fraction, 0.0}) {
    for (const Attempt& attempt : attempts) {
      const Eigen::VectorXd* field = attempt.across ? across() : &f;
      if (!field) continue;
      const double value =
          !attempt.at_witness
              ? (disjoint || !attempt.across ? 0.5 : median(*field))
              : (attempt.across ? std::clamp(field_value_at(part, *field, witness), lo, hi)
                                : f_witness);
      std::vector<Mesh> pieces = cut_at(*field, value);
      if (!makes_progress(part, pieces, area, min_fraction)) continue;
      if (!options.limits.active()) return {std::move(pieces), value, attempt.across};
      double shortfall = shortfall_of(pieces);
      if (shortfall == 0.0) return {std::move(pieces), value, attempt.across};
      if (paper_cut.pieces.empty()) {
        paper_cut = {pieces, value, attempt.across};
        paper_shortfall = shortfall;
      }
      if (shortfall < fallback_shortfall) {
        fallback_shortfall = shortfall;
        fallback = {std::move(pieces), value, attempt.across};
      }
      // The nearest iso-values of this field, alternately on either side.
      for (int k = 1; options.limit_step > 0; ++k) {
        const double below = value - k * options.limit_step, above = value + k * options.limit_step;
        if (below < lo && above > hi) break;
        for (const double near : {below, above}) {
          if (near < lo || near > hi) continue;
          std::vector<Mesh> moved = cut_at(*field, near);
          if (!makes_progress(part, moved, area, min_fraction)) continue;
          shortfall = shortfall_of(moved);
          if (shortfall == 0.0) return {std::move(moved), near, attempt.across};
          if (shortfall < fallback_shortfall) {
            fallback_shortfall = shortfall;
            fallback = {std::move(moved), near, attempt.across};
          }
        }
      }
    }
    if (!fallback.pieces.empty())
      return fallback_shortfall <= options.limit_gain * paper_shortfall ? fallback : paper_cut;
  }
  return {};
}

WitnessCut cut_through_hole(const Mesh& part, const std::vector<int>& first,
                            const std::vector<int>& second, const std::vector<int>& loop,
                            const WitnessCutOptions& options, const OneStrip& one_strip,
                            const HoleCount& holes) {
  const double area = surface_area(part);
  const Eigen::VectorXd f = harmonic_field(part, first, second, options.harmonic);
  const double value = hole_split_value(f, loop);
  std::vector<Mesh> pieces = cut_along_isoline(part, f, value, options.cut);
  if (!makes_progress(part, pieces, area, options.min_piece_fraction)) {
    // The hole lies where f hardly varies: cut across the part through the hole instead.
    Vec3 centre = Vec3::Zero();
    for (int v : loop) centre += to_eigen(part.point(part.vertex_handle(v)));
    centre /= static_cast<double>(loop.size());
    return cut_through_witness(part, first, second, centre, options, one_strip);
  }
  if (!options.limits.active()) return {std::move(pieces), value};
  const double paper_shortfall = cut_shortfall(pieces, options.limits, one_strip);
  if (paper_shortfall == 0.0) return {std::move(pieces), value};
  // The cut through the middle of the hole leaves a piece too narrow or too small (a hole
  // near the part's end leaves a ring between them). Every iso-value of f between the hole's
  // extremes goes through the hole too, and so do those of the field across the part: the
  // first that meets the limits replaces it, or else the one falling least short, if it falls
  // far less short (limit_gain, as in cut_through_witness). An iso-value away from the middle
  // can cross the loop and still leave the hole in a piece: with `holes`, a cut whose pieces
  // hold more than the middle cut's is passed over (counted only for a cut that would be kept,
  // as counting selects each piece's strip boundaries).
  const auto holes_in = [&](const std::vector<Mesh>& cut) {
    int count = 0;
    for (const Mesh& piece : cut) count += holes(piece);
    return count;
  };
  const int middle_holes = holes ? holes_in(pieces) : 0;
  WitnessCut best;
  double best_shortfall = std::numeric_limits<double>::infinity();
  // Iso-values of `field` at these shares of its range over the hole's loop: each goes
  // through the hole. True when one meets the limits (it is then `best`).
  const auto through_hole = [&](const Eigen::VectorXd& field, bool across,
                                std::initializer_list<double> shares) {
    double low = field[loop.front()], high = low;
    for (int v : loop) low = std::min(low, field[v]), high = std::max(high, field[v]);
    for (const double t : shares) {
      const double near = low + t * (high - low);
      std::vector<Mesh> moved = cut_along_isoline(part, field, near, options.cut);
      if (!makes_progress(part, moved, area, options.min_piece_fraction)) continue;
      const double shortfall = cut_shortfall(moved, options.limits, one_strip);
      if (!(shortfall < best_shortfall)) continue;
      if (holes && holes_in(moved) > middle_holes) continue;
      best = {std::move(moved), near, across}, best_shortfall = shortfall;
      if (shortfall == 0.0) return true;
    }
    return false;
  };
  if (through_hole(f, false, {0.3, 0.7, 0.1, 0.9})) return best;
  // Across the part (the field between its farthest vertices), through the hole.
  const auto [from, to] = farthest_vertex_pair(part, 4);
  if (from != to) {
    const Eigen::VectorXd g = harmonic_field(part, {from}, {to}, options.harmonic);
    if (through_hole(g, true, {0.5, 0.3, 0.7, 0.1, 0.9})) return best;
  }
  if (!best.pieces.empty() && best_shortfall <= options.limit_gain * paper_shortfall) return best;
  return {std::move(pieces), value};
}

}  // namespace papercraft
