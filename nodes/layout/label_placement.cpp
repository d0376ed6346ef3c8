// place_labels: the number and the seam labels of a piece, each at the first spot of a list of
// candidate generators that passes the one clearance test (LabelPlacer::clear_at).
#include "nodes/layout/label_placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "nodes/layout/annotations.h"
#include "nodes/layout/label_placer.h"

namespace papercraft::layout_internal {

std::optional<std::pair<Vec2, double>> incircle(const StripData& data, int t) {
  const Triangle& tri = data.strip->triangles[t];
  const Vec2 &a = data.points[tri[0]], &b = data.points[tri[1]], &c = data.points[tri[2]];
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double perimeter = la + lb + lc;
  if (perimeter <= 0) return std::nullopt;
  return std::pair<Vec2, double>{(la * a + lb * b + lc * c) / perimeter,
                                 std::abs(cross(b - a, c - a)) / perimeter};
}

std::vector<std::array<Vec2, 2>> cut_lines(const StripData& data, const Piece& piece) {
  std::vector<std::array<Vec2, 2>> lines;
  for (const auto& loop : piece.loops)
    for (const PieceEdge& e : loop) lines.push_back({data.points[e.v0], data.points[e.v1]});
  for (const Flap& flap : piece.flaps) {
    if (flap.base.empty() || flap.outer.empty()) continue;
    lines.push_back({flap.base.front(), flap.outer.front()});
    for (std::size_t i = 0; i + 1 < flap.outer.size(); ++i)
      lines.push_back({flap.outer[i], flap.outer[i + 1]});
    lines.push_back({flap.outer.back(), flap.base.back()});
  }
  return lines;
}

bool point_in_polygon(const Vec2& p, const std::vector<Vec2>& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

std::vector<TabEdge> outer_tab_edges(const Piece& piece, const std::string& label) {
  std::vector<TabEdge> edges;
  for (const PieceTab& tab : piece.tabs) {
    if (tab.label != label) continue;
    for (int f : tab.flaps) {
      const Flap& flap = piece.flaps[f];
      if (flap.base.size() < 2 || flap.outer.size() < 2) continue;
      const std::size_t i = (flap.outer.size() - 1) / 2;
      const Vec2 a = flap.outer[i], b = flap.outer[i + 1];
      if ((b - a).norm() < 1e-9) continue;
      const Vec2 along = (b - a).normalized();
      Vec2 outward(along.y(), -along.x());
      Vec2 inside = Vec2::Zero();
      for (const Vec2& q : flap.base) inside += q;
      inside /= static_cast<double>(flap.base.size());
      if (outward.dot(inside - a) > 0) outward = -outward;
      edges.push_back({0.5 * (a + b), along, outward});
    }
  }
  return edges;
}

// Beside the piece, whatever other text is there: no cut line crosses it, and it meets none
// of the piece's triangles and tabs.
bool LabelPlacer::beside(const Box& candidate) const {
  if (!router_.box_clear(candidate)) return false;
  if (overlaps_triangles(candidate.data(), 4, shapes_, 0.0)) return false;
  Box2 around;
  for (const Vec2& corner : candidate) around.add(corner);
  for (std::size_t f = 0; f < flaps_.size(); ++f) {
    const Box2& box = flap_boxes_[f];
    if (around.hi.x() < box.lo.x() || box.hi.x() < around.lo.x() || around.hi.y() < box.lo.y() ||
        box.hi.y() < around.lo.y())
      continue;  // apart, touching not even at a point
    const auto& flap = flaps_[f];
    for (std::size_t i = 0; i < flap.size(); ++i)
      if (segment_crosses(flap[i], flap[(i + 1) % flap.size()], candidate)) return false;
    for (const Vec2& corner : candidate)
      if (point_in_polygon(corner, flap)) return false;
  }
  return true;
}

Placement LabelPlacer::run(bool number_last) {
  // The number (first, unless `number_last`).
  piece_.number = piece_number(data_, piece_, box_, options_);
  if (!number_last) place_number();
  printed_.assign(piece_.labels.size(), 1);
  clear_spot_.assign(piece_.labels.size(), 1);
  detached_.assign(piece_.labels.size(), 0);
  for (std::size_t n = 0; n < piece_.labels.size(); ++n) {
    PieceLabel& label = piece_.labels[n];
    if (label.chain < 0) continue;
    SeamLabel s;
    s.n = n;
    s.label = &label;
    s.chain = &chains_[label.chain];
    s.total = chain_length(data_, piece_, *s.chain);
    s.sizes = {std::max(label.size, smallest_)};
    for (double size : {0.85 * label.size, 0.7 * label.size, smallest_})
      if (size < s.sizes.back() && size >= smallest_) s.sizes.push_back(size);
    const auto& loop = piece_.loops[s.chain->loop];
    const PieceEdge& head = loop[s.chain->start % loop.size()];
    const PieceEdge& tail = loop[(s.chain->start + s.chain->count - 1) % loop.size()];
    s.chord = data_.points[tail.v1] - data_.points[head.v0];
    s.tab_edges = outer_tab_edges(piece_, label.text);
    for (const Generator generator : kLabelGenerators)
      if ((this->*generator)(s)) break;
  }
  if (number_last) place_number();
  // A side of a slit that found no clear spot, where the other side found one, or where the
  // other found none either and comes first: the other names the slit alone.
  for (std::size_t m = 0; m < piece_.labels.size(); ++m) {
    if (clear_spot_[m] || piece_.labels[m].chain < 0) continue;
    for (std::size_t n = 0; n < piece_.labels.size() && printed_[m]; ++n)
      if (printed_[n] && (clear_spot_[n] || n < m) && slit_twins(n, m)) printed_[m] = 0;
    if (printed_[m]) {
      warnings_.push_back("piece " + piece_.name + ": label " + piece_.labels[m].text +
                          (detached_[m] ? " finds no spot clear of other text and lines that a "
                                          "leader line reaches; printed near its seam"
                                        : " finds no spot clear of other text and lines"));
      placement_.crowded.push_back(m);
    }
  }
  std::size_t kept = 0;
  for (std::size_t n = 0; n < piece_.labels.size(); ++n)
    if (printed_[n]) {
      if (kept != n) piece_.labels[kept] = std::move(piece_.labels[n]);
      placement_.kept.push_back(n);
      ++kept;
    }
  piece_.labels.resize(kept);
  return placement_;
}

// --- The piece number: at the best spot, shrunk (not below the smallest text) until it lies
// clear on the piece; else at the incentres of the other roomiest triangles; else anywhere on
// the piece; else beside it; else where it was, crowded.

void LabelPlacer::place_number() {
  if (number_at_incentres() || number_on_grid() || number_beside_edges()) return;
  number_crowded();
}

bool LabelPlacer::number_at_incentres() {
  PieceLabel& number = *piece_.number;
  std::vector<std::pair<double, Vec2>> spots;  // inscribed radius, incentre
  for (int t : piece_.triangles)
    if (const auto circle = incircle(data_, t)) spots.push_back({circle->second, circle->first});
  std::stable_sort(spots.begin(), spots.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  if (spots.size() > 40) spots.resize(40);
  spots.insert(spots.begin(), {0.0, number.position});
  for (double size = number.size;; size -= 0.25) {
    size = std::max(size, smallest_);
    for (const auto& [order, centre] : spots) {
      const auto candidate = text_box(centre, number.direction, size, number.text.size());
      if (!clear_at(candidate, Ground::Piece)) continue;
      number.position = centre;
      number.size = size;
      taken_.push_back(candidate);
      return true;
    }
    if (size <= smallest_) return false;
  }
}

// Anywhere on the piece, at the smallest size: centres on a grid over the piece (1 mm, coarser
// on a large piece), nearest the first spot first. A crowded small piece often has room
// between its labels that no incentre hits.
bool LabelPlacer::number_on_grid() {
  PieceLabel& number = *piece_.number;
  const Box2& bounds = shapes_.bounds;
  const Vec2 extent = bounds.hi - bounds.lo;
  const double step = std::max(1.0, std::sqrt(extent.x() * extent.y() / 4000.0));
  std::vector<std::pair<double, Vec2>> centres;
  for (double x = bounds.lo.x() + 0.5 * step; x < bounds.hi.x(); x += step)
    for (double y = bounds.lo.y() + 0.5 * step; y < bounds.hi.y(); y += step)
      centres.push_back({(Vec2(x, y) - number.position).squaredNorm(), Vec2(x, y)});
  std::stable_sort(centres.begin(), centres.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [order, centre] : centres) {
    const auto candidate = text_box(centre, number.direction, smallest_, number.text.size());
    if (!clear_at(candidate, Ground::Piece)) continue;
    number.position = centre;
    number.size = smallest_;
    taken_.push_back(candidate);
    return true;
  }
  return false;
}

// Beside the piece: at a gap outside the middle of each of its longest cut edges.
bool LabelPlacer::number_beside_edges() {
  PieceLabel& number = *piece_.number;
  std::vector<std::pair<double, std::array<Vec2, 2>>> edges;
  for (const auto& line : lines_) edges.push_back({(line[1] - line[0]).norm(), line});
  std::stable_sort(edges.begin(), edges.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  if (edges.size() > 24) edges.resize(24);
  const double size = std::max(number.size, smallest_);
  for (const auto& [length, line] : edges) {
    if (length <= 0) continue;
    const Vec2 along = (line[1] - line[0]) / length;
    for (double fraction : {0.5, 0.25, 0.75}) {
      const Vec2 middle = line[0] + fraction * (line[1] - line[0]);
      for (double side : {1.0, -1.0}) {
        for (double gap : {0.6, 1.5, 3.0, 5.0}) {
          const Vec2 centre =
              middle + side * Vec2(-along.y(), along.x()) * (kHalfLineEm * size + gap);
          const auto candidate = text_box(centre, along, size, number.text.size());
          if (!clear_at(candidate, Ground::Beside)) continue;
          number.position = centre;
          number.direction = along;
          number.size = size;
          number.outside = true;
          taken_.push_back(candidate);
          return true;
        }
      }
    }
  }
  return false;
}

void LabelPlacer::number_crowded() {
  PieceLabel& number = *piece_.number;
  number.size = std::max(number.size, smallest_);
  taken_.push_back(text_box(number.position, number.direction, number.size, number.text.size()));
  warnings_.push_back("piece " + piece_.name + ": no room for its number clear of the cut line");
  placement_.number_crowded = true;
}

// --- Points along a chain, and slits.

// A point `at` mm along `chain` (and the direction of its edge there).
std::optional<Vec2> LabelPlacer::chain_point(const Chain& chain, double at, Vec2* direction) const {
  const auto& loop = piece_.loops[chain.loop];
  double walked = 0;
  for (int i = 0; i < chain.count; ++i) {
    const PieceEdge& e = loop[(chain.start + i) % loop.size()];
    const Vec2 a = data_.points[e.v0], b = data_.points[e.v1];
    const double length = (b - a).norm();
    if (length <= 0) continue;
    if (walked + length >= at || i == chain.count - 1) {
      *direction = (b - a) / length;
      return Vec2(a + std::clamp((at - walked) / length, 0.0, 1.0) * (b - a));
    }
    walked += length;
  }
  return std::nullopt;
}

// The two sides of a seam of the piece with itself that run side by side from a common
// corner, no farther apart than kSlitWidth anywhere: a slit (a cone opened along a ruling).
// One label at a slit names both its sides.
bool LabelPlacer::slit(const Chain& one, const Chain& other) const {
  constexpr double kSlitWidth = 8.0;
  const double length = chain_length(data_, piece_, one);
  if (std::abs(length - chain_length(data_, piece_, other)) > 1e-6 * std::max(length, 1.0))
    return false;
  Vec2 direction;
  for (double fraction : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const auto p = chain_point(one, fraction * length, &direction);
    const auto q = chain_point(other, (1.0 - fraction) * length, &direction);
    if (!p || !q || (*p - *q).norm() > kSlitWidth) return false;
  }
  return true;
}

// Labels m and n name the two sides of one slit.
bool LabelPlacer::slit_twins(std::size_t m, std::size_t n) const {
  const PieceLabel &x = piece_.labels[m], &y = piece_.labels[n];
  return m != n && x.text == y.text && x.chain >= 0 && y.chain >= 0 &&
         slit(chains_[x.chain], chains_[y.chain]);
}

// --- Seam label generators, in the order kLabelGenerators tries them.

// Where chain_label put it, at its size.
bool LabelPlacer::as_given(SeamLabel& s) {
  const PieceLabel& label = *s.label;
  const auto first_box = text_box(label.position, label.direction, label.size, label.text.size());
  if (!(label.size >= smallest_ && clear_at(first_box, Ground::Piece))) return false;
  taken_.push_back(first_box);
  return true;
}

// Along the seam, then smaller, down to the smallest text: along the edge at each spot, or
// along the chain's chord (a curved seam), nearest the seam first, then farther in.
bool LabelPlacer::along_seam(SeamLabel& s) {
  for (double size : s.sizes)
    for (double gap : {0.6, 0.3, 1.2, 2.0, 3.0, 4.5})
      for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9, 0.05, 0.95}) {
        Vec2 along;
        const Vec2 on_edge = point_at(s, fraction * s.total, &along);
        for (const Vec2& direction :
             {along, s.chord.norm() > 1e-9 ? Vec2(s.chord.normalized()) : along}) {
          const Vec2 inward(-along.y(), along.x());
          const Vec2 centre = on_edge + inward * (kHalfLineEm * size + gap);
          const auto candidate = text_box(centre, direction, size, s.label->text.size());
          if (!clear_at(candidate, Ground::Piece)) continue;
          put(s, centre, direction, size, s.label->outside, candidate);
          return true;
        }
      }
  return false;
}

// On the seam's own tab, when this side carries it: the tab is glued under the other piece,
// but the label is read while gluing.
bool LabelPlacer::on_own_tab(SeamLabel& s) {
  for (const PieceTab& tab : piece_.tabs) {
    if (tab.label != s.label->text) continue;
    for (int f : tab.flaps) {
      const Flap& flap = piece_.flaps[f];
      if (flap.base.size() < 2 || flap.outer.empty()) continue;
      std::vector<Vec2> polygon(flap.base.rbegin(), flap.base.rend());
      polygon.insert(polygon.end(), flap.outer.begin(), flap.outer.end());
      const Vec2 direction = (flap.base.front() - flap.base.back()).normalized();
      Vec2 centre = Vec2::Zero();
      for (const Vec2& q : polygon) centre += q;
      centre /= static_cast<double>(polygon.size());
      for (double size : s.sizes) {
        const auto candidate = text_box(centre, direction, size, s.label->text.size());
        if (!clear_on_flap(candidate, polygon)) continue;
        put(s, centre, direction, size, s.label->outside, candidate);
        return true;
      }
    }
  }
  return false;
}

// Beside the seam, outside the piece: read while cutting, and the other piece's label names
// the seam after. Beyond this side's tab too, where it carries one.
bool LabelPlacer::beside_seam(SeamLabel& s) {
  const double beyond_tab = options_.tab_width_mm + 1.0;
  for (double size : s.sizes)
    for (double gap : {0.6, 1.2, 2.0, 3.0, beyond_tab, beyond_tab + 2.0})
      for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9}) {
        Vec2 along;
        const Vec2 on_edge = point_at(s, fraction * s.total, &along);
        for (const Vec2& direction :
             {along, s.chord.norm() > 1e-9 ? Vec2(s.chord.normalized()) : along}) {
          const Vec2 outward(along.y(), -along.x());
          const Vec2 centre = on_edge + outward * (kHalfLineEm * size + gap);
          const auto candidate = text_box(centre, direction, size, s.label->text.size());
          if (!clear_at(candidate, Ground::Beside)) continue;
          put(s, centre, direction, size, true, candidate);
          return true;
        }
      }
  return false;
}

