// Seam labels, piece numbers, fold lines and alignment marks on the pieces, and label_box.
#include "nodes/layout/annotations.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <utility>

#include "core/edge_map.h"
#include "nodes/layout/pages.h"
#include "nodes/layout/piece_shapes.h"

namespace papercraft::layout_internal {
namespace {

// Texts clear each other by at least this (mm). Boxes that only touch in the piece's plane
// can overlap by a rounding error once turned onto the page (and counted so).
constexpr double kTextGap = 1e-6;

// The inscribed circle of triangle t of the piece's strip: its centre and radius; none for a
// triangle whose corners coincide.
std::optional<std::pair<Vec2, double>> incircle(const StripData& data, int t) {
  const Triangle& tri = data.strip->triangles[t];
  const Vec2 &a = data.points[tri[0]], &b = data.points[tri[1]], &c = data.points[tri[2]];
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double perimeter = la + lb + lc;
  if (perimeter <= 0) return std::nullopt;
  return std::pair<Vec2, double>{(la * a + lb * b + lc * c) / perimeter,
                                 std::abs(cross(b - a, c - a)) / perimeter};
}

// Where the piece number goes: the incentre of a triangle with (nearly) the largest
// inscribed circle, the one nearest the piece's centroid; and that circle's radius.
std::pair<Vec2, double> number_spot(const StripData& data, const Piece& piece) {
  struct Candidate {
    Vec2 centre;
    double radius;
  };
  std::vector<Candidate> candidates;
  Vec2 centroid = Vec2::Zero();
  double area = 0, largest = 0;
  for (int t : piece.triangles) {
    const auto circle = incircle(data, t);
    if (!circle) continue;
    const Triangle& tri = data.strip->triangles[t];
    const Vec2 &a = data.points[tri[0]], &b = data.points[tri[1]], &c = data.points[tri[2]];
    const double twice_area = std::abs(cross(b - a, c - a));
    centroid += twice_area * (a + b + c) / 3.0;
    area += twice_area;
    candidates.push_back({circle->first, circle->second});
    largest = std::max(largest, circle->second);
  }
  if (candidates.empty()) return {data.points[data.strip->triangles[piece.triangles[0]][0]], 0};
  if (area > 0) centroid /= area;
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates)
    if (c.radius >= 0.8 * largest &&
        (!best || (c.centre - centroid).norm() < (best->centre - centroid).norm()))
      best = &c;
  return {best->centre, best->radius};
}

}  // namespace

void add_alignment_marks(const StripData& data, Piece& piece, const Chain& chain, double length) {
  if (chain.closed || length <= 0.0) return;
  const auto& loop = piece.loops[chain.loop];
  const int n = static_cast<int>(loop.size());
  auto tick = [&](int vertex, int edge) {
    const Vec2 d = data.points[loop[edge].v1] - data.points[loop[edge].v0];
    if (d.norm() == 0.0) return;
    const Vec2 across = Vec2(-d.y(), d.x()).normalized() * (0.5 * length);
    const Vec2& at = data.points[vertex];
    piece.marks.push_back({at - across, at + across});
  };
  const int first = chain.start, last = (chain.start + chain.count - 1) % n;
  if (loop[(first + n - 1) % n].kind == EdgeKind::Seam) tick(loop[first].v0, first);
  if (loop[(last + 1) % n].kind == EdgeKind::Seam) tick(loop[last].v1, last);
}

PieceLabel chain_label(const StripData& data, const Piece& piece, const Chain& chain,
                       const std::string& text, double size) {
  const auto& loop = piece.loops[chain.loop];
  const double total = chain_length(data, piece, chain);
  const double text_width = 0.6 * static_cast<double>(text.size());
  size = std::max(std::min(size, (total - 0.5) / std::max(text_width, 1e-9)), std::min(size, 2.0));
  // The edge at the chain's middle (a closed chain has none: its longest edge), with the
  // text kept clear of the edge's corners where the edge is long enough.
  int chosen = 0;
  double at = 0.5;
  double walked = 0, longest = -1;
  for (int i = 0; i < chain.count; ++i) {
    const PieceEdge& e = loop[(chain.start + i) % loop.size()];
    const double length = (data.points[e.v1] - data.points[e.v0]).norm();
    if (chain.closed) {
      if (length > longest) {
        longest = length;
        chosen = i;
      }
    } else if (walked + length >= 0.5 * total || i == chain.count - 1) {
      chosen = i;
      at = length > 0 ? std::clamp((0.5 * total - walked) / length, 0.0, 1.0) : 0.5;
      break;
    }
    walked += length;
  }
  const PieceEdge& e = loop[(chain.start + chosen) % loop.size()];
  const Vec2 a = data.points[e.v0], b = data.points[e.v1];
  const double length = (b - a).norm();
  const double clearance = 0.5 * text_width * size + 0.5;
  if (length > 2 * clearance)
    at = std::clamp(at, clearance / length, 1.0 - clearance / length);
  else
    at = 0.5;
  const Vec2 d = length > 0 ? Vec2((b - a) / length) : Vec2::UnitX();
  return {text, a + at * (b - a) + Vec2(-d.y(), d.x()) * (0.6 * size + 0.6), d, size, -1, false,
          {}};
}

std::vector<FoldLine> piece_folds(const StripData& data, const Piece& piece,
                                  double threshold_degrees, double strong_degrees) {
  const FlatStrip& strip = *data.strip;
  std::unordered_map<int, char> in_piece;
  for (int t : piece.triangles) in_piece[t] = 1;
  std::vector<FoldLine> folds;  // in the strip frame; placed later
  for (int t : piece.triangles) {
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = tri[i], b = tri[(i + 1) % 3], c = tri[(i + 2) % 3];
      if (a > b) continue;
      auto it = data.owner.find(directed_edge_key(b, a));
      if (it == data.owner.end() || !in_piece.count(it->second)) continue;
      const Triangle& other = strip.triangles[it->second];
      int d = -1;
      for (int k = 0; k < 3; ++k)
        if (other[k] != a && other[k] != b) d = other[k];
      const Vec3 &pa = strip.vertices3d[a], &pb = strip.vertices3d[b];
      const Vec3 n1 = (pb - pa).cross(strip.vertices3d[c] - pa);
      const Vec3 n2 = (pa - pb).cross(strip.vertices3d[d] - pb);
      if (n1.norm() == 0 || n2.norm() == 0) continue;
      const double bend =
          std::acos(std::clamp(n1.normalized().dot(n2.normalized()), -1.0, 1.0)) / kDegree;
      if (bend <= threshold_degrees) continue;
      const bool convex = (strip.vertices3d[d] - pa).dot(n1) < 0;
      folds.push_back({data.points[a], data.points[b],
                       convex ? FoldKind::Mountain : FoldKind::Valley, bend,
                       bend < strong_degrees});
    }
  }
  return folds;
}

