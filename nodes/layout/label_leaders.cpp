// The label placer's generators that reach a spot by a leader line: straight from the seam or
// its tab, farther onto the piece, from a grid round the seam, or bent round a corner.
#include <algorithm>
#include <cmath>
#include <limits>

#include "nodes/layout/annotations.h"
#include "nodes/layout/label_placer.h"

namespace papercraft::layout_internal {

// The text at `centre` (running along `along`, smallest size) with a leader line from
// `anchor`: the box `candidate` passed its test already; the line (stopping short of the box)
// must cross no cut line and no text, and pass `line_ok`.
template <class LineOk>
bool LabelPlacer::leader_at(SeamLabel& s, const Vec2& anchor, const Vec2& centre, const Vec2& along,
                            const Box& candidate, bool outside, LineOk line_ok) {
  const double reach = (centre - anchor).norm();
  if (reach <= 0) return false;
  const Vec2 ray = (centre - anchor) / reach;
  const auto parts = segment_outside(anchor, centre, candidate);
  if (parts.empty()) return false;
  const Vec2 start = anchor + 0.2 * ray;
  const Vec2 end = parts.front()[1] - 0.3 * ray;
  if ((end - start).dot(ray) <= 0.1) return false;
  if (!router_.clear(start, end, taken_) || !line_ok(start, end)) return false;
  put(s, centre, along, smallest_, outside, candidate);
  s.label->leader = {anchor, end};
  taken_.push_back(leader_box(s.label->leader));
  return true;
}

// A leader line from `anchor` to a text box at `radius` (in order) along a ray turned 0, +10,
// -10, +20, ... degrees (to +-170) from `normal`: the box must pass `box_ok`.
template <class BoxOk, class LineOk>
bool LabelPlacer::leader_to(SeamLabel& s, const Vec2& anchor, const Vec2& along, const Vec2& normal,
                            std::initializer_list<double> radii, bool outside, BoxOk box_ok,
                            LineOk line_ok) {
  for (double radius : radii) {
    for (int step = 0; step <= 34; ++step) {
      const double turn = (step % 2 == 1 ? 1 : -1) * ((step + 1) / 2) * 10.0 * kDegree;
      const Vec2 ray = std::cos(turn) * normal + std::sin(turn) * along;
      const Vec2 centre = anchor + radius * ray;
      const auto candidate = text_box(centre, along, smallest_, s.label->text.size());
      if (box_ok(candidate) && leader_at(s, anchor, centre, along, candidate, outside, line_ok))
        return true;
    }
  }
  return false;
}

// A leader that runs off the piece: it touches no triangle and ends outside every tab.
bool LabelPlacer::off_piece(const Vec2& start, const Vec2& end) const {
  if (overlaps_triangles(leader_box({start, end}).data(), 4, shapes_, 0.01)) return false;
  for (const auto& flap : flaps_)
    if (point_in_polygon(start, flap) || point_in_polygon(end, flap)) return false;
  return true;
}

// A leader that stays on the piece: it crosses no cut line, so its middle tells.
bool LabelPlacer::on_piece(const Vec2& start, const Vec2& end) const {
  const Vec2 middle = 0.5 * (start + end);
  return box_on_piece({middle, middle, middle, middle}, shapes_);
}

// Off the piece: the line touches no triangle of the piece and ends outside every tab.
bool LabelPlacer::leader_outside(SeamLabel& s, const Vec2& anchor, const Vec2& along,
                                 const Vec2& outward) {
  return leader_to(
      s, anchor, along, outward, {4.0, 6.0, 8.0, 11.0, 15.0, 20.0, 26.0}, true,
      [this](const Box& candidate) { return clear_at(candidate, Ground::Beside); },
      [this](const Vec2& a, const Vec2& b) { return off_piece(a, b); });
}

// From the seam, its middle first: a seam in a narrow slit is reached from the slit's mouth.
bool LabelPlacer::leader_from_seam(SeamLabel& s) {
  for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9, 0.0, 1.0}) {
    Vec2 along;
    const Vec2 anchor = point_at(s, fraction * s.total, &along);
    if (leader_outside(s, anchor, along, Vec2(along.y(), -along.x()))) return true;
  }
  return false;
}

// From the middle of the outer edge of the seam's tab on this side: the seam itself is walled
// in by its tab, but the tab names its seam as well.
bool LabelPlacer::leader_from_tab(SeamLabel& s) {
  for (const TabEdge& edge : s.tab_edges)
    if (leader_outside(s, edge.middle, edge.along, edge.outward)) return true;
  return false;
}

// On the piece farther in, with a leader line from the seam: a seam round a small hole or in a
// crowded corner has no room next to it, but the paper around it often has. The line stays on
// the piece (it crosses no cut line) and crosses no text; fold lines it may cross.
bool LabelPlacer::leader_inward(SeamLabel& s) {
  for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9}) {
    Vec2 along;
    const Vec2 anchor = point_at(s, fraction * s.total, &along);
    if (leader_to(
            s, anchor, along, Vec2(-along.y(), along.x()),
            {5.0, 7.0, 9.0, 12.0, 15.0, 19.0, 24.0, 30.0}, false,
            [this](const Box& candidate) { return clear_at(candidate, Ground::Piece); },
            [this](const Vec2& a, const Vec2& b) { return on_piece(a, b); }))
      return true;
  }
  return false;
}

