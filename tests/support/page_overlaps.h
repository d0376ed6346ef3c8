#pragma once
// Independent overlap checks of laid-out pages (PatternLayout), for the tab style and print
// side tests: glue tab flaps against their own piece and each other, and pieces (with their
// tabs) against each other. Simple polygons in page mm; touching is not overlapping.

#include <algorithm>
#include <string>
#include <vector>

#include "core/pattern.h"

namespace papercraft::testing {

namespace overlap_detail {

inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

inline double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t =
      d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Inside by the crossing number and farther than eps from every edge.
inline bool strictly_inside(const Vec2& p, const std::vector<Vec2>& polygon, double eps) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if (distance_to_segment(p, a, b) <= eps) return false;
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

inline bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double eps) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  const double s1 = eps * (b - a).norm(), s2 = eps * (d - c).norm();
  return ((d1 > s1 && d2 < -s1) || (d1 < -s1 && d2 > s1)) &&
         ((d3 > s2 && d4 < -s2) || (d3 < -s2 && d4 > s2));
}

// Every turn the same way (repeated points aside).
inline bool convex(const std::vector<Vec2>& polygon) {
  int left = 0, right = 0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double turn =
        cross(polygon[(i + 1) % n] - polygon[i], polygon[(i + 2) % n] - polygon[(i + 1) % n]);
    left += turn > 1e-12;
    right += turn < -1e-12;
  }
  return left == 0 || right == 0;
}

}  // namespace overlap_detail

/// The interiors of two simple polygons overlap: edges cross properly, or a corner of one, or
/// the centroid of a convex one, lies strictly inside the other (eps in mm).
inline bool polygons_overlap(const std::vector<Vec2>& p, const std::vector<Vec2>& q,
                             double eps = 1e-6) {
  using namespace overlap_detail;
  Vec2 plo = p[0], phi = p[0], qlo = q[0], qhi = q[0];
  for (const Vec2& v : p) plo = plo.cwiseMin(v), phi = phi.cwiseMax(v);
  for (const Vec2& v : q) qlo = qlo.cwiseMin(v), qhi = qhi.cwiseMax(v);
  if (!(plo.x() < qhi.x() && qlo.x() < phi.x() && plo.y() < qhi.y() && qlo.y() < phi.y()))
    return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j)
      if (segments_cross(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()], eps))
        return true;
  for (int pass = 0; pass < 2; ++pass) {
    const auto& a = pass ? q : p;
    const auto& b = pass ? p : q;
    Vec2 centroid = Vec2::Zero();
    for (const Vec2& v : a) {
      if (strictly_inside(v, b, eps)) return true;
      centroid += v;
    }
    if (convex(a) && strictly_inside(centroid / static_cast<double>(a.size()), b, eps)) return true;
  }
  return false;
}

/// A piece's triangles (page mm).
inline std::vector<std::vector<Vec2>> piece_triangles(const PlacedPiece& piece) {
  std::vector<std::vector<Vec2>> out;
  for (const Triangle& t : piece.triangles)
    out.push_back({piece.vertices[t[0]], piece.vertices[t[1]], piece.vertices[t[2]]});
  return out;
}

/// Every flap of every tab of a piece (page mm).
inline std::vector<std::vector<Vec2>> piece_flaps(const PlacedPiece& piece) {
  std::vector<std::vector<Vec2>> out;
  for (const Tab& tab : piece.tabs)
    for (const auto& flap : tab.flaps) out.push_back(flap);
  return out;
}

/// Overlaps on one piece: a flap over a triangle of its piece, or over another flap.
/// `problems` gets a line for each.
inline int tab_overlaps(const PlacedPiece& piece, std::vector<std::string>* problems = nullptr) {
  const auto triangles = piece_triangles(piece);
  const auto flaps = piece_flaps(piece);
  int count = 0;
  for (std::size_t f = 0; f < flaps.size(); ++f) {
    for (const auto& triangle : triangles)
      if (polygons_overlap(flaps[f], triangle)) {
        ++count;
        if (problems) problems->push_back("piece " + piece.name + ": a flap covers its piece");
        break;
      }
    for (std::size_t g = f + 1; g < flaps.size(); ++g)
      if (polygons_overlap(flaps[f], flaps[g])) {
        ++count;
        if (problems) problems->push_back("piece " + piece.name + ": two flaps overlap");
      }
  }
  return count;
}

/// Pairs of pieces (triangles and flaps; joining strips too) on one page that overlap.
inline int piece_overlaps(const Page& page, std::vector<std::string>* problems = nullptr) {
  std::vector<const PlacedPiece*> all;
  for (const PlacedPiece& piece : page.pieces) all.push_back(&piece);
  for (const PlacedPiece& joint : page.joints) all.push_back(&joint);
  std::vector<std::vector<std::vector<Vec2>>> shapes;
  for (const PlacedPiece* piece : all) {
    auto shape = piece_triangles(*piece);
    for (auto& flap : piece_flaps(*piece)) shape.push_back(std::move(flap));
    shapes.push_back(std::move(shape));
  }
  std::vector<std::pair<Vec2, Vec2>> boxes;
  for (const auto& shape : shapes) {
    Vec2 lo = Vec2::Constant(1e300), hi = Vec2::Constant(-1e300);
    for (const auto& polygon : shape)
      for (const Vec2& v : polygon) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    boxes.emplace_back(lo, hi);
  }
  int count = 0;
  for (std::size_t a = 0; a < shapes.size(); ++a)
    for (std::size_t b = a + 1; b < shapes.size(); ++b) {
      const auto& [alo, ahi] = boxes[a];
      const auto& [blo, bhi] = boxes[b];
      if (!(alo.x() < bhi.x() && blo.x() < ahi.x() && alo.y() < bhi.y() && blo.y() < ahi.y()))
        continue;
      bool overlap = false;
      for (const auto& p : shapes[a])
        for (const auto& q : shapes[b])
          if (!overlap && polygons_overlap(p, q)) overlap = true;
      if (!overlap) continue;
      ++count;
      if (problems) problems->push_back("pieces " + all[a]->name + " and " + all[b]->name);
    }
  return count;
}

/// All overlaps of a layout: tab_overlaps of every piece and piece_overlaps of every page.
inline int layout_overlaps(const PatternLayout& layout,
                           std::vector<std::string>* problems = nullptr) {
  int count = 0;
  for (const Page& page : layout.pages) {
    for (const PlacedPiece& piece : page.pieces) count += tab_overlaps(piece, problems);
    count += piece_overlaps(page, problems);
  }
  return count;
}

}  // namespace papercraft::testing