PieceLabel piece_number(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const LayoutOptions& options) {
  auto [centre, radius] = number_spot(data, piece);
  PieceLabel number;
  number.text = piece.name;
  number.position = centre;
  number.size =
      std::min(options.number_size_mm,
               std::max(std::min(options.min_text_mm, options.number_size_mm), 1.8 * radius));
  number.direction = Vec2(std::cos(box.angle), std::sin(box.angle));
  return number;
}

namespace {

// The boundary segments of a piece and its flaps' outer chains (mm, strip frame): no text
// may cross them.
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

// True when segments a-b and c-d cross at a point inside both (touching does not count).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// The middle of the outer edge of a flap of the tab `label` carries on this piece, that edge's
// direction and its normal pointing away from the tab: where a leader leaves a seam walled in
// by its own tab.
struct TabEdge {
  Vec2 middle, along, outward;
};
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

// True when q lies in the convex quad (on its edges included).
bool inside_convex(const Vec2& q, const std::array<Vec2, 4>& box) {
  bool positive = false, negative = false;
  for (int i = 0; i < 4; ++i) {
    const double side = cross(box[(i + 1) % 4] - box[i], q - box[i]);
    positive = positive || side > 0;
    negative = negative || side < 0;
  }
  return !(positive && negative);
}

// A piece's cut lines in square buckets (4 mm, coarser on a huge piece), so a text box or a
// leader line is tested against the lines near it only; and the search for leaders that bend:
// breadth first on a square grid around a seam, stepping between neighbouring grid points along
// moves that cross no cut line and no text, from points just off the seam; the first grid
// point (fewest steps) whose text box passes a test ends it.
class LeaderRouter {
 public:
  LeaderRouter(const std::vector<std::array<Vec2, 2>>& lines, double step)
      : lines_(lines), step_(step) {
    for (const auto& line : lines) bounds_.add(line[0]), bounds_.add(line[1]);
    if (lines.empty()) return;
    bucket_ = std::max(4.0, (bounds_.hi - bounds_.lo).maxCoeff() / 256.0);
    bounds_.lo -= Vec2::Constant(bucket_);
    columns_ = static_cast<int>((bounds_.hi.x() - bounds_.lo.x()) / bucket_) + 2;
    rows_ = static_cast<int>((bounds_.hi.y() - bounds_.lo.y()) / bucket_) + 2;
    buckets_.resize(static_cast<std::size_t>(columns_) * rows_);
    for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
      const auto [c0, r0] = cell(lines[i][0].cwiseMin(lines[i][1]));
      const auto [c1, r1] = cell(lines[i][0].cwiseMax(lines[i][1]));
      for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c)
          buckets_[static_cast<std::size_t>(r) * columns_ + c].push_back(i);
    }
  }

  // True when segment a-b crosses no cut line and no box of `taken`.
  bool clear(const Vec2& a, const Vec2& b, const std::vector<std::array<Vec2, 4>>& taken) const {
    if (!buckets_.empty()) {
      const auto [c0, r0] = cell(a.cwiseMin(b));
      const auto [c1, r1] = cell(a.cwiseMax(b));
      for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c)
          for (int i : buckets_[static_cast<std::size_t>(r) * columns_ + c])
            if (segments_cross(a, b, lines_[i][0], lines_[i][1])) return false;
    }
    for (const auto& box : taken)
      if (segment_crosses(a, b, box)) return false;
    return true;
  }

  // True when no cut line crosses the convex quad.
  bool box_clear(const std::array<Vec2, 4>& box) const {
    if (buckets_.empty()) return true;
    Vec2 lo = box[0], hi = box[0];
    for (const Vec2& q : box) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    const auto [c0, r0] = cell(lo);
    const auto [c1, r1] = cell(hi);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        for (int i : buckets_[static_cast<std::size_t>(r) * columns_ + c])
          if (segment_crosses(lines_[i][0], lines_[i][1], box)) return false;
    return true;
  }

  // The path from one of `starts` to the first grid point within `reach` of it where
  // `box_ok(centre, start index)` holds, grid points inside a box of `taken` left out: the
  // points of the path, start first, and the start's index; empty when none is found.
  template <class BoxOk>
  std::pair<std::vector<Vec2>, int> route(const std::vector<Vec2>& starts, double reach,
                                          const std::vector<std::array<Vec2, 4>>& taken,
                                          BoxOk box_ok) const {
    Box2 around;
    for (const Vec2& s : starts) around.add(s);
    const Vec2 origin = around.lo - Vec2::Constant(reach);
    const int n = static_cast<int>((around.hi.x() - around.lo.x() + 2 * reach) / step_) + 2;
    const int m = static_cast<int>((around.hi.y() - around.lo.y() + 2 * reach) / step_) + 2;
    auto point = [&](int node) { return Vec2(origin + step_ * Vec2(node % n, node / n)); };
    auto free = [&](const Vec2& q) {
      for (const auto& box : taken)
        if (inside_convex(q, box)) return false;
      return true;
    };
    std::vector<int> parent(static_cast<std::size_t>(n) * m, -2), source(parent.size(), -1);
    std::deque<int> queue;
    for (int k = 0; k < static_cast<int>(starts.size()); ++k) {
      const Vec2 g = (starts[k] - origin) / step_;
      for (int dx = 0; dx <= 1; ++dx)
        for (int dy = 0; dy <= 1; ++dy) {
          const int x = static_cast<int>(std::floor(g.x())) + dx;
          const int y = static_cast<int>(std::floor(g.y())) + dy;
          if (x < 0 || y < 0 || x >= n || y >= m) continue;
          const int node = y * n + x;
          if (parent[node] != -2 || !free(point(node)) || !clear(starts[k], point(node), taken))
            continue;
          parent[node] = -1;
          source[node] = k;
          queue.push_back(node);
        }
    }
    while (!queue.empty()) {
      const int node = queue.front();
      queue.pop_front();
      const Vec2 here = point(node);
      const int k = source[node];
      if ((here - starts[k]).norm() > reach) continue;
      if ((here - starts[k]).norm() >= 2.0 && box_ok(here, k)) {
        std::vector<Vec2> path{here};
        for (int at = parent[node]; at >= 0; at = parent[at]) path.push_back(point(at));
        path.push_back(starts[k]);
        std::reverse(path.begin(), path.end());
        return {path, k};
      }
      const int x = node % n, y = node / n;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= n || ny >= m) continue;
          const int next = ny * n + nx;
          if (parent[next] != -2) continue;
          const Vec2 there = point(next);
          if (!free(there) || !clear(here, there, taken)) continue;
          parent[next] = node;
          source[next] = k;
          queue.push_back(next);
        }
    }
    return {{}, -1};
  }

 private:
  std::pair<int, int> cell(const Vec2& p) const {
    const int c = static_cast<int>(std::floor((p.x() - bounds_.lo.x()) / bucket_));
    const int r = static_cast<int>(std::floor((p.y() - bounds_.lo.y()) / bucket_));
    return {std::clamp(c, 0, columns_ - 1), std::clamp(r, 0, rows_ - 1)};
  }

  const std::vector<std::array<Vec2, 2>>& lines_;
  double step_;
  double bucket_ = 4.0;
  Box2 bounds_;
  int columns_ = 0, rows_ = 0;
  std::vector<std::vector<int>> buckets_;
};

}  // namespace

