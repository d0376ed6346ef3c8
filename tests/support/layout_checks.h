#pragma once
// Checks shared by the layout tests: polygon predicates written independently of the layout's
// own (polygon_2d.h), the shapes of a placed piece, and expect_valid_layout, every invariant a
// layout promises.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/pattern.h"
#include "core/strip.h"
#include "nodes/layout/pages.h"

namespace papercraft::testing {

inline constexpr double kEps = 1e-7;  // mm

inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

inline double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t =
      d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Strictly inside: odd crossing number and farther than eps from every edge.
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

// Interiors of two simple polygons overlap: edges cross properly, or a corner or the
// centroid of one lies strictly inside the other.
inline bool polygons_overlap(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j)
      if (segments_cross(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()], kEps))
        return true;
  for (int pass = 0; pass < 2; ++pass) {
    const auto& a = pass ? q : p;
    const auto& b = pass ? p : q;
    Vec2 centroid = Vec2::Zero();
    for (const Vec2& v : a) {
      if (strictly_inside(v, b, kEps)) return true;
      centroid += v;
    }
    if (strictly_inside(centroid / static_cast<double>(a.size()), b, kEps)) return true;
  }
  return false;
}

struct Shape {
  std::vector<Vec2> polygon;
  Vec2 lo, hi;
  int tab = -1;   // -1: a triangle of the piece; else index of the tab in the piece
  int flap = -1;  // index of the flap (global within the piece)
};

inline Shape make_shape(std::vector<Vec2> polygon, int tab, int flap) {
  Shape s{std::move(polygon), Vec2::Constant(1e300), Vec2::Constant(-1e300), tab, flap};
  for (const Vec2& v : s.polygon) {
    s.lo = s.lo.cwiseMin(v);
    s.hi = s.hi.cwiseMax(v);
  }
  return s;
}

// The piece's triangles and its tab flaps.
std::vector<Shape> shapes_of(const PlacedPiece& piece) {
  std::vector<Shape> shapes;
  for (const Triangle& t : piece.triangles)
    shapes.push_back(
        make_shape({piece.vertices[t[0]], piece.vertices[t[1]], piece.vertices[t[2]]}, -1, -1));
  int flap_id = 0;
  for (int k = 0; k < static_cast<int>(piece.tabs.size()); ++k) {
    const Tab& tab = piece.tabs[k];
    EXPECT_EQ(tab.flaps.size(), tab.bases.size());
    for (std::size_t f = 0; f < tab.flaps.size(); ++f, ++flap_id) {
      EXPECT_GT(tab.flaps[f].size(), tab.bases[f].size());
      shapes.push_back(make_shape(tab.flaps[f], k, flap_id));
    }
  }
  return shapes;
}

inline bool boxes_overlap(const Shape& a, const Shape& b) {
  return a.lo.x() < b.hi.x() && b.lo.x() < a.hi.x() && a.lo.y() < b.hi.y() && b.lo.y() < a.hi.y();
}

// On a triangle of the piece or a flap of its tabs (borders included, to 1e-6 mm).
inline bool on_piece(const Vec2& p, const PlacedPiece& piece) {
  constexpr double kSlack = 1e-6;
  for (const Triangle& t : piece.triangles) {
    const Vec2 &a = piece.vertices[t[0]], &b = piece.vertices[t[1]], &c = piece.vertices[t[2]];
    const double s = cross(b - a, c - a) < 0 ? -1.0 : 1.0;  // page triangles are clockwise
    if (s * cross(b - a, p - a) >= -kSlack * (b - a).norm() &&
        s * cross(c - b, p - b) >= -kSlack * (c - b).norm() &&
        s * cross(a - c, p - c) >= -kSlack * (a - c).norm())
      return true;
  }
  for (const Tab& tab : piece.tabs)
    for (const auto& flap : tab.flaps)
      if (strictly_inside(p, flap, -kSlack)) return true;
  return false;
}