// The other side of a slit already names it: this side goes unprinted, rather than over its
// twin in the slit.
bool LabelPlacer::named_by_slit_twin(SeamLabel& s) {
  for (std::size_t m = 0; m < s.n; ++m)
    if (printed_[m] && slit_twins(m, s.n)) {
      printed_[s.n] = 0;
      return true;
    }
  return false;
}

// No spot a leader line can reach (a seam in a knot of cut lines, where several short seams
// meet at one corner): the nearest spot within kNear of the seam, on the piece or beside it,
// clear of other text and crossed by no line, with no leader. Read next to its seam, the text
// names it; one over another text names nothing.
bool LabelPlacer::near_without_leader(SeamLabel& s) {
  PieceLabel& label = *s.label;
  constexpr double kNear = 12.0, kStep = 0.75;
  std::vector<std::pair<double, Vec2>> near;   // distance to the seam, centre
  std::vector<std::pair<Vec2, Vec2>> samples;  // points along the seam, direction there
  Box2 around;
  for (int k = 0; k <= 8; ++k) {
    Vec2 along;
    const Vec2 at = point_at(s, k / 8.0 * s.total, &along);
    samples.push_back({at, along});
    around.add(at);
  }
  for (double x = around.lo.x() - kNear; x <= around.hi.x() + kNear; x += kStep)
    for (double y = around.lo.y() - kNear; y <= around.hi.y() + kNear; y += kStep) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& sample : samples)
        nearest = std::min(nearest, (Vec2(x, y) - sample.first).norm());
      if (nearest <= kNear) near.push_back({nearest, Vec2(x, y)});
    }
  std::stable_sort(near.begin(), near.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [distance, centre] : near) {
    Vec2 along = samples.front().second;
    double closest = std::numeric_limits<double>::infinity();
    for (const auto& sample : samples)
      if ((centre - sample.first).norm() < closest)
        closest = (centre - sample.first).norm(), along = sample.second;
    for (const Vec2& direction : {along, Vec2(-along.y(), along.x())}) {
      const auto candidate = text_box(centre, direction, smallest_, label.text.size());
      const bool on = clear_at(candidate, Ground::Piece);
      if (!on && !clear_at(candidate, Ground::Beside)) continue;
      put(s, centre, direction, smallest_, !on, candidate);
      label.leader.clear();
      clear_spot_[s.n] = 0;
      detached_[s.n] = 1;
      return true;
    }
  }
  return false;
}