std::vector<std::array<Vec2, 4>> leader_boxes(const std::vector<Vec2>& leader) {
  std::vector<std::array<Vec2, 4>> boxes;
  for (std::size_t i = 0; i + 1 < leader.size(); ++i)
    boxes.push_back(leader_box({leader[i], leader[i + 1]}));
  return boxes;
}

std::array<Vec2, 4> leader_box(const std::vector<Vec2>& leader) {
  const Vec2 d = leader.back() - leader.front();
  const double length = d.norm();
  const Vec2 n = length > 0 ? Vec2(Vec2(-d.y(), d.x()) * (kLeaderHalfWidth / length))
                            : Vec2(kLeaderHalfWidth, 0.0);
  return {leader.front() - n, leader.back() - n, leader.back() + n, leader.front() + n};
}

namespace {

// What one pass of `place_labels` left: the positions (in the labels it was given) of the
// labels it kept, in order, and of those printed with no spot clear of other text and lines.
struct Placement {
  std::vector<std::size_t> kept;
  std::vector<std::size_t> crowded;
  bool number_crowded = false;  // the number found no clear spot either
  std::size_t misses() const { return crowded.size() + (number_crowded ? 1 : 0); }
};

// One pass of arrange_labels: the number, then the labels in their order, each taking the
// first clear spot left by those before it (the number after them, with `number_last`).
Placement place_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                       const OrientedBox& box, const LayoutOptions& options, bool number_last,
                       std::vector<std::string>& warnings) {
  Placement placement;
  const PieceShapes shapes = piece_shapes(data, piece);
  const std::vector<std::array<Vec2, 2>> lines = cut_lines(data, piece);
  const double smallest = options.min_text_mm;
  std::vector<std::array<Vec2, 4>> taken;
  const LeaderRouter router(lines, 1.0);
  auto clear = [&](const std::array<Vec2, 4>& candidate) {
    for (const auto& other : taken)
      if (convex_overlap(candidate.data(), 4, other.data(), 4, -kTextGap)) return false;
    return router.box_clear(candidate);
  };
  auto fits = [&](const std::array<Vec2, 4>& candidate) {
    return box_on_piece(candidate, shapes) && clear(candidate);
  };
  // Off the piece: the box meets none of its triangles and tabs (text printed beside it).
  std::vector<std::vector<Vec2>> flaps;
  std::vector<Box2> flap_boxes;  // each flap's bounding box: a box beyond it meets none of it
  for (const Flap& flap : piece.flaps) {
    if (flap.base.size() < 2 || flap.outer.empty()) continue;
    flaps.emplace_back(flap.base.rbegin(), flap.base.rend());
    flaps.back().insert(flaps.back().end(), flap.outer.begin(), flap.outer.end());
    flap_boxes.emplace_back();
    for (const Vec2& p : flaps.back()) flap_boxes.back().add(p);
  }
  // Beside the piece, whatever other text is there: no cut line crosses it, and it meets none
  // of the piece's triangles and tabs.
  auto beside = [&](const std::array<Vec2, 4>& candidate) {
    if (!router.box_clear(candidate)) return false;
    if (overlaps_triangles(candidate.data(), 4, shapes, 0.0)) return false;
    Box2 around;
    for (const Vec2& corner : candidate) around.add(corner);
    for (std::size_t f = 0; f < flaps.size(); ++f) {
      const Box2& box = flap_boxes[f];
      if (around.hi.x() < box.lo.x() || box.hi.x() < around.lo.x() || around.hi.y() < box.lo.y() ||
          box.hi.y() < around.lo.y())
        continue;  // apart, touching not even at a point
      const auto& flap = flaps[f];
      for (std::size_t i = 0; i < flap.size(); ++i)
        if (segment_crosses(flap[i], flap[(i + 1) % flap.size()], candidate)) return false;
      for (const Vec2& corner : candidate)
        if (point_in_polygon(corner, flap)) return false;
    }
    return true;
  };
  auto fits_outside = [&](const std::array<Vec2, 4>& candidate) {
    return clear(candidate) && beside(candidate);
  };
  // The number (first, unless `number_last`): at the best spot, shrunk (not below the
  // smallest text) until it lies clear on the piece; else at the incentres of the other
  // roomiest triangles.
  piece.number = piece_number(data, piece, box, options);
  auto place_number = [&] {
    std::vector<std::pair<double, Vec2>> spots;  // inscribed radius, incentre
    for (int t : piece.triangles)
      if (const auto circle = incircle(data, t)) spots.push_back({circle->second, circle->first});
    std::stable_sort(spots.begin(), spots.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    if (spots.size() > 40) spots.resize(40);
    spots.insert(spots.begin(), {0.0, piece.number->position});
    // At the first of `centres` (second of each pair) where it fits at `size`.
    auto number_at = [&](const std::vector<std::pair<double, Vec2>>& centres, double size) {
      for (const auto& [order, centre] : centres) {
        const auto candidate =
            text_box(centre, piece.number->direction, size, piece.number->text.size());
        if (!fits(candidate)) continue;
        piece.number->position = centre;
        piece.number->size = size;
        taken.push_back(candidate);
        return true;
      }
      return false;
    };
    bool number_placed = false;
    for (double size = piece.number->size; !number_placed; size -= 0.25) {
      size = std::max(size, smallest);
      number_placed = number_at(spots, size);
      if (size <= smallest) break;
    }
    if (!number_placed) {
      // Anywhere on the piece, at the smallest size: centres on a grid over the piece (1 mm,
      // coarser on a large piece), nearest the first spot first. A crowded small piece often
      // has room between its labels that no incentre hits.
      const Box2& bounds = shapes.bounds;
      const Vec2 extent = bounds.hi - bounds.lo;
      const double step = std::max(1.0, std::sqrt(extent.x() * extent.y() / 4000.0));
      std::vector<std::pair<double, Vec2>> centres;
      for (double x = bounds.lo.x() + 0.5 * step; x < bounds.hi.x(); x += step)
        for (double y = bounds.lo.y() + 0.5 * step; y < bounds.hi.y(); y += step)
          centres.push_back({(Vec2(x, y) - piece.number->position).squaredNorm(), Vec2(x, y)});
      std::stable_sort(centres.begin(), centres.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
      number_placed = number_at(centres, smallest);
    }
    if (!number_placed) {
      // Beside the piece: at a gap outside the middle of each of its longest cut edges.
      std::vector<std::pair<double, std::array<Vec2, 2>>> edges;
      for (const auto& line : lines) edges.push_back({(line[1] - line[0]).norm(), line});
      std::stable_sort(edges.begin(), edges.end(),
                       [](const auto& x, const auto& y) { return x.first > y.first; });
      if (edges.size() > 24) edges.resize(24);
      const double size = std::max(piece.number->size, smallest);
      for (const auto& [length, line] : edges) {
        if (number_placed || length <= 0) continue;
        const Vec2 along = (line[1] - line[0]) / length;
        for (double fraction : {0.5, 0.25, 0.75}) {
          const Vec2 middle = line[0] + fraction * (line[1] - line[0]);
          for (double side : {1.0, -1.0}) {
            for (double gap : {0.6, 1.5, 3.0, 5.0}) {
              const Vec2 centre =
                  middle + side * Vec2(-along.y(), along.x()) * (kHalfLineEm * size + gap);
              const auto candidate = text_box(centre, along, size, piece.number->text.size());
              if (!fits_outside(candidate)) continue;
              piece.number->position = centre;
              piece.number->direction = along;
              piece.number->size = size;
              piece.number->outside = true;
              taken.push_back(candidate);
              number_placed = true;
              break;
            }
            if (number_placed) break;
          }
          if (number_placed) break;
        }
      }
    }
    if (!number_placed) {
      piece.number->size = std::max(piece.number->size, smallest);
      taken.push_back(text_box(piece.number->position, piece.number->direction, piece.number->size,
                               piece.number->text.size()));
      warnings.push_back("piece " + piece.name + ": no room for its number clear of the cut line");
      placement.number_crowded = true;
    }
  };
  if (!number_last) place_number();
  // A point `at` mm along `chain` (and the direction of its edge there).
  auto chain_point = [&](const Chain& chain, double at, Vec2* direction) -> std::optional<Vec2> {
    const auto& loop = piece.loops[chain.loop];
    double walked = 0;
    for (int i = 0; i < chain.count; ++i) {
      const PieceEdge& e = loop[(chain.start + i) % loop.size()];
      const Vec2 a = data.points[e.v0], b = data.points[e.v1];
      const double length = (b - a).norm();
      if (length <= 0) continue;
      if (walked + length >= at || i == chain.count - 1) {
        *direction = (b - a) / length;
        return Vec2(a + std::clamp((at - walked) / length, 0.0, 1.0) * (b - a));
      }
      walked += length;
    }
    return std::nullopt;
  };
  // The two sides of a seam of the piece with itself that run side by side from a common
  // corner, no farther apart than kSlitWidth anywhere: a slit (a cone opened along a ruling).
  // One label at a slit names both its sides.
  constexpr double kSlitWidth = 8.0;
  auto slit = [&](const Chain& one, const Chain& other) {
    const double length = chain_length(data, piece, one);
    if (std::abs(length - chain_length(data, piece, other)) > 1e-6 * std::max(length, 1.0))
      return false;
    Vec2 direction;
    for (double fraction : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const auto p = chain_point(one, fraction * length, &direction);
      const auto q = chain_point(other, (1.0 - fraction) * length, &direction);
      if (!p || !q || (*p - *q).norm() > kSlitWidth) return false;
    }
    return true;
  };
  // Labels m and n name the two sides of one slit.
  auto slit_twins = [&](std::size_t m, std::size_t n) {
    const PieceLabel &x = piece.labels[m], &y = piece.labels[n];
    return m != n && x.text == y.text && x.chain >= 0 && y.chain >= 0 &&
           slit(chains[x.chain], chains[y.chain]);
  };
  std::vector<char> printed(piece.labels.size(), 1);
  std::vector<char> clear_spot(piece.labels.size(), 1);
  std::vector<char> detached(piece.labels.size(), 0);  // clear, but near its seam only
  for (std::size_t n = 0; n < piece.labels.size(); ++n) {
    PieceLabel& label = piece.labels[n];
    if (label.chain < 0) continue;
    const Chain& chain = chains[label.chain];
    const auto& loop = piece.loops[chain.loop];
    const double total = chain_length(data, piece, chain);
    auto point_at = [&](double at, Vec2* direction) {
      if (const auto point = chain_point(chain, at, direction)) return *point;
      *direction = Vec2::UnitX();
      return label.position;
    };
    const auto first_box = text_box(label.position, label.direction, label.size, label.text.size());
    if (label.size >= smallest && fits(first_box)) {
      taken.push_back(first_box);
      continue;
    }
    bool placed = false;
    // Along the seam, then smaller, down to the smallest text.
    std::vector<double> sizes{std::max(label.size, smallest)};
    for (double size : {0.85 * label.size, 0.7 * label.size, smallest})
      if (size < sizes.back() && size >= smallest) sizes.push_back(size);
    // Along the edge at each spot, or along the chain's chord (a curved seam), nearest the
    // seam first, then farther in.
    const PieceEdge& head = loop[chain.start % loop.size()];
    const PieceEdge& tail = loop[(chain.start + chain.count - 1) % loop.size()];
    const Vec2 chord = data.points[tail.v1] - data.points[head.v0];
    for (double size : sizes) {
      for (double gap : {0.6, 0.3, 1.2, 2.0, 3.0, 4.5}) {
        for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9, 0.05, 0.95}) {
          Vec2 along;
          const Vec2 on_edge = point_at(fraction * total, &along);
          for (const Vec2& direction :
               {along, chord.norm() > 1e-9 ? Vec2(chord.normalized()) : along}) {
            const Vec2 inward(-along.y(), along.x());
            const Vec2 centre = on_edge + inward * (kHalfLineEm * size + gap);
            const auto candidate = text_box(centre, direction, size, label.text.size());
            if (!fits(candidate)) continue;
            label.position = centre;
            label.direction = direction;
            label.size = size;
            taken.push_back(candidate);
            placed = true;
            break;
          }
          if (placed) break;
        }
        if (placed) break;
      }
      if (placed) break;
    }
    // On the seam's own tab, when this side carries it: the tab is glued under the other
    // piece, but the label is read while gluing.
    for (const PieceTab& tab : piece.tabs) {
      if (placed || tab.label != label.text) continue;
      for (int f : tab.flaps) {
        const Flap& flap = piece.flaps[f];
        if (placed || flap.base.size() < 2 || flap.outer.empty()) continue;
        std::vector<Vec2> polygon(flap.base.rbegin(), flap.base.rend());
        polygon.insert(polygon.end(), flap.outer.begin(), flap.outer.end());
        const Vec2 direction = (flap.base.front() - flap.base.back()).normalized();
        Vec2 centre = Vec2::Zero();
        for (const Vec2& q : polygon) centre += q;
        centre /= static_cast<double>(polygon.size());
        for (double size : sizes) {
          const auto candidate = text_box(centre, direction, size, label.text.size());
          bool inside = true;
          for (const Vec2& corner : candidate) inside = inside && point_in_polygon(corner, polygon);
          bool free = true;
          for (const auto& other : taken)
            free = free && !convex_overlap(candidate.data(), 4, other.data(), 4, -kTextGap);
          if (!inside || !free) continue;
          label.position = centre;
          label.direction = direction;
          label.size = size;
          taken.push_back(candidate);
          placed = true;
          break;
        }
      }
    }
    // Beside the seam, outside the piece: read while cutting, and the other piece's label
    // names the seam after.
    for (double size : sizes) {
      // Beyond this side's tab too, where it carries one.
      const double beyond_tab = options.tab_width_mm + 1.0;
      for (double gap : {0.6, 1.2, 2.0, 3.0, beyond_tab, beyond_tab + 2.0}) {
        for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9}) {
          if (placed) break;
          Vec2 along;
          const Vec2 on_edge = point_at(fraction * total, &along);
          for (const Vec2& direction :
               {along, chord.norm() > 1e-9 ? Vec2(chord.normalized()) : along}) {
            const Vec2 outward(along.y(), -along.x());
            const Vec2 centre = on_edge + outward * (kHalfLineEm * size + gap);
            const auto candidate = text_box(centre, direction, size, label.text.size());
            if (!fits_outside(candidate)) continue;
            label.position = centre;
            label.direction = direction;
            label.size = size;
            label.outside = true;
            taken.push_back(candidate);
            placed = true;
            break;
          }
        }
        if (placed) break;
      }
      if (placed) break;
    }
    // The text at `centre` (running along `along`, smallest size) with a leader line from
    // `anchor`: the box `candidate` passed its test already; the line (stopping short of the
    // box) must cross no cut line and no text, and pass `line_ok`.
    auto leader_at = [&](const Vec2& anchor, const Vec2& centre, const Vec2& along,
                         const std::array<Vec2, 4>& candidate, bool outside, auto line_ok) {
      const double reach = (centre - anchor).norm();
      if (reach <= 0) return false;
      const Vec2 ray = (centre - anchor) / reach;
      const auto parts = segment_outside(anchor, centre, candidate);
      if (parts.empty()) return false;
      const Vec2 start = anchor + 0.2 * ray;
      const Vec2 end = parts.front()[1] - 0.3 * ray;
      if ((end - start).dot(ray) <= 0.1) return false;
      if (!router.clear(start, end, taken) || !line_ok(start, end)) return false;
      label.position = centre;
      label.direction = along;
      label.size = smallest;
      label.outside = outside;
      label.leader = {anchor, end};
      taken.push_back(candidate);
      taken.push_back(leader_box(label.leader));
      return true;
    };
    // A leader line from `anchor` to a text box at `radius` (in order) along a ray turned 0,
    // +10, -10, +20, ... degrees (to +-170) from `normal`: the box must pass `box_ok`.
    auto leader_to = [&](const Vec2& anchor, const Vec2& along, const Vec2& normal,
                         std::initializer_list<double> radii, bool outside, auto box_ok,
                         auto line_ok) {
      for (double radius : radii) {
        for (int step = 0; step <= 34; ++step) {
          const double turn = (step % 2 == 1 ? 1 : -1) * ((step + 1) / 2) * 10.0 * kDegree;
          const Vec2 ray = std::cos(turn) * normal + std::sin(turn) * along;
          const Vec2 centre = anchor + radius * ray;
          const auto candidate = text_box(centre, along, smallest, label.text.size());
          if (box_ok(candidate) && leader_at(anchor, centre, along, candidate, outside, line_ok))
            return true;
        }
      }
      return false;
    };
    // A leader that runs off the piece: it touches no triangle and ends outside every tab.
    auto off_piece = [&](const Vec2& start, const Vec2& end) {
      if (overlaps_triangles(leader_box({start, end}).data(), 4, shapes, 0.01)) return false;
      for (const auto& flap : flaps)
        if (point_in_polygon(start, flap) || point_in_polygon(end, flap)) return false;
      return true;
    };
    // A leader that stays on the piece: it crosses no cut line, so its middle tells.
    auto on_piece = [&](const Vec2& start, const Vec2& end) {
      const Vec2 middle = 0.5 * (start + end);
      return box_on_piece({middle, middle, middle, middle}, shapes);
    };
    // Off the piece: the line touches no triangle of the piece and ends outside every tab.
    auto leader_outside = [&](const Vec2& anchor, const Vec2& along, const Vec2& outward) {
      return leader_to(anchor, along, outward, {4.0, 6.0, 8.0, 11.0, 15.0, 20.0, 26.0}, true,
                       fits_outside, off_piece);
    };
    // From the seam, its middle first: a seam in a narrow slit is reached from the slit's
    // mouth.
    for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9, 0.0, 1.0}) {
      if (placed) break;
      Vec2 along;
      const Vec2 anchor = point_at(fraction * total, &along);
      placed = leader_outside(anchor, along, Vec2(along.y(), -along.x()));
    }
    // From the middle of the outer edge of the seam's tab on this side: the seam itself is
    // walled in by its tab, but the tab names its seam as well.
    const std::vector<TabEdge> tab_edges = outer_tab_edges(piece, label.text);
    for (const TabEdge& edge : tab_edges) {
      if (placed) break;
      placed = leader_outside(edge.middle, edge.along, edge.outward);
    }
    // On the piece farther in, with a leader line from the seam: a seam round a small hole or
    // in a crowded corner has no room next to it, but the paper around it often has. The line
    // stays on the piece (it crosses no cut line) and crosses no text; fold lines it may cross.
    for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9}) {
      if (placed) break;
      Vec2 along;
      const Vec2 anchor = point_at(fraction * total, &along);
      placed = leader_to(anchor, along, Vec2(-along.y(), along.x()),
                         {5.0, 7.0, 9.0, 12.0, 15.0, 19.0, 24.0, 30.0}, false, fits, on_piece);
    }
    // Anywhere within 36 mm of the seam, on the piece or beside it: centres on a 1.5 mm grid,
    // nearest the seam first, each reached by a straight leader from the nearest of seven
    // points along the seam where one is free. The rays above miss a free spot behind a
    // crowd of other labels; this finds it, at some cost, for the few labels that get here.
    if (!placed) {
      struct Anchor {
        Vec2 at, along;
      };
      std::vector<Anchor> anchors;
      Box2 around;
      for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9, 0.0, 1.0}) {
        Anchor a;
        a.at = point_at(fraction * total, &a.along);
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
      std::vector<const Anchor*> order;
      for (const auto& spot : centres) {
        if (placed) break;
        const Vec2& centre = spot.second;  // a lambda below takes it (no structured binding)
        order.clear();
        for (const Anchor& a : anchors) order.push_back(&a);
        std::stable_sort(order.begin(), order.end(), [&](const Anchor* x, const Anchor* y) {
          return (centre - x->at).squaredNorm() < (centre - y->at).squaredNorm();
        });
        for (const Anchor* a : order) {
          const auto candidate = text_box(centre, a->along, smallest, label.text.size());
          if (fits(candidate))
            placed = leader_at(a->at, centre, a->along, candidate, false, on_piece);
          else if (fits_outside(candidate))
            placed = leader_at(a->at, centre, a->along, candidate, true, off_piece);
          if (placed) break;
        }
      }
    }
    // Round a corner: a leader that bends, found by a search through the free paper within
    // 40 mm, on the piece or off it, from points just off the seam (and off the outer edge of
    // the seam's tab on this side, which may wall the seam in); straightened after, and ended
    // where it meets its text. A seam deep in a notch reaches the open paper this way.
    for (bool outside : {false, true}) {
      if (placed) break;
      std::vector<Vec2> starts, alongs, origins;  // origin: where the leader begins
      for (double fraction : {0.5, 0.3, 0.7, 0.1, 0.9}) {
        Vec2 along;
        const Vec2 at = point_at(fraction * total, &along);
        const Vec2 inward(-along.y(), along.x());
        const Vec2 start = at + (outside ? -0.4 : 0.4) * inward;
        if (box_on_piece({start, start, start, start}, shapes) == outside) continue;
        starts.push_back(start);
        alongs.push_back(along);
        origins.push_back(at);
      }
      for (const TabEdge& edge : tab_edges) {
        if (!outside) break;
        starts.push_back(edge.middle + 0.4 * edge.outward);
        alongs.push_back(edge.along);
        origins.push_back(edge.middle);
      }
      if (starts.empty()) continue;
      std::array<Vec2, 4> found;
      Vec2 found_centre, found_direction;
      // Along the seam, else across it (still read from one side, where a slot is too narrow).
      auto box_ok = [&](const Vec2& centre, int k) {
        for (const Vec2& direction : {alongs[k], Vec2(-alongs[k].y(), alongs[k].x())}) {
          const auto candidate = text_box(centre, direction, smallest, label.text.size());
          if (inside_convex(starts[k], candidate)) continue;
          if (!(outside ? fits_outside(candidate) : fits(candidate))) continue;
          found = candidate;
          found_centre = centre;
          found_direction = direction;
          return true;
        }
        return false;
      };
      auto [path, k] = router.route(starts, 40.0, taken, box_ok);
      if (path.empty()) continue;
      // Straightened: from each point on, to the farthest later point in plain sight; then cut
      // where it first meets the text's box.
      std::vector<Vec2> leader{path.front()};
      for (std::size_t i = 0; i + 1 < path.size();) {
        std::size_t j = path.size() - 1;
        while (j > i + 1 && !(router.clear(path[i], path[j], taken) &&
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
      if (router.clear(origins[k], leader[1], taken))
        leader.front() = origins[k];
      else
        leader.insert(leader.begin(), origins[k]);
      label.position = found_centre;
      label.direction = found_direction;
      label.size = smallest;
      label.outside = outside;
      label.leader = leader;
      taken.push_back(found);
      for (const auto& box : leader_boxes(label.leader)) taken.push_back(box);
      placed = true;
    }
    if (!placed) {
      // The other side of a slit already names it: this side goes unprinted, rather than
      // over its twin in the slit.
      for (std::size_t m = 0; m < n && !placed; ++m)
        if (printed[m] && slit_twins(m, n)) {
          printed[n] = 0;
          placed = true;
        }
    }
    if (!placed) {
      // No spot a leader line can reach (a seam in a knot of cut lines, where several short
      // seams meet at one corner): the nearest spot within kNear of the seam, on the piece or
      // beside it, clear of other text and crossed by no line, with no leader. Read next to
      // its seam, the text names it; one over another text names nothing.
      constexpr double kNear = 12.0, kStep = 0.75;
      std::vector<std::pair<double, Vec2>> near;   // distance to the seam, centre
      std::vector<std::pair<Vec2, Vec2>> samples;  // points along the seam, direction there
      Box2 around;
      for (int k = 0; k <= 8; ++k) {
        Vec2 along;
        const Vec2 at = point_at(k / 8.0 * total, &along);
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
        if (placed) break;
        Vec2 along = samples.front().second;
        double closest = std::numeric_limits<double>::infinity();
        for (const auto& sample : samples)
          if ((centre - sample.first).norm() < closest)
            closest = (centre - sample.first).norm(), along = sample.second;
        for (const Vec2& direction : {along, Vec2(-along.y(), along.x())}) {
          const auto candidate = text_box(centre, direction, smallest, label.text.size());
          const bool on = fits(candidate);
          if (!on && !fits_outside(candidate)) continue;
          label.position = centre;
          label.direction = direction;
          label.size = smallest;
          label.outside = !on;
          label.leader.clear();
          taken.push_back(candidate);
          placed = true;
          clear_spot[n] = 0;
          detached[n] = 1;
          break;
        }
      }
    }
    if (!placed) {
      // No clear spot: the spot along the seam, on the piece or beside it and crossed by no cut
      // line, whose text meets the fewest other texts (the first spot where none meets fewer).
      auto crowding = [&](const std::array<Vec2, 4>& candidate) {
        int count = 0;
        for (const auto& other : taken)
          count += convex_overlap(candidate.data(), 4, other.data(), 4, -kTextGap);
        return count;
      };
      label.size = std::max(label.size, smallest);
      int least =
          crowding(text_box(label.position, label.direction, label.size, label.text.size()));
      for (double gap : {0.6, 1.2, 2.0, 3.0, 4.5}) {
        for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9}) {
          Vec2 along;
          const Vec2 on_edge = point_at(fraction * total, &along);
          for (double side : {1.0, -1.0}) {
            if (least == 0) break;
            const Vec2 normal = side * Vec2(-along.y(), along.x());
            const Vec2 centre = on_edge + normal * (kHalfLineEm * smallest + gap);
            const auto candidate = text_box(centre, along, smallest, label.text.size());
            const bool inside = side > 0;
            if (inside ? !(box_on_piece(candidate, shapes) && router.box_clear(candidate))
                       : !beside(candidate))
              continue;
            const int count = crowding(candidate);
            if (count >= least) continue;
            least = count;
            label.position = centre;
            label.direction = along;
            label.size = smallest;
            label.outside = !inside;
            label.leader.clear();
          }
        }
      }
      taken.push_back(text_box(label.position, label.direction, label.size, label.text.size()));
      clear_spot[n] = 0;
    }
  }
  if (number_last) place_number();
  // A side of a slit that found no clear spot, where the other side found one, or where the
  // other found none either and comes first: the other names the slit alone.
  for (std::size_t m = 0; m < piece.labels.size(); ++m) {
    if (clear_spot[m] || piece.labels[m].chain < 0) continue;
    for (std::size_t n = 0; n < piece.labels.size() && printed[m]; ++n)
      if (printed[n] && (clear_spot[n] || n < m) && slit_twins(n, m)) printed[m] = 0;
    if (printed[m]) {
      warnings.push_back("piece " + piece.name + ": label " + piece.labels[m].text +
                         (detached[m] ? " finds no spot clear of other text and lines that a "
                                        "leader line reaches; printed near its seam"
                                      : " finds no spot clear of other text and lines"));
      placement.crowded.push_back(m);
    }
  }
  std::size_t kept = 0;
  for (std::size_t n = 0; n < piece.labels.size(); ++n)
    if (printed[n]) {
      if (kept != n) piece.labels[kept] = std::move(piece.labels[n]);
      placement.kept.push_back(n);
      ++kept;
    }
  piece.labels.resize(kept);
  return placement;
}

}  // namespace