// Anywhere within 36 mm of the seam, on the piece or beside it: centres on a 1.5 mm grid,
// nearest the seam first, each reached by a straight leader from the nearest of seven points
// along the seam where one is free. The rays above miss a free spot behind a crowd of other
// labels; this finds it, at some cost, for the few labels that get here.
bool LabelPlacer::leader_from_grid(SeamLabel& s) {
  struct Anchor {
    Vec2 at, along;
  };
  std::vector<Anchor> anchors;
  Box2 around;
  for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9, 0.0, 1.0}) {
    Anchor a;
    a.at = point_at(s, fraction * s.total, &a.along);
    anchors.push_back(a);
    around.add(a.at);
  }
  constexpr double kReach = 36.0, kStep = 1.5, kNearest = 2.0;
  std::vector<std::pair<double, Vec2>> centres;
  for (double x = around.lo.x() - kReach; x <= around.hi.x() + kReach; x += kStep)
    for (double y = around.lo.y() - kReach; y <= around.hi.y() + kReach; y += kStep) {
      const Vec2 centre(x, y);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Anchor& a : anchors) nearest = std::min(nearest, (centre - a.at).norm());
      if (nearest >= kNearest && nearest <= kReach) centres.push_back({nearest, centre});
    }
  std::stable_sort(centres.begin(), centres.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  auto on = [this](const Vec2& a, const Vec2& b) { return on_piece(a, b); };
  auto off = [this](const Vec2& a, const Vec2& b) { return off_piece(a, b); };
  std::vector<const Anchor*> order;
  for (const auto& spot : centres) {
    const Vec2& centre = spot.second;  // a lambda below takes it (no structured binding)
    order.clear();
    for (const Anchor& a : anchors) order.push_back(&a);
    std::stable_sort(order.begin(), order.end(), [&](const Anchor* x, const Anchor* y) {
      return (centre - x->at).squaredNorm() < (centre - y->at).squaredNorm();
    });
    for (const Anchor* a : order) {
      const auto candidate = text_box(centre, a->along, smallest_, s.label->text.size());
      bool placed = false;
      if (clear_at(candidate, Ground::Piece))
        placed = leader_at(s, a->at, centre, a->along, candidate, false, on);
      else if (clear_at(candidate, Ground::Beside))
        placed = leader_at(s, a->at, centre, a->along, candidate, true, off);
      if (placed) return true;
    }
  }
  return false;
}

// Round a corner: a leader that bends, found by a search through the free paper within 40 mm,
// on the piece or off it, from points just off the seam (and off the outer edge of the seam's
// tab on this side, which may wall the seam in); straightened after, and ended where it meets
// its text. A seam deep in a notch reaches the open paper this way.
bool LabelPlacer::leader_round_corner(SeamLabel& s) {
  PieceLabel& label = *s.label;
  for (bool outside : {false, true}) {
    const Ground ground = outside ? Ground::Beside : Ground::Piece;
    std::vector<Vec2> starts, alongs, origins;  // origin: where the leader begins
    for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9}) {
      Vec2 along;
      const Vec2 at = point_at(s, fraction * s.total, &along);
      const Vec2 inward(-along.y(), along.x());
      const Vec2 start = at + (outside ? -0.4 : 0.4) * inward;
      if (box_on_piece({start, start, start, start}, shapes_) == outside) continue;
      starts.push_back(start);
      alongs.push_back(along);
      origins.push_back(at);
    }
    for (const TabEdge& edge : s.tab_edges) {
      if (!outside) break;
      starts.push_back(edge.middle + 0.4 * edge.outward);
      alongs.push_back(edge.along);
      origins.push_back(edge.middle);
    }
    if (starts.empty()) continue;
    Box found;
    Vec2 found_centre, found_direction;
    // Along the seam, else across it (still read from one side, where a slot is too narrow).
    auto box_ok = [&](const Vec2& centre, int k) {
      for (const Vec2& direction : {alongs[k], Vec2(-alongs[k].y(), alongs[k].x())}) {
        const auto candidate = text_box(centre, direction, smallest_, label.text.size());
        if (inside_convex(starts[k], candidate)) continue;
        if (!clear_at(candidate, ground)) continue;
        found = candidate;
        found_centre = centre;
        found_direction = direction;
        return true;
      }
      return false;
    };
    auto [path, k] = router_.route(starts, 40.0, taken_, box_ok);
    if (path.empty()) continue;
    // Straightened: from each point on, to the farthest later point in plain sight; then cut
    // where it first meets the text's box.
    std::vector<Vec2> leader{path.front()};
    for (std::size_t i = 0; i + 1 < path.size();) {
      std::size_t j = path.size() - 1;
      while (j > i + 1 && !(router_.clear(path[i], path[j], taken_) &&
                            (outside ? off_piece(path[i], path[j]) : on_piece(path[i], path[j]))))
        --j;
      leader.push_back(path[j]);
      i = j;
    }
    for (std::size_t i = 0; i + 1 < leader.size(); ++i) {
      const auto parts = segment_outside(leader[i], leader[i + 1], found);
      if (parts.size() == 1 && (parts.front()[1] - leader[i + 1]).norm() < 1e-12) continue;
      const Vec2 d = (leader[i + 1] - leader[i]).normalized();
      leader.resize(i + 2);
      leader.back() = parts.empty() ? leader[i] : Vec2(parts.front()[1] - 0.3 * d);
      break;
    }
    if (leader.size() < 2 || (leader.back() - leader[leader.size() - 2]).norm() < 0.1) continue;
    // It starts on the seam or the tab's edge: the start moved back onto it (or joined to it,
    // where the first segment would not stay clear from there).
    if (router_.clear(origins[k], leader[1], taken_))
      leader.front() = origins[k];
    else
      leader.insert(leader.begin(), origins[k]);
    put(s, found_centre, found_direction, smallest_, outside, found);
    label.leader = leader;
    for (const auto& box : leader_boxes(label.leader)) taken_.push_back(box);
    return true;
  }
  return false;
}

}  // namespace papercraft::layout_internal