// Every invariant a layout promises (the layout tests' contract with layout_pages): pieces
// inside the margins, isometric and never mirrored, every strip laid out completely, tabs on
// seam edges covering neither their piece nor each other, no two pieces overlapping, labels
// on their piece (or beside it on no piece), no two labels overlapping, leaders crossing no
// cut line or label, matching labels and one tab or joining strip per seam.
inline void expect_valid_layout(const PatternLayout& layout, const std::vector<FlatStrip>& strips,
                                const LayoutOptions& options) {
  const double x0 = options.margin_mm - kEps, y0 = options.margin_mm - kEps;
  const double x1 = options.page.width_mm - options.margin_mm + kEps;
  const double y1 = options.page.height_mm - options.margin_mm + kEps;
  auto inside = [&](const Vec2& p) {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  };
  std::map<int, const FlatStrip*> by_id;
  for (const FlatStrip& s : strips) by_id[s.id] = &s;
  std::map<std::string, int> label_count, tab_count, joint_count;
  std::set<std::string> self_seams;  // seams of a piece with itself
  std::map<int, std::size_t> triangles_per_strip;
  std::map<int, double> placed_area;  // page mm^2

  for (std::size_t p = 0; p < layout.pages.size(); ++p) {
    const Page& page = layout.pages[p];
    EXPECT_TRUE(inside(page.scale_bar.start));
    EXPECT_TRUE(inside(page.scale_bar.start + Vec2(page.scale_bar.length_mm, 0)));
    std::vector<std::vector<Shape>> shapes;
    for (const PlacedPiece& piece : page.pieces) {
      std::ostringstream trace;
      trace << "page " << p << " strip " << piece.strip_id << " piece " << piece.piece_index;
      SCOPED_TRACE(trace.str());
      const FlatStrip& strip = *by_id.at(piece.strip_id);
      triangles_per_strip[piece.strip_id] += piece.triangles.size();
      for (const Vec2& v : piece.vertices) EXPECT_TRUE(inside(v)) << v.transpose();
      for (const Tab& tab : piece.tabs)
        for (const auto& flap : tab.flaps)
          for (const Vec2& v : flap) EXPECT_TRUE(inside(v)) << v.transpose();
      for (const Label& label : piece.labels) EXPECT_TRUE(inside(label.position));
      EXPECT_TRUE(inside(piece.number.position));
      for (const FoldLine& fold : piece.folds) EXPECT_TRUE(inside(fold.a) && inside(fold.b));

      // An isometric copy at mm_per_unit, never mirrored (counter-clockwise as seen on
      // the page, whose y axis points down).
      // Where the layout divided the strip's triangles, the points it added have no strip
      // vertex (-1) but their 3D point.
      ASSERT_EQ(piece.points3d.size(), piece.vertices.size());
      ASSERT_EQ(piece.strip_vertex.size(), piece.vertices.size());
      for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
        if (piece.strip_vertex[v] < 0) continue;
        EXPECT_NEAR((piece.points3d[v] - strip.vertices3d[piece.strip_vertex[v]]).norm(), 0.0,
                    1e-12);
        EXPECT_NEAR(
            (piece.transform.apply(strip.vertices2d[piece.strip_vertex[v]]) - piece.vertices[v])
                .norm(),
            0.0, 1e-9);
      }
      for (const Triangle& t : piece.triangles) {
        placed_area[piece.strip_id] +=
            0.5 * std::abs(cross(piece.vertices[t[1]] - piece.vertices[t[0]],
                                 piece.vertices[t[2]] - piece.vertices[t[0]]));
        for (int i = 0; i < 3; ++i) {
          const int a = t[i], b = t[(i + 1) % 3];
          const double page_length = (piece.vertices[a] - piece.vertices[b]).norm();
          const double model_length = (piece.points3d[a] - piece.points3d[b]).norm();
          EXPECT_NEAR(page_length, model_length * layout.mm_per_unit,
                      1e-9 * std::max(1.0, page_length));
        }
        EXPECT_LE(cross(piece.vertices[t[1]] - piece.vertices[t[0]],
                        piece.vertices[t[2]] - piece.vertices[t[0]]),
                  1e-9);
      }

      for (const Label& label : piece.labels) ++label_count[label.text];
      for (const PieceSeam& seam : piece.seams)
        if (seam.partner == piece.name) self_seams.insert(seam.label);
      for (const Tab& tab : piece.tabs) {
        ++tab_count[tab.label];
        EXPECT_FALSE(tab.flaps.empty());
        // Every flap lies along seam edges of this piece that carry the tab's label (a flap
        // on one edge may take part of it).
        for (const auto& base : tab.bases)
          for (std::size_t j = 0; j + 1 < base.size(); ++j) {
            bool found = false;
            for (const PlacedEdge& e : piece.edges) {
              const double length = (e.b - e.a).norm();
              auto on_edge = [&](const Vec2& q) {
                const double t = (q - e.a).dot(e.b - e.a) / std::max(length * length, 1e-300);
                return t >= -1e-9 && t <= 1 + 1e-9 &&
                       std::abs(cross(e.b - e.a, q - e.a)) <= 1e-9 * std::max(1.0, length);
              };
              const bool whole =
                  (e.a - base[j]).norm() <= 1e-9 && (e.b - base[j + 1]).norm() <= 1e-9;
              const bool part = base.size() == 2 && on_edge(base[0]) && on_edge(base[1]) &&
                                (base[1] - base[0]).dot(e.b - e.a) > 0;
              if (!whole && !part) continue;
              found = true;
              EXPECT_EQ(e.kind, EdgeKind::Seam);
              EXPECT_EQ(e.label, tab.label);
              EXPECT_TRUE(e.has_tab);
            }
            EXPECT_TRUE(found) << "tab " << tab.label << " is not on an edge of its piece";
          }
      }
      for (const PlacedEdge& e : piece.edges) {
        if (e.kind != EdgeKind::Seam) {
          EXPECT_FALSE(e.has_tab);
        }
      }

      // Tabs cover neither their own piece nor each other.
      std::vector<Shape> mine = shapes_of(piece);
      for (std::size_t i = 0; i < mine.size(); ++i)
        for (std::size_t j = i + 1; j < mine.size(); ++j) {
          if (mine[i].tab < 0 && mine[j].tab < 0) continue;  // unfold guarantees these
          if (mine[i].flap >= 0 && mine[i].flap == mine[j].flap) continue;
          if (boxes_overlap(mine[i], mine[j])) {
            EXPECT_FALSE(polygons_overlap(mine[i].polygon, mine[j].polygon))
                << "tab shapes " << i << " and " << j << " overlap";
          }
        }
      shapes.push_back(std::move(mine));
    }
    // Joining strips: flat rectangles inside the margins, named by their seam.
    for (const PlacedPiece& joint : page.joints) {
      EXPECT_EQ(joint.strip_id, -1);
      EXPECT_EQ(joint.vertices.size(), 4u);
      EXPECT_TRUE(joint.tabs.empty());
      for (const Vec2& v : joint.vertices) EXPECT_TRUE(inside(v)) << v.transpose();
      ++joint_count[joint.name];
      shapes.push_back(shapes_of(joint));
    }
    // No two label boxes (seam labels, piece numbers, joint names) overlap, and every seam
    // label lies on its piece.
    std::vector<std::array<Vec2, 4>> boxes;
    std::vector<std::string> names;
    for (const PlacedPiece& joint : page.joints) {
      boxes.push_back(label_box(joint.number));
      names.push_back(joint.number.text);
    }
    for (const PlacedPiece& piece : page.pieces) {
      for (const Label& label : piece.labels) {
        boxes.push_back(label_box(label));
        names.push_back(label.text);
        const auto& box = boxes.back();
        if (label.outside) {
          // Printed beside its piece: on no piece of the page.
          for (const PlacedPiece& other : page.pieces)
            for (int i = 0; i < 4; ++i)
              EXPECT_FALSE(on_piece(box[i], other))
                  << "label " << label.text << " beside strip " << piece.strip_id
                  << " lies on strip " << other.strip_id;
          continue;
        }
        for (int i = 0; i < 4; ++i)
          for (const Vec2& point : {box[i], Vec2(0.5 * (box[i] + box[(i + 1) % 4]))})
            EXPECT_TRUE(on_piece(point, piece))
                << "label " << label.text << " of strip " << piece.strip_id
                << " leaves its piece at " << point.transpose();
      }
      boxes.push_back(label_box(piece.number));
      names.push_back(piece.number.text);
    }
    for (std::size_t a = 0; a < boxes.size(); ++a)
      for (std::size_t b = a + 1; b < boxes.size(); ++b) {
        std::vector<Vec2> pa(boxes[a].begin(), boxes[a].end()),
            pb(boxes[b].begin(), boxes[b].end());
        EXPECT_FALSE(polygons_overlap(pa, pb))
            << "labels " << names[a] << " and " << names[b] << " overlap on page " << p;
      }
    // A leader line (from a seam or its tab to a label away from it) crosses no cut line of
    // the page once it has left its start, and no other label.
    std::vector<std::array<Vec2, 2>> cuts;
    for (const auto* pieces : {&page.pieces, &page.joints})
      for (const PlacedPiece& piece : *pieces)
        for (const auto& loop : piece.cut_outline)
          for (std::size_t i = 0; i < loop.size(); ++i)
            cuts.push_back({loop[i], loop[(i + 1) % loop.size()]});
    auto crosses = [](const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
      const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
      const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
      return ((d1 > 1e-12 && d2 < -1e-12) || (d1 < -1e-12 && d2 > 1e-12)) &&
             ((d3 > 1e-12 && d4 < -1e-12) || (d3 < -1e-12 && d4 > 1e-12));
    };
    for (const PlacedPiece& piece : page.pieces)
      for (const Label& label : piece.labels) {
        // Straight, or bent round a corner: every segment.
        for (std::size_t k = 0; k + 1 < label.leader.size(); ++k) {
          const Vec2 direction = (label.leader[k + 1] - label.leader[k]).normalized();
          const Vec2 start = label.leader[k] + (k == 0 ? 0.1 : 0.0) * direction;
          const Vec2 end = label.leader[k + 1];
          for (const auto& cut : cuts)
            EXPECT_FALSE(crosses(start, end, cut[0], cut[1]))
                << "the leader of " << label.text << " crosses a cut line on page " << p;
          const auto own = label_box(label);
          for (std::size_t a = 0; a < boxes.size(); ++a) {
            if (boxes[a] == own) continue;
            for (int i = 0; i < 4; ++i)
              EXPECT_FALSE(crosses(start, end, boxes[a][i], boxes[a][(i + 1) % 4]))
                  << "the leader of " << label.text << " crosses label " << names[a];
          }
        }
      }
    // No two pieces (with their tabs) overlap.
    for (std::size_t a = 0; a < shapes.size(); ++a)
      for (std::size_t b = a + 1; b < shapes.size(); ++b)
        for (const Shape& sa : shapes[a])
          for (const Shape& sb : shapes[b])
            if (boxes_overlap(sa, sb)) {
              ASSERT_FALSE(polygons_overlap(sa.polygon, sb.polygon))
                  << "pieces " << a << " and " << b << " overlap on page " << p;
            }
  }
  // Every strip is laid out completely.
  bool divided = false;
  for (const std::string& note : layout.warnings)
    divided = divided || note.rfind("triangles divided", 0) == 0;
  for (const FlatStrip& s : strips) {
    if (!divided) {
      EXPECT_EQ(triangles_per_strip[s.id], s.triangles.size());
    }
    double area = 0;
    for (const Triangle& t : s.triangles)
      area += 0.5 * std::abs(cross(s.vertices2d[t[1]] - s.vertices2d[t[0]],
                                   s.vertices2d[t[2]] - s.vertices2d[t[0]]));
    area *= layout.mm_per_unit * layout.mm_per_unit;
    EXPECT_NEAR(placed_area[s.id], area, 1e-9 * std::max(1.0, area)) << "strip " << s.id;
  }
  // Matching labels on both sides of every seam, one tab per seam. A seam split with its
  // strip is printed as several (L.1, L.2, ...).
  std::set<std::string> input_labels;
  for (const FlatStrip& s : strips)
    for (const BoundaryEdge& e : s.boundary)
      if (e.kind == EdgeKind::Seam) input_labels.insert(e.label);
  for (const std::string& label : input_labels) {
    int printed = label_count.count(label) ? label_count[label] : 0;
    std::string prefix = label;
    prefix += '.';
    for (const auto& [text, count] : label_count)
      if (text.compare(0, prefix.size(), prefix) == 0) printed += count;
    EXPECT_GE(printed, self_seams.count(label) ? 1 : 2) << label;
  }
  for (const auto& [label, count] : label_count) {
    // One label may name both sides of a slit in a piece (a seam of the piece with itself).
    if (count != 1 || !self_seams.count(label)) {
      EXPECT_EQ(count, 2) << "seam label " << label;
    }
    if (options.tab_width_mm > 0 && options.joining_strips) {
      EXPECT_EQ(tab_count[label] + joint_count[label], 1) << "tabs and joints of seam " << label;
    } else if (options.tab_width_mm > 0) {
      EXPECT_LE(tab_count[label], 1) << "tabs of seam " << label;
    }
  }
  for (const auto& [label, count] : tab_count) EXPECT_EQ(label_count.count(label), 1u) << label;
  for (const auto& [label, count] : joint_count) EXPECT_EQ(label_count.count(label), 1u) << label;
}

std::vector<const PlacedPiece*> pieces_of(const PatternLayout& layout, int strip_id) {
  std::vector<const PlacedPiece*> result;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces)
      if (piece.strip_id == strip_id) result.push_back(&piece);
  return result;
}

inline int count_folds(const PlacedPiece& piece, FoldKind kind) {
  int count = 0;
  for (const FoldLine& f : piece.folds) count += f.kind == kind;
  return count;
}

}  // namespace papercraft::testing