namespace {

// Everything arrange_labels reads of a piece, its strip and its chains, byte for byte.
std::string label_key(const StripData& data, const Piece& piece, const std::vector<Chain>& chains,
                      const OrientedBox& box) {
  std::string key;
  auto put = [&key](const auto& value) {
    key.append(reinterpret_cast<const char*>(&value), sizeof(value));
  };
  auto put_text = [&](const std::string& text) {
    put(text.size());
    key += text;
  };
  auto put_points = [&](const std::vector<Vec2>& points) {
    put(points.size());
    for (const Vec2& q : points) put(q.x()), put(q.y());
  };
  put(box.angle), put(box.min.x()), put(box.min.y()), put(box.size.x()), put(box.size.y());
  // The name by its length only: a split before this piece renumbers it, and its number
  // takes the same room at the same length.
  put(piece.strip), put(piece.joint), put(piece.name.size());
  put(piece.triangles.size());
  for (int t : piece.triangles) {
    put(t);
    for (int v : data.strip->triangles[t]) put(data.points[v].x()), put(data.points[v].y());
  }
  put(piece.loops.size());
  for (const auto& loop : piece.loops) {
    put(loop.size());
    for (const PieceEdge& e : loop) {
      put(e.v0), put(e.v1), put(e.kind), put(e.flap), put(e.flap_first);
      put(e.edge_flaps.size());
      for (int f : e.edge_flaps) put(f);
      put_text(e.label);
      put_text(e.printed);
    }
  }
  put(piece.flaps.size());
  for (const Flap& flap : piece.flaps) {
    put_points(flap.base);
    put_points(flap.outer);
    put(flap.tab);
  }
  put(piece.tabs.size());
  for (const PieceTab& tab : piece.tabs) {
    put_text(tab.label);
    put(tab.flaps.size());
    for (int f : tab.flaps) put(f);
  }
  put(piece.labels.size());
  for (const PieceLabel& label : piece.labels) {
    put_text(label.text);
    put(label.position.x()), put(label.position.y()), put(label.direction.x());
    put(label.direction.y()), put(label.size), put(label.chain >= 0), put(label.outside);
    put_points(label.leader);
    if (label.chain < 0) continue;
    const Chain& chain = chains[label.chain];
    put(chain.loop), put(chain.start), put(chain.count), put(chain.closed);
  }
  return key;
}

}  // namespace