// No clear spot: the spot along the seam, on the piece or beside it and crossed by no cut
// line, whose text meets the fewest other texts (the first spot where none meets fewer).
bool LabelPlacer::fewest_overlaps(SeamLabel& s) {
  PieceLabel& label = *s.label;
  auto crowding = [&](const Box& candidate) {
    int count = 0;
    for (const auto& other : taken_)
      count += convex_overlap(candidate.data(), 4, other.data(), 4, -kTextGap);
    return count;
  };
  label.size = std::max(label.size, smallest_);
  int least = crowding(text_box(label.position, label.direction, label.size, label.text.size()));
  for (double gap : {0.6, 1.2, 2.0, 3.0, 4.5}) {
    for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9}) {
      Vec2 along;
      const Vec2 on_edge = point_at(s, fraction * s.total, &along);
      for (double side : {1.0, -1.0}) {
        if (least == 0) break;
        const Vec2 normal = side * Vec2(-along.y(), along.x());
        const Vec2 centre = on_edge + normal * (kHalfLineEm * smallest_ + gap);
        const auto candidate = text_box(centre, along, smallest_, label.text.size());
        const bool inside = side > 0;
        // Crossed by no cut line, on its ground; other text it may meet.
        if (inside ? !(box_on_piece(candidate, shapes_) && router_.box_clear(candidate))
                   : !beside(candidate))
          continue;
        const int count = crowding(candidate);
        if (count >= least) continue;
        least = count;
        label.position = centre;
        label.direction = along;
        label.size = smallest_;
        label.outside = !inside;
        label.leader.clear();
      }
    }
  }
  taken_.push_back(text_box(label.position, label.direction, label.size, label.text.size()));
  clear_spot_[s.n] = 0;
  return true;
}

Placement place_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                       const OrientedBox& box, const LayoutOptions& options, bool number_last,
                       std::vector<std::string>& warnings) {
  return LabelPlacer(data, piece, chains, box, options, warnings).run(number_last);
}

}  // namespace papercraft::layout_internal