void arrange_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                    const OrientedBox& box, const LayoutOptions& options,
                    std::vector<std::string>& warnings, LabelCache* cache) {
  std::string key;
  if (cache) {
    key = label_key(data, piece, chains, box);
    if (const auto found = cache->entries.find(key); found != cache->entries.end()) {
      const LabelCache::Entry& entry = found->second;
      // The chains by their index in this layout's list (the same chains, numbered anew
      // where pieces before were split).
      std::vector<PieceLabel> labels = entry.labels;
      for (std::size_t k = 0; k < labels.size(); ++k)
        labels[k].chain = piece.labels[entry.kept[k]].chain;
      piece.labels = std::move(labels);
      piece.number = entry.number;
      if (piece.number) piece.number->text = piece.name;
      // The notes name the piece as it was named then.
      const std::string then = "piece " + entry.name + ":", now = "piece " + piece.name + ":";
      for (const std::string& note : entry.warnings)
        warnings.push_back(note.rfind(then, 0) == 0 ? now + note.substr(then.size()) : note);
      return;
    }
  }
  const Piece before = piece;
  std::vector<std::string> notes;
  Placement best = place_labels(data, piece, chains, box, options, false, notes);
  std::vector<std::size_t> kept = best.kept;  // positions in before.labels of those kept
  // Labels that found no clear spot take the spots first in another pass, the others fill in
  // around them; a crowded corner often has room for all where the order was the trouble. Up
  // to three more passes, each putting the labels crowded in any pass before first; then one
  // with the number placed after the labels (it has more places to go than a label). The pass
  // with the fewest labels and numbers left without a clear spot is kept (the first on a tie).
  std::vector<std::size_t> first;  // positions in before.labels, crowded in some pass
  std::vector<std::size_t> order(before.labels.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  Placement last = best;  // the pass before, in `order`
  for (int pass = 0; pass < 4 && best.misses() > 0; ++pass) {
    const bool number_last = pass == 3;
    for (std::size_t m : last.crowded)
      if (std::find(first.begin(), first.end(), order[m]) == first.end()) first.push_back(order[m]);
    std::vector<std::size_t> next = first;
    for (std::size_t n = 0; n < before.labels.size(); ++n)
      if (std::find(first.begin(), first.end(), n) == first.end()) next.push_back(n);
    Piece retry = before;
    for (std::size_t k = 0; k < next.size(); ++k) retry.labels[k] = before.labels[next[k]];
    std::vector<std::string> retry_notes;
    last = place_labels(data, retry, chains, box, options, number_last, retry_notes);
    order = std::move(next);
    if (last.misses() >= best.misses()) continue;
    // Back in the labels' own order.
    std::vector<std::pair<std::size_t, PieceLabel>> sorted;
    for (std::size_t k = 0; k < last.kept.size(); ++k)
      sorted.emplace_back(order[last.kept[k]], std::move(retry.labels[k]));
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    retry.labels.clear();
    kept.clear();
    for (auto& [n, label] : sorted) {
      retry.labels.push_back(std::move(label));
      kept.push_back(n);
    }
    best = last;
    piece = std::move(retry);
    notes = std::move(retry_notes);
  }
  warnings.insert(warnings.end(), notes.begin(), notes.end());
  if (cache)
    cache->entries[std::move(key)] = {piece.name, piece.labels, std::move(kept), piece.number,
                                      std::move(notes)};
}

std::vector<std::array<Vec2, 4>> text_boxes(const Piece& piece) {
  std::vector<std::array<Vec2, 4>> boxes;
  if (piece.number)
    boxes.push_back(text_box(piece.number->position, piece.number->direction, piece.number->size,
                             piece.number->text.size()));
  for (const PieceLabel& label : piece.labels)
    boxes.push_back(text_box(label.position, label.direction, label.size, label.text.size()));
  return boxes;
}

std::vector<FoldLine> clear_of_text(const std::vector<FoldLine>& folds,
                                    const std::vector<std::array<Vec2, 4>>& boxes) {
  std::vector<FoldLine> out;
  for (const FoldLine& fold : folds) {
    std::vector<std::array<Vec2, 2>> parts{{fold.a, fold.b}};
    for (const auto& box : boxes) {
      std::vector<std::array<Vec2, 2>> next;
      for (const auto& part : parts)
        for (const auto& piece : segment_outside(part[0], part[1], box)) next.push_back(piece);
      parts = std::move(next);
    }
    for (const auto& part : parts) {
      if ((part[1] - part[0]).norm() < 1e-6) continue;
      FoldLine shortened = fold;
      shortened.a = part[0];
      shortened.b = part[1];
      out.push_back(shortened);
    }
  }
  return out;
}

}  // namespace papercraft::layout_internal

namespace papercraft {

using layout_internal::kDegree;
using layout_internal::text_box;

std::array<Vec2, 4> label_box(const Label& label) {
  const double angle = label.angle_degrees * kDegree;
  return text_box(label.position, Vec2(std::cos(angle), std::sin(angle)), label.size_mm,
                  label.text.size());
}

}  // namespace papercraft
