#include "nodes/layout/pages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

#include "core/edge_map.h"
#include "core/errors.h"
#include "core/flat_boundary.h"
#include "nodes/layout/divide_triangles.h"
#include "nodes/layout/nesting.h"
#include "nodes/layout/polygon_2d.h"
#include "nodes/layout/split_to_fit.h"
#include "support/layout_strips.h"

namespace papercraft {
namespace {

using testing::arc_strip;
using testing::cell_strip;
using testing::l_footprint;
using testing::mark_seam;
using testing::prism_strips;
using testing::square_footprint;

constexpr double kEps = 1e-7;  // mm

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t =
      d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Strictly inside: odd crossing number and farther than eps from every edge.
bool strictly_inside(const Vec2& p, const std::vector<Vec2>& polygon, double eps) {
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

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double eps) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  const double s1 = eps * (b - a).norm(), s2 = eps * (d - c).norm();
  return ((d1 > s1 && d2 < -s1) || (d1 < -s1 && d2 > s1)) &&
         ((d3 > s2 && d4 < -s2) || (d3 < -s2 && d4 > s2));
}

// Interiors of two simple polygons overlap: edges cross properly, or a corner or the
// centroid of one lies strictly inside the other.
bool polygons_overlap(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
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

Shape make_shape(std::vector<Vec2> polygon, int tab, int flap) {
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

bool boxes_overlap(const Shape& a, const Shape& b) {
  return a.lo.x() < b.hi.x() && b.lo.x() < a.hi.x() && a.lo.y() < b.hi.y() && b.lo.y() < a.hi.y();
}

// Every invariant a layout promises (pages_test's contract with layout_pages).
// On a triangle of the piece or a flap of its tabs (borders included, to 1e-6 mm).
bool on_piece(const Vec2& p, const PlacedPiece& piece) {
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

void expect_valid_layout(const PatternLayout& layout, const std::vector<FlatStrip>& strips,
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

int count_folds(const PlacedPiece& piece, FoldKind kind) {
  int count = 0;
  for (const FoldLine& f : piece.folds) count += f.kind == kind;
  return count;
}

// A box: the band folds at three corners (the fourth is its seam), all convex: mountains.
// Seams A (band with itself), T and B (band with caps): two labels and one tab each, the
// tabs on the band (the lower strip id).
TEST(LayoutPages, BoxHasMountainFoldsMatchingLabelsAndOneTabPerSeam) {
  const auto strips = prism_strips(square_footprint(40), 60, 0);
  LayoutOptions options;
  options.scale = 1.0;
  const PatternLayout layout = layout_pages(strips, options);
  EXPECT_DOUBLE_EQ(layout.mm_per_unit, 1.0);
  ASSERT_EQ(layout.pages.size(), 1u);
  ASSERT_EQ(layout.pages[0].pieces.size(), 3u);
  expect_valid_layout(layout, strips, options);
  EXPECT_TRUE(layout.warnings.empty());

  const PlacedPiece& band = *pieces_of(layout, 0).at(0);
  EXPECT_EQ(band.folds.size(), 3u);
  EXPECT_EQ(count_folds(band, FoldKind::Mountain), 3);
  for (const FoldLine& f : band.folds) {
    EXPECT_NEAR(f.bend_degrees, 90.0, 1e-9);
    EXPECT_NEAR((f.a - f.b).norm(), 60.0, 1e-9);
  }
  EXPECT_EQ(band.tabs.size(), 3u);
  EXPECT_EQ(band.labels.size(), 4u);  // A twice, T, B
  EXPECT_EQ(band.number.text, "1");   // pieces are numbered 1..N
  for (int cap : {1, 2}) {
    const PlacedPiece& piece = *pieces_of(layout, cap).at(0);
    EXPECT_TRUE(piece.folds.empty());  // the diagonal is flat
    EXPECT_TRUE(piece.tabs.empty());
    ASSERT_EQ(piece.labels.size(), 1u);
    EXPECT_EQ(piece.labels[0].text, cap == 1 ? "T" : "B");
    ASSERT_EQ(piece.cut_outline.size(), 1u);
    EXPECT_EQ(piece.cut_outline[0].size(), 4u);  // no tab: the square itself
  }
  // The band's cut line goes around its three tabs: its 10 corners and the tabs' outer
  // chains (the ends and a mitre point over every seam vertex between).
  ASSERT_EQ(band.cut_outline.size(), 1u);
  EXPECT_EQ(band.cut_outline[0].size(), 10u + 5u + 5u + 2u);
  // Labels are upright and have a readable size.
  for (const Label& label : band.labels) {
    EXPECT_GT(label.angle_degrees, -90.0);
    EXPECT_LE(label.angle_degrees, 90.0);
    EXPECT_GE(label.size_mm, 2.5 - 1e-12);
  }
}

// An L-shaped prism has one reflex corner: a valley fold among four mountains.
TEST(LayoutPages, LShapedPrismHasOneValleyFold) {
  const auto strips = prism_strips(l_footprint(20), 30, 4);
  LayoutOptions options;
  options.scale = 1.5;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  const PlacedPiece& band = *pieces_of(layout, 4).at(0);
  EXPECT_EQ(count_folds(band, FoldKind::Mountain), 4);
  EXPECT_EQ(count_folds(band, FoldKind::Valley), 1);
}

// height_mm maps the largest side of the 3D bounding box (here x and y: 20, z: 15).
TEST(LayoutPages, HeightMapsLargestSideOfTheBoundingBox) {
  const auto strips = prism_strips(l_footprint(10), 15, 0);
  LayoutOptions options;
  options.height_mm = 100;
  EXPECT_DOUBLE_EQ(layout_scale(strips, options), 5.0);
  const PatternLayout layout = layout_pages(strips, options);
  EXPECT_DOUBLE_EQ(layout.mm_per_unit, 5.0);
  expect_valid_layout(layout, strips, options);
  options.scale = 2.0;  // overrides height_mm
  EXPECT_DOUBLE_EQ(layout_scale(strips, options), 2.0);
}

// Two cells bent along their shared edge: a fold only above the threshold; bent away from
// the printed (outer, +z) side it is a mountain, towards it a valley.
TEST(LayoutPages, FoldThresholdAndDirection) {
  auto bent = [](double degrees) {
    FlatStrip s = cell_strip(0, 2, 1, 10, 10);
    const double a = degrees * M_PI / 180.0;
    for (std::size_t v = 0; v < s.vertices2d.size(); ++v)
      if (s.vertices2d[v].x() > 15)
        s.vertices3d[v] = Vec3(10 + 10 * std::cos(a), s.vertices2d[v].y(), 10 * std::sin(a));
    return std::vector<FlatStrip>{s};
  };
  LayoutOptions options;
  options.scale = 1;
  options.fold_angle_degrees = 0.5;
  EXPECT_TRUE(layout_pages(bent(0.3), options).pages[0].pieces[0].folds.empty());
  options.fold_angle_degrees = 0.1;
  auto folds = layout_pages(bent(0.3), options).pages[0].pieces[0].folds;
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].kind, FoldKind::Valley);
  EXPECT_NEAR(folds[0].bend_degrees, 0.3, 1e-6);
  EXPECT_TRUE(folds[0].gentle);
  folds = layout_pages(bent(-30), options).pages[0].pieces[0].folds;
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].kind, FoldKind::Mountain);
  EXPECT_NEAR(folds[0].bend_degrees, 30, 1e-6);
  EXPECT_FALSE(folds[0].gentle);
  options.strong_fold_angle_degrees = 45;
  EXPECT_TRUE(layout_pages(bent(-30), options).pages[0].pieces[0].folds.at(0).gentle);
}

// Two flat strips glued along y = 0 in 3D, each with its own uv offset (as across a uv
// seam of an atlas): a tab shows the partner's texture where the partner would lie.
TEST(LayoutPages, TabTextureContinuesThePartnerStrip) {
  std::vector<FlatStrip> strips = {cell_strip(0, 2, 1, 20, 10), cell_strip(1, 2, 1, 20, 10)};
  mark_seam(strips[0], "s", 1, [](const Vec2& m) { return m.y() == 0; });
  mark_seam(strips[1], "s", 0, [](const Vec2& m) { return m.y() == 10; });
  auto uv_of = [](int strip, const Vec2& p3d) {
    return Vec2(p3d.x() / 40 + 0.5 * strip, (p3d.y() + 10) / 20);
  };
  for (int k = 0; k < 2; ++k)
    for (std::size_t v = 0; v < strips[k].vertices3d.size(); ++v) {
      strips[k].vertices3d[v].y() -= 10 * k;
      strips[k].uvs.push_back(uv_of(k, strips[k].vertices3d[v].head<2>()));
    }
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  int patches = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces)
      for (const Tab& tab : piece.tabs)
        for (const TexturePatch& patch : tab.texture) {
          ++patches;
          Eigen::Matrix3d from, to;
          for (int k = 0; k < 3; ++k) {
            from.col(k) << patch.uvs[k], 1.0;
            to.col(k) << patch.corners[k], 1.0;
          }
          const Eigen::Matrix3d page_to_uv = from * to.inverse();
          Vec2 centre = Vec2::Zero();
          for (const Vec2& c : patch.clip) centre += c / static_cast<double>(patch.clip.size());
          const Vec2 uv = (page_to_uv * Eigen::Vector3d(centre.x(), centre.y(), 1)).head<2>();
          // The flat continuation of the piece's own strip frame, in 3D.
          const Vec2 frame =
              piece.transform.linear.inverse() * (centre - piece.transform.translation);
          const Vec2 p3d = frame - Vec2(0, 10 * piece.strip_id);
          const Vec2 expected = uv_of(1 - piece.strip_id, p3d);
          EXPECT_NEAR((uv - expected).norm(), 0, 1e-9) << uv.transpose();
        }
  EXPECT_GE(patches, 2);  // one per seam edge under the tab
}

TEST(LayoutPages, OpenEdgesGetNoTabsOrLabels) {
  const std::vector<FlatStrip> strips = {cell_strip(3, 4, 2, 10, 10)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  const PlacedPiece& piece = layout.pages.at(0).pieces.at(0);
  EXPECT_TRUE(piece.tabs.empty());
  EXPECT_TRUE(piece.labels.empty());
  EXPECT_EQ(piece.number.text, "1");  // the only piece, whatever its strip id
  for (const PlacedEdge& e : piece.edges) EXPECT_EQ(e.kind, EdgeKind::Open);
  expect_valid_layout(layout, strips, options);
}

// 600 mm of strip on A4: split at rulings (inner edges across the strip) into pieces that
// fit, each cut a new seam with its own label pair and tab.
TEST(LayoutPages, LongStripIsSplitAtRulingsIntoPiecesThatFit) {
  const std::vector<FlatStrip> strips = {cell_strip(7, 60, 1, 10, 20)};
  LayoutOptions options;
  options.scale = 1;
  EXPECT_EQ(strips_exceeding_page(strips, options), std::vector<int>{7});
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  const auto pieces = pieces_of(layout, 7);
  ASSERT_EQ(pieces.size(), 3u);
  std::set<std::string> numbers;
  std::map<std::string, int> seam_edges;
  for (const PlacedPiece* piece : pieces) {
    EXPECT_EQ(piece->piece_count, 3);
    numbers.insert(piece->number.text);
    for (const PlacedEdge& e : piece->edges)
      if (e.kind == EdgeKind::Seam) {
        ++seam_edges[e.label];
        EXPECT_NEAR((e.a - e.b).norm(), 20.0, 1e-9);  // one ruling
      }
  }
  EXPECT_EQ(numbers, (std::set<std::string>{"1a", "1b", "1c"}));
  // Balanced: about 200 mm each, not two full pages and a 90 mm remainder (greedy).
  for (const PlacedPiece* piece : pieces) {
    Vec2 lo = piece->vertices[0], hi = lo;
    for (const Vec2& v : piece->vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    EXPECT_GE((hi - lo).maxCoeff(), 0.5 * (297 - 2 * options.margin_mm)) << piece->number.text;
  }
  EXPECT_EQ(seam_edges.size(), 2u);
  for (const auto& [label, count] : seam_edges) EXPECT_EQ(count, 2) << label;
  ASSERT_FALSE(layout.warnings.empty());
  EXPECT_NE(layout.warnings[0].find("strip 7"), std::string::npos);
  // A short strip is left whole.
  EXPECT_TRUE(strips_exceeding_page({cell_strip(8, 20, 1, 10, 20)}, options).empty());
}

// A 300 degree annulus, 340 mm across: split along its arc into pieces that fit.
TEST(LayoutPages, CurvedStripIsSplitIntoPiecesThatFit) {
  const std::vector<FlatStrip> strips = {arc_strip(2, 150, 170, 300 * M_PI / 180, 120)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  const auto pieces = pieces_of(layout, 2);
  ASSERT_GE(pieces.size(), 2u);
  // Balanced: no piece is a sliver next to the others.
  std::vector<double> areas;
  for (const PlacedPiece* piece : pieces) {
    double area = 0;
    for (const Triangle& t : piece->triangles)
      area += 0.5 * std::abs(cross(piece->vertices[t[1]] - piece->vertices[t[0]],
                                   piece->vertices[t[2]] - piece->vertices[t[0]]));
    areas.push_back(area);
  }
  EXPECT_GE(*std::min_element(areas.begin(), areas.end()),
            0.6 * *std::max_element(areas.begin(), areas.end()));
}

// Long thin arcs (C shapes) that fit the page one at a time: laid out again with each split
// in halves that fit half a page, they need fewer pages, and the layout keeps that (every
// split strip printed as Na and Nb, a note saying so); with split_long_strips off it does not.
// Four arcs of 270 degrees between radii r and r + 10 mm, at 1:1, laid out without and with
// split_long_strips (each layout checked valid).
std::pair<PatternLayout, PatternLayout> arcs_without_and_with_split(
    double r, int segments, std::vector<FlatStrip>& strips) {
  for (int k = 0; k < 4; ++k) strips.push_back(arc_strip(k, r, r + 10, 270 * M_PI / 180, segments));
  LayoutOptions options;
  options.scale = 1;
  options.split_long_strips = false;
  PatternLayout without = layout_pages(strips, options);
  expect_valid_layout(without, strips, options);
  options.split_long_strips = true;
  PatternLayout with = layout_pages(strips, options);
  expect_valid_layout(with, strips, options);
  return {std::move(without), std::move(with)};
}

TEST(LayoutPages, LongThinStripsAreSplitWhereThatSavesPages) {
  std::vector<FlatStrip> strips;  // four C shapes 180 mm across: one per page
  const auto [whole, split] = arcs_without_and_with_split(80, 60, strips);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(pieces_of(whole, k).size(), 1u);
  EXPECT_LT(split.pages.size(), whole.pages.size());
  for (int k = 0; k < 4; ++k) {
    const auto pieces = pieces_of(split, k);
    ASSERT_EQ(pieces.size(), 2u) << "strip " << k;
    EXPECT_EQ(pieces[0]->name.back() == 'a' ? pieces[1]->name.back() : pieces[0]->name.back(), 'b');
  }
  EXPECT_TRUE(std::any_of(split.warnings.begin(), split.warnings.end(), [](const std::string& w) {
    return w.find("split in parts of half a page") != std::string::npos;
  }));
  std::cout << "[ pages    ] long arcs: " << whole.pages.size() << " pages whole, "
            << split.pages.size() << " split\n";
}

// Arcs larger than the page: split only to fit it, each part is still a wide bend that packs
// alone; in parts of half a page they pack together.
// splits_per_page bounds what a page saved may cost: the four arcs above save pages only by
// splitting all four, more than one per page saved, so with splits_per_page 1 they stay whole.
TEST(LayoutPages, SplitsPerPageBoundsTheStripsSplitForAPageSaved) {
  std::vector<FlatStrip> strips;
  const auto [whole, split] = arcs_without_and_with_split(80, 60, strips);
  const int saved = static_cast<int>(whole.pages.size() - split.pages.size());
  ASSERT_GT(saved, 0);
  ASSERT_LT(saved, 4);
  LayoutOptions options;
  options.scale = 1;
  options.splits_per_page = 1;
  const PatternLayout strict = layout_pages(strips, options);
  expect_valid_layout(strict, strips, options);
  EXPECT_EQ(strict.pages.size(), whole.pages.size());
  for (int k = 0; k < 4; ++k) EXPECT_EQ(pieces_of(strict, k).size(), 1u) << "strip " << k;
  options.splits_per_page = 0;
  EXPECT_THROW(layout_pages(strips, options), InvalidInputException);
}

TEST(LayoutPages, LongThinStripsLargerThanThePageAreSplitSmallerWhereThatSavesPages) {
  std::vector<FlatStrip> strips;  // four C shapes 320 mm across
  const auto [page_parts, half_parts] = arcs_without_and_with_split(150, 90, strips);
  EXPECT_LT(half_parts.pages.size(), page_parts.pages.size());
  // Some arcs in more pieces (in halves of a page or where they bend), none in fewer.
  std::size_t more = 0;
  for (int k = 0; k < 4; ++k) {
    EXPECT_GE(pieces_of(half_parts, k).size(), pieces_of(page_parts, k).size()) << "strip " << k;
    more += pieces_of(half_parts, k).size() - pieces_of(page_parts, k).size();
  }
  EXPECT_GT(more, 0u);
  std::cout << "[ pages    ] arcs larger than the page: " << page_parts.pages.size()
            << " pages split for the page, " << half_parts.pages.size() << " in half pages\n";
}

// A strip bent like an L (legs 220 and 100 mm, 20 mm wide), a U (legs 100, 200 and 100 mm) and
// a straight bar (300 x 20 mm) of 10 mm cells at 1:1: split where they bend, the L gives two
// straight parts, the U three, the bar stays whole; the parts cover every triangle once, each
// is connected and straight (its tightest rectangle at most 1.5 times its area), and every
// edge between two parts carries a split label.
TEST(LayoutSplit, StripsAreSplitWhereTheyBend) {
  auto parts_of = [](const FlatStrip& strip, std::size_t expected) {
    layout_internal::StripData data = layout_internal::prepare_strip(strip, 1.0);
    std::set<std::string> used;
    const auto sets = layout_internal::split_at_bends(data, used);
    ASSERT_EQ(sets.size(), expected) << "strip " << strip.id;
    std::vector<int> all;
    std::map<int, std::size_t> part_of;
    for (std::size_t k = 0; k < sets.size(); ++k) {
      double area = 0;
      for (int t : sets[k]) {
        const Triangle& tri = strip.triangles[t];
        area += 0.5 * std::abs(cross(strip.vertices2d[tri[1]] - strip.vertices2d[tri[0]],
                                     strip.vertices2d[tri[2]] - strip.vertices2d[tri[0]]));
        all.push_back(t);
        part_of[t] = k;
      }
      bool unused = false;
      const auto box = layout_internal::tightest_box(
          layout_internal::convex_hull(layout_internal::piece_points(data, sets[k])), -1, -1,
          &unused);
      EXPECT_LE(box.size.prod(), 1.5 * area) << "strip " << strip.id << " part " << k;
    }
    std::sort(all.begin(), all.end());
    std::vector<int> every(strip.triangles.size());
    std::iota(every.begin(), every.end(), 0);
    EXPECT_EQ(all, every);
    // Every inner edge between two parts is labelled as a split seam.
    std::map<std::pair<int, int>, int> owner;
    for (int t = 0; t < static_cast<int>(strip.triangles.size()); ++t)
      for (int i = 0; i < 3; ++i)
        owner[{strip.triangles[t][i], strip.triangles[t][(i + 1) % 3]}] = t;
    int cut_edges = 0;
    for (const auto& [edge, t] : owner) {
      auto twin = owner.find({edge.second, edge.first});
      if (twin == owner.end() || part_of[t] == part_of[twin->second]) continue;
      ++cut_edges;
      const auto key =
          directed_edge_key(std::min(edge.first, edge.second), std::max(edge.first, edge.second));
      EXPECT_TRUE(data.split_label.count(key)) << edge.first << "-" << edge.second;
    }
    EXPECT_EQ(cut_edges > 0, expected > 1);
  };
  parts_of(cell_strip(0, 22, 10, 10, 10, [](int i, int j) { return j < 2 || i >= 20; }), 2);
  parts_of(cell_strip(1, 20, 10, 10, 10, [](int i, int j) { return j < 2 || i < 2 || i >= 18; }),
           3);
  parts_of(cell_strip(2, 30, 2, 10, 10), 1);
}

// A U-shaped piece whose slot walls are glued to each other: the tab shrinks to fit in a
// 2.4 mm slot and is dropped (with a warning) in a 0.8 mm one.
TEST(LayoutPages, TabShrinksToFitAndIsDroppedWithoutRoom) {
  auto slotted = [](int slot_cells) {
    const double cell = 0.8;
    FlatStrip s = cell_strip(0, 25, 25, cell, cell, [&](int i, int j) {
      return !(i >= 10 && i < 10 + slot_cells && j >= 5);
    });
    const double left = 10 * cell, right = (10 + slot_cells) * cell;
    mark_seam(s, "S", 0, [&](const Vec2& m) {
      return (std::abs(m.x() - left) < 1e-9 || std::abs(m.x() - right) < 1e-9) && m.y() > 5 * cell;
    });
    return std::vector<FlatStrip>{s};
  };
  LayoutOptions options;
  options.scale = 1;
  const auto wide = slotted(3);
  PatternLayout layout = layout_pages(wide, options);
  expect_valid_layout(layout, wide, options);
  const PlacedPiece& piece = layout.pages.at(0).pieces.at(0);
  ASSERT_EQ(piece.tabs.size(), 1u);
  EXPECT_TRUE(layout.warnings.empty()) << (layout.warnings.empty() ? "" : layout.warnings[0]);

  // In the 0.8 mm slot no tab fits: the seam (16 mm long) gets a joining strip instead, a
  // loose 18 x 10 mm strip named S to glue behind both walls.
  const auto narrow = slotted(1);
  layout = layout_pages(narrow, options);
  expect_valid_layout(layout, narrow, options);
  EXPECT_TRUE(layout.pages.at(0).pieces.at(0).tabs.empty());
  ASSERT_EQ(layout.warnings.size(), 2u);
  EXPECT_NE(layout.warnings[0].find("no room"), std::string::npos);
  EXPECT_NE(layout.warnings[1].find("joining strip"), std::string::npos);
  EXPECT_EQ(layout.stats.seams, 1);
  EXPECT_EQ(layout.stats.seams_without_tab, 0);
  EXPECT_EQ(layout.stats.joining_strips, 1);
  int joints = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& joint : page.joints) {
      ++joints;
      EXPECT_EQ(joint.name, "S");
      EXPECT_EQ(joint.number.text, "S");
      const double a = (joint.vertices[1] - joint.vertices[0]).norm();
      const double b = (joint.vertices[2] - joint.vertices[1]).norm();
      EXPECT_NEAR(std::max(a, b), 18.0, 1e-9);
      EXPECT_NEAR(std::min(a, b), 2 * options.tab_width_mm, 1e-9);
      ASSERT_EQ(joint.marks.size(), 2u);  // the centre line, cut around the name
    }
  EXPECT_EQ(joints, 1);

  // Without joining strips the seam is named as having none.
  options.joining_strips = false;
  layout = layout_pages(narrow, options);
  expect_valid_layout(layout, narrow, options);
  EXPECT_EQ(layout.stats.seams_without_tab, 1);
  EXPECT_EQ(layout.stats.joining_strips, 0);
  ASSERT_EQ(layout.warnings.size(), 1u);
  EXPECT_NE(layout.warnings[0].find("no room"), std::string::npos);
}

// Two pieces, each with a notch, glued along one straight wall of each: the notch's other side
// bulges to 0.6 mm from the wall near its bottom, so no flap fits along the whole wall; the
// wall that takes the tab takes it on its half at the notch's mouth, where there is room, and
// the cut line runs along the rest of it.
TEST(LayoutPages, BlockedWallTakesATabOnPartOfIt) {
  const std::vector<Vec2> outline = {Vec2(0, 0),   Vec2(40, 0),    Vec2(40, 40),
                                     Vec2(22, 40), Vec2(20.3, 14), Vec2(21, 12),
                                     Vec2(20, 10), Vec2(18, 40),   Vec2(0, 40)};
  const std::vector<Triangle> triangles = {{1, 2, 3}, {1, 3, 4}, {1, 4, 5}, {1, 5, 6},
                                           {0, 1, 6}, {0, 6, 7}, {0, 7, 8}};
  // The first piece as drawn; the second its mirror image, the same surface seen from the other
  // side in 3D, so that its mirrored wall is the first's wall reversed.
  auto notched = [&](int id) {
    FlatStrip v;
    v.id = v.source_strip = id;
    for (const Vec2& p : outline) {
      v.vertices2d.push_back(id == 0 ? p : Vec2(40 - p.x(), p.y()));
      v.vertices3d.emplace_back(p.x(), p.y(), 0.0);
    }
    for (Triangle t : triangles) {
      if (id == 1) std::swap(t[1], t[2]);
      v.triangles.push_back(t);
    }
    v.boundary = testing::open_boundary(v.triangles);
    const Vec2 wall_middle(id == 0 ? 19.0 : 21.0, 25.0);
    mark_seam(v, "V", 1 - id, [&](const Vec2& m) { return (m - wall_middle).norm() < 1e-9; });
    return v;
  };
  const std::vector<FlatStrip> strips{notched(0), notched(1)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.seams, 1);
  EXPECT_EQ(layout.stats.seams_without_tab, 0);
  EXPECT_EQ(layout.stats.joining_strips, 0) << "a tab fits on part of the wall";
  int flaps = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      if (piece.tabs.empty()) continue;
      ASSERT_EQ(piece.tabs.size(), 1u);
      ASSERT_EQ(piece.tabs[0].bases.size(), 1u);
      ++flaps;
      const auto& base = piece.tabs[0].bases[0];
      ASSERT_EQ(base.size(), 2u);
      EXPECT_NEAR((base[1] - base[0]).norm(), 0.5 * std::hypot(2.0, 30.0), 1e-9) << "half a wall";
      // The cut line passes through both ends of the flap's base.
      ASSERT_EQ(piece.cut_outline.size(), 1u);
      for (const Vec2& q : base) {
        bool on_cut = false;
        for (const Vec2& c : piece.cut_outline[0]) on_cut = on_cut || (c - q).norm() < 1e-9;
        EXPECT_TRUE(on_cut) << q.transpose();
      }
    }
  EXPECT_EQ(flaps, 1);
}

// A seam 1.5 mm long takes no flap of the smallest height (1 mm) at 45 degrees; steeper
// ends give it one.
TEST(LayoutPages, ShortSeamGetsASteeperTab) {
  FlatStrip a = cell_strip(0, 1, 4, 1.5, 5.0), b = cell_strip(1, 1, 4, 1.5, 5.0);
  mark_seam(a, "S", 1, [](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
  mark_seam(b, "S", 0, [](const Vec2& m) { return std::abs(m.y() - 20.0) < 1e-9; });
  const std::vector<FlatStrip> strips{a, b};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.seams, 1);
  EXPECT_EQ(layout.stats.seams_without_tab, 0);
}

// Strips too narrow for a seam label (1.5 mm at 2 mm text): the labels are printed beside
// their pieces, on no piece and over no other text, and the nesting keeps other pieces off them.
TEST(LayoutPages, LabelsWithoutRoomOnTheirPieceArePrintedBesideIt) {
  std::vector<FlatStrip> strips;
  for (int k = 0; k < 12; ++k) {
    FlatStrip s = cell_strip(k, 12, 1, 5.0, 1.5);
    std::string label = "N";
    label += std::to_string(k / 2);
    if (k % 2 == 0)
      mark_seam(s, label, k + 1, [&](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
    else
      mark_seam(s, label, k - 1, [&](const Vec2& m) { return std::abs(m.y() - 1.5) < 1e-9; });
    strips.push_back(s);
  }
  LayoutOptions options;
  options.scale = 1;
  options.tab_width_mm = 0;  // no tab to carry the label either
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  int outside = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces)
      for (const Label& label : piece.labels) outside += label.outside ? 1 : 0;
  EXPECT_EQ(outside, 12);
  EXPECT_EQ(layout.stats.overlapping_text, 0);
}

// A seam at the bottom of a slot 1.5 mm wide and 19.5 mm deep, on a comb whose teeth are
// 1.5 mm wide too: no room for its label on the piece, on a tab or beside the seam, so it is
// printed beyond the slot with a leader line from the seam's middle that touches no piece and
// no other text.
// A comb of 1.5 mm cells (nx by 14, the cells where keep(i, j)) whose seam S12 is the edge
// from (1.5, 1.5) to (3, 1.5), at the bottom of a slot in column 1; and a 20 mm block glued to
// it there (its seam edge shortened to the same 1.5 mm).
std::vector<FlatStrip> slot_and_block(int nx, const std::function<bool(int, int)>& keep) {
  FlatStrip comb = cell_strip(0, nx, 14, 1.5, 1.5, keep);
  mark_seam(comb, "S12", 1, [](const Vec2& m) {
    return std::abs(m.y() - 1.5) < 1e-9 && std::abs(m.x() - 2.25) < 1e-9;
  });
  FlatStrip block = cell_strip(1, 4, 4, 5.0, 5.0);
  mark_seam(block, "S12", 0,
            [](const Vec2& m) { return std::abs(m.y()) < 1e-9 && std::abs(m.x() - 2.5) < 1e-9; });
  for (Vec2& v : block.vertices2d)
    if (std::abs(v.y()) < 1e-9 && (std::abs(v.x() - 0.0) < 1e-9 || std::abs(v.x() - 5.0) < 1e-9))
      v.x() = v.x() < 1 ? 1.75 : 3.25;
  for (std::size_t i = 0; i < block.vertices2d.size(); ++i)
    block.vertices3d[i] = Vec3(block.vertices2d[i].x(), block.vertices2d[i].y(), 0.0);
  return {comb, block};
}

TEST(LayoutPages, LabelInANarrowSlotGetsALeaderLine) {
  const std::vector<FlatStrip> strips =
      slot_and_block(3, [](int i, int j) { return i != 1 || j == 0; });
  const FlatStrip& comb = strips[0];
  LayoutOptions options;
  options.scale = 1;
  options.tab_width_mm = 0;  // no tab to carry the label
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.overlapping_text, 0);
  int leaders = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      if (piece.strip_id != 0) continue;
      ASSERT_EQ(piece.labels.size(), 1u);
      const Label& label = piece.labels[0];
      ASSERT_EQ(label.leader.size(), 2u) << "no leader line";
      ++leaders;
      EXPECT_TRUE(label.outside);
      // It starts at the seam's middle: the comb's page vertex of (2.25, 1.5).
      Vec2 seam_middle = Vec2::Zero();
      for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
        const Vec2 strip_point = comb.vertices2d[piece.strip_vertex[v]];
        if ((strip_point - Vec2(1.5, 1.5)).norm() < 1e-9 ||
            (strip_point - Vec2(3.0, 1.5)).norm() < 1e-9)
          seam_middle += 0.5 * piece.vertices[v];
      }
      EXPECT_LT((label.leader.front() - seam_middle).norm(), 1e-6);
      // It runs out of the slot on no piece, and ends at the text, clear of it.
      for (int k = 1; k <= 20; ++k) {
        const Vec2 point =
            label.leader.front() + (k / 20.0) * (label.leader.back() - label.leader.front());
        for (const PlacedPiece& other : page.pieces)
          EXPECT_FALSE(on_piece(point, other) && k > 1)
              << "leader crosses strip " << other.strip_id;
      }
      const auto box = label_box(label);
      const double to_text = (label.leader.back() - label.position).norm();
      EXPECT_LT(to_text, (box[2] - box[0]).norm()) << "leader ends far from its text";
      EXPECT_GT((label.leader.back() - label.leader.front()).norm(), 18.0)
          << "the slot is 19.5 mm deep";
    }
  EXPECT_EQ(leaders, 1);
}

// The same seam at the bottom of a slot that bends (up 13.5 mm, right 3 mm, up and out) in a
// piece whose arms are at most 3 mm wide: the only paper with room for the label is the block
// of 4.5 x 4.5 mm beyond the bend, and no straight line reaches it from the seam, nor free
// paper off the piece. So the leader bends (more than two points), still crossing no cut
// line and no text.
TEST(LayoutPages, LabelInABentSlotGetsALeaderThatBends) {
  auto slot = [](int i, int j) {
    return (i == 1 && j >= 1 && j <= 10) || (j == 10 && i >= 1 && i <= 3) || (i == 3 && j >= 10);
  };
  const std::vector<FlatStrip> strips =
      slot_and_block(5, [&](int i, int j) { return !slot(i, j); });
  LayoutOptions options;
  options.scale = 1;
  options.tab_width_mm = 0;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.stats.overlapping_text, 0);
  int bent = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      if (piece.strip_id != 0) continue;
      ASSERT_EQ(piece.labels.size(), 1u);
      EXPECT_GT(piece.labels[0].leader.size(), 2u) << "the leader does not bend";
      bent += piece.labels[0].leader.size() > 2 ? 1 : 0;
    }
  EXPECT_EQ(bent, 1);
}

// Random rectangles seamed in pairs along their long sides, random scale: valid layouts.
TEST(LayoutPages, RandomStripsWithSeamsKeepEveryInvariant) {
  std::mt19937 random(12345);
  std::uniform_int_distribution<int> cells(1, 8);
  std::uniform_real_distribution<double> size(3.0, 25.0);
  int pages = 0, shelf_pages = 0;
  for (int round = 0; round < 4; ++round) {
    std::vector<FlatStrip> strips;
    for (int k = 0; k < 24; ++k) {
      const int nx = cells(random), ny = cells(random);
      const double w = size(random), h = size(random);
      FlatStrip s = cell_strip(k, nx, ny, w, h);
      std::string label = "P";
      label += std::to_string(k / 2);
      if (k % 2 == 0)
        mark_seam(s, label, k + 1, [&](const Vec2& m) { return std::abs(m.y()) < 1e-9; });
      else
        mark_seam(s, label, k - 1, [&](const Vec2& m) { return std::abs(m.y() - ny * h) < 1e-9; });
      strips.push_back(s);
    }
    LayoutOptions options;
    options.scale = 0.5 + 0.25 * round;
    const PatternLayout layout = layout_pages(strips, options);
    expect_valid_layout(layout, strips, options);
    EXPECT_LE(static_cast<int>(layout.pages.size()), layout.shelf_page_count);
    pages += static_cast<int>(layout.pages.size());
    shelf_pages += layout.shelf_page_count;
  }
  std::cout << "[ pages    ] layout " << pages << ", shelf " << shelf_pages
            << " on 4 sets of 24 seamed strips\n";
}

// The nesting tries three orders (by area, longest side, bounding rectangle) and keeps the best
// fill: never more pages than the area order alone, and on random sets of long bars, squares
// and triangles sometimes fewer pages or an emptier last page.
TEST(LayoutNesting, ThreeOrdersNeverLoseToOne) {
  using layout_internal::NestOptions;
  using layout_internal::NestShape;
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec2 area(190, 270);
  int better = 0;
  for (int round = 0; round < 8; ++round) {
    std::vector<NestShape> shapes;
    for (int k = 0; k < 18; ++k) {
      const double a = 120 + 60 * unit(random), b = 30 + 50 * unit(random);
      NestShape shape;
      switch (k % 3) {
        case 0:  // a long bar
          shape.convex.push_back({Vec2(0, 0), Vec2(a, 0), Vec2(a, 12), Vec2(0, 12)});
          break;
        case 1:  // a square
          shape.convex.push_back({Vec2(0, 0), Vec2(b, 0), Vec2(b, b), Vec2(0, b)});
          break;
        default:  // a right triangle
          shape.convex.push_back({Vec2(0, 0), Vec2(0.5 * a, 0), Vec2(0, b)});
      }
      shapes.push_back(std::move(shape));
    }
    NestOptions one, three;
    one.rotations = three.rotations = 8;
    one.cell_mm = three.cell_mm = 1.0;
    one.orders = 1;
    three.orders = 3;
    int pages_one = 0, pages_three = 0;
    const auto by_one = layout_internal::nest_shapes(shapes, area, one, &pages_one);
    const auto by_three = layout_internal::nest_shapes(shapes, area, three, &pages_three);
    EXPECT_LE(pages_three, pages_one) << "round " << round;
    auto last_area = [&](const std::vector<layout_internal::NestPlacement>& placements, int pages) {
      double sum = 0;
      for (std::size_t i = 0; i < shapes.size(); ++i)
        if (placements[i].page == pages - 1)
          sum += std::abs(layout_internal::signed_area(shapes[i].convex[0]));
      return sum;
    };
    if (pages_three < pages_one ||
        last_area(by_three, pages_three) < last_area(by_one, pages_one) - 1e-9)
      ++better;
    for (const auto& placement : by_three) EXPECT_GE(placement.page, 0);
  }
  EXPECT_GE(better, 1) << "the other orders never helped";
  std::cout << "[ orders   ] three orders did better on " << better << " of 8 sets\n";
}

// Half rings (arcs packed by rectangles leave their insides empty): nesting keeps the
// spacing between any two pieces, measured exactly on their triangles and tab flaps, and never
// needs more pages than the rectangle packer; on arcs it needs fewer.
// Six regions of a model, each a large piece (100 x 120 mm) glued to two small ones
// (40 x 50 mm), given region by region: largest first puts the large pieces two to a page and
// the small ones after them, mostly away from their partner; the fill in the given order, in
// runs of half a page, puts every small piece on its partner's page, on as many pages. Without
// neighbours it is not tried; on random shapes it never costs a page or parts neighbours.
TEST(LayoutNesting, PiecesGluedToEachOtherStayOnOnePageWhereThatCostsNoPage) {
  using layout_internal::NestOptions;
  using layout_internal::NestShape;
  auto rectangle = [](double w, double h) {
    NestShape shape;
    shape.convex.push_back({Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)});
    return shape;
  };
  const Vec2 area(190, 277);
  std::vector<NestShape> shapes;
  NestOptions options;
  options.rotations = 4;
  options.cell_mm = 1.0;
  for (int region = 0; region < 6; ++region) {
    const int big = static_cast<int>(shapes.size());
    shapes.push_back(rectangle(100, 120));
    for (int k = 0; k < 2; ++k) {
      options.neighbours.push_back({big, static_cast<int>(shapes.size())});
      shapes.push_back(rectangle(40, 50));
    }
  }
  auto together = [&](const std::vector<layout_internal::NestPlacement>& placements) {
    int count = 0;
    for (const auto& [a, b] : options.neighbours) count += placements[a].page == placements[b].page;
    return count;
  };
  NestOptions plain = options;
  plain.grouped = false;
  int pages_plain = 0, pages_grouped = 0;
  const auto apart = layout_internal::nest_shapes(shapes, area, plain, &pages_plain);
  const auto near = layout_internal::nest_shapes(shapes, area, options, &pages_grouped);
  EXPECT_EQ(pages_grouped, pages_plain);
  EXPECT_LT(together(apart), 12);
  EXPECT_EQ(together(near), 12);
  std::cout << "[ nesting  ] glued pairs on one page: " << together(apart)
            << " of 12 largest first, " << together(near) << " in runs\n";
  // Random shapes glued in a chain: never more pages, never fewer pairs on one page.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> side(20.0, 120.0);
  for (int round = 0; round < 4; ++round) {
    std::vector<NestShape> chain;
    NestOptions glued;
    glued.rotations = 8;
    glued.cell_mm = 1.0;
    for (int k = 0; k < 16; ++k) {
      chain.push_back(rectangle(side(random), side(random)));
      if (k > 0) glued.neighbours.push_back({k - 1, k});
    }
    NestOptions loose = glued;
    loose.grouped = false;
    int p_loose = 0, p_glued = 0;
    const auto a = layout_internal::nest_shapes(chain, area, loose, &p_loose);
    const auto b = layout_internal::nest_shapes(chain, area, glued, &p_glued);
    EXPECT_LE(p_glued, p_loose) << "round " << round;
    int near_a = 0, near_b = 0;
    for (const auto& [x, y] : glued.neighbours) {
      near_a += a[x].page == a[y].page;
      near_b += b[x].page == b[y].page;
    }
    EXPECT_GE(near_b, near_a) << "round " << round;
  }
}

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t =
      d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - a - t * d).norm();
}

double polygon_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) {
      best = std::min(best, segment_distance(a[i], b[j], b[(j + 1) % b.size()]));
      best = std::min(best, segment_distance(b[j], a[i], a[(i + 1) % a.size()]));
    }
  return best;
}

FlatStrip half_ring(int id, double inner, double outer, int segments) {
  FlatStrip s;
  s.id = id;
  for (int k = 0; k <= segments; ++k) {
    const double angle = std::numbers::pi * k / segments;
    for (double r : {inner, outer}) {
      const Vec2 p(r * std::cos(angle), r * std::sin(angle));
      s.vertices2d.push_back(p);
      s.vertices3d.emplace_back(p.x(), p.y(), 0.0);
    }
  }
  for (int k = 0; k < segments; ++k) {
    const int a = 2 * k, b = 2 * k + 1, c = 2 * k + 2, d = 2 * k + 3;
    s.triangles.push_back({a, b, c});
    s.triangles.push_back({b, d, c});
  }
  s.boundary = flat_boundary(s.triangles);
  for (BoundaryEdge& e : s.boundary) e.kind = EdgeKind::Open;
  return s;
}

TEST(LayoutPages, NestingKeepsTheGapAndNeedsNoMorePagesThanRectangles) {
  std::vector<FlatStrip> strips;
  for (int k = 0; k < 30; ++k)
    strips.push_back(half_ring(k, 30 + (k % 5) * 4, 40 + (k % 5) * 4, 24));
  LayoutOptions options;
  options.scale = 1;
  options.spacing_mm = 2;
  const PatternLayout nested = layout_pages(strips, options);
  expect_valid_layout(nested, strips, options);
  options.packing = PackingMethod::MaxRects;
  const PatternLayout boxed = layout_pages(strips, options);
  EXPECT_LE(nested.pages.size(), boxed.pages.size());
  EXPECT_LT(nested.pages.size(), boxed.pages.size()) << "nested arcs must save paper";
  EXPECT_EQ(nested.rectangle_page_count, static_cast<int>(boxed.pages.size()));
  for (const Page& page : nested.pages) {
    std::vector<std::vector<std::vector<Vec2>>> shapes;  // per piece: its polygons
    for (const PlacedPiece& piece : page.pieces) {
      std::vector<std::vector<Vec2>> polygons;
      for (const Triangle& t : piece.triangles)
        polygons.push_back({piece.vertices[t[0]], piece.vertices[t[1]], piece.vertices[t[2]]});
      for (const Tab& tab : piece.tabs)
        for (const auto& flap : tab.flaps) polygons.push_back(flap);
      shapes.push_back(std::move(polygons));
    }
    for (std::size_t i = 0; i < shapes.size(); ++i)
      for (std::size_t j = i + 1; j < shapes.size(); ++j)
        for (const auto& a : shapes[i])
          for (const auto& b : shapes[j])
            ASSERT_GE(polygon_distance(a, b), options.spacing_mm - 1e-6)
                << "pieces " << page.pieces[i].name << " and " << page.pieces[j].name;
  }
  std::cout << "[ pages    ] nested " << nested.pages.size() << ", rectangles "
            << boxed.pages.size() << " for 30 half rings\n";
}

// Rectangles' pages: MaxRects never worse than the shelf baseline; rectangles keep the
// spacing and stay in their bin.
TEST(LayoutPages, PackerNeverNeedsMorePagesThanShelf) {
  std::mt19937 random(777);
  int total_packed = 0, total_shelf = 0;
  for (int round = 0; round < 30; ++round) {
    std::uniform_real_distribution<double> side(5.0, round % 2 ? 180.0 : 90.0);
    std::vector<Vec2> sizes;
    for (int k = 0; k < 40; ++k) sizes.emplace_back(side(random), side(random));
    const double w = 190, h = 267, spacing = 2;
    const auto placed = pack_rectangles(sizes, w, h, spacing, PackingMethod::MaxRects);
    int pages = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      pages = std::max(pages, placed[i].page + 1);
      const Vec2 size_i = placed[i].rotated ? Vec2(sizes[i].y(), sizes[i].x()) : sizes[i];
      EXPECT_GE(placed[i].x, -1e-9);
      EXPECT_GE(placed[i].y, -1e-9);
      EXPECT_LE(placed[i].x + size_i.x(), w + 1e-6);
      EXPECT_LE(placed[i].y + size_i.y(), h + 1e-6);
      for (std::size_t j = 0; j < i; ++j) {
        if (placed[i].page != placed[j].page) continue;
        const Vec2 size_j = placed[j].rotated ? Vec2(sizes[j].y(), sizes[j].x()) : sizes[j];
        const bool apart = placed[i].x + size_i.x() + spacing <= placed[j].x + 1e-6 ||
                           placed[j].x + size_j.x() + spacing <= placed[i].x + 1e-6 ||
                           placed[i].y + size_i.y() + spacing <= placed[j].y + 1e-6 ||
                           placed[j].y + size_j.y() + spacing <= placed[i].y + 1e-6;
        EXPECT_TRUE(apart) << "rectangles " << i << " and " << j;
      }
    }
    const int shelf = shelf_pack_page_count(sizes, w, h, spacing);
    EXPECT_LE(pages, shelf);
    total_packed += pages;
    total_shelf += shelf;
  }
  EXPECT_LT(total_packed, total_shelf);
  std::cout << "[ pages    ] MaxRects " << total_packed << ", shelf " << total_shelf
            << " on 30 random sets of 40 rectangles\n";
}

// One tall piece and six small ones: shelves waste the height beside the tall piece
// (2 pages); MaxRects stacks the small ones beside it (1 page).
TEST(LayoutPages, PackerBeatsShelfOnTallAndSmallPieces) {
  std::vector<FlatStrip> strips = {cell_strip(0, 1, 5, 120, 50)};
  for (int k = 1; k <= 6; ++k) strips.push_back(cell_strip(k, 3, 2, 20, 20));
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  expect_valid_layout(layout, strips, options);
  EXPECT_EQ(layout.pages.size(), 1u);
  EXPECT_EQ(layout.shelf_page_count, 2);
  options.packing = PackingMethod::Shelf;
  EXPECT_EQ(layout_pages(strips, options).pages.size(), 2u);
}

TEST(LayoutPages, OversizedTriangleOverflowsWithWarning) {
  const std::vector<FlatStrip> strips = {cell_strip(0, 1, 1, 400, 400)};
  LayoutOptions options;
  options.scale = 1;
  options.packing = PackingMethod::MaxRects;  // nesting divides the triangles (below)
  const PatternLayout layout = layout_pages(strips, options);
  EXPECT_EQ(layout.pages.size(), 2u);  // split into its two triangles, each alone
  bool overflow = false;
  for (const std::string& w : layout.warnings) overflow |= w.find("overflows") != std::string::npos;
  EXPECT_TRUE(overflow);
}

// The same square with nesting: its triangles are divided (each edge in n equal parts) and the
// strip cut across them into pieces that fit the page, along the divided cells' edges: no piece
// overflows, each is a rectangle (4 corners), and the surface is laid out whole.
TEST(LayoutPages, TriangleLargerThanThePageIsCutAcrossItsDividedTriangles) {
  const std::vector<FlatStrip> strips = {cell_strip(0, 1, 1, 400, 400)};
  LayoutOptions options;
  options.scale = 1;
  const PatternLayout layout = layout_pages(strips, options);
  bool divided = false;
  for (const std::string& w : layout.warnings) {
    EXPECT_EQ(w.find("overflows"), std::string::npos) << w;
    divided = divided || w.rfind("triangles divided", 0) == 0;
  }
  EXPECT_TRUE(divided);
  expect_valid_layout(layout, strips, options);
  int pieces = 0;
  for (const Page& page : layout.pages)
    for (const PlacedPiece& piece : page.pieces) {
      ++pieces;
      ASSERT_EQ(piece.outline.size(), 1u);
      // Corners: outline points where the direction turns.
      const auto& loop = piece.outline[0];
      int corners = 0;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 a = loop[(i + loop.size() - 1) % loop.size()], b = loop[i],
                   c = loop[(i + 1) % loop.size()];
        corners += std::abs(cross((b - a).normalized(), (c - b).normalized())) > 1e-6;
      }
      EXPECT_EQ(corners, 4) << "piece " << piece.name;
      EXPECT_NE(piece.strip_vertex.end(),
                std::find(piece.strip_vertex.begin(), piece.strip_vertex.end(), -1));
    }
  // 400 x 400 mm on pages of 178 x 256 mm (room for tabs kept): two slabs of 200 x 400 mm,
  // each cut in three of 133 x 200 mm (10 x 10 cells of 40 mm: cut along cell edges).
  EXPECT_EQ(pieces, 6);
  EXPECT_EQ(static_cast<int>(layout.pages.size()), 6);
}

// Both sides of every seam of divided strips get the same points (bit for bit), and the surface and
// its flat image are kept: each new triangle is an isometric copy (flat edges as long as 3D ones).
TEST(LayoutDivide, BothSidesOfEverySeamGetTheSamePoints) {
  // Scaled to coordinates no binary fraction is, and every other strip's vertices numbered
  // backwards: the two sides of a seam see its ends in opposite index order.
  auto strips = prism_strips(square_footprint(40), 60, 0);
  for (std::size_t k = 0; k < strips.size(); ++k) {
    FlatStrip& s = strips[k];
    for (Vec3& v : s.vertices3d) v *= 0.37;
    for (Vec2& v : s.vertices2d) v *= 0.37;
    if (k % 2 == 1) continue;
    const int last = static_cast<int>(s.vertices3d.size()) - 1;
    std::reverse(s.vertices3d.begin(), s.vertices3d.end());
    std::reverse(s.vertices2d.begin(), s.vertices2d.end());
    for (Triangle& t : s.triangles)
      for (int& v : t) v = last - v;
    for (BoundaryEdge& e : s.boundary) e.v0 = last - e.v0, e.v1 = last - e.v1;
  }
  for (int n : {1, 2, 3, 5, 7}) {
    const auto divided = layout_internal::divide_triangles(strips, n);
    ASSERT_EQ(divided.size(), strips.size());
    std::map<int, const FlatStrip*> by_id;
    for (const FlatStrip& s : divided) by_id[s.id] = &s;
    for (std::size_t k = 0; k < strips.size(); ++k) {
      const FlatStrip &before = strips[k], &after = divided[k];
      ASSERT_EQ(after.triangles.size(), before.triangles.size() * n * n);
      ASSERT_EQ(after.boundary.size(), before.boundary.size() * n);
      double area_before = 0, area_after = 0;
      for (const Triangle& t : before.triangles)
        area_before += 0.5 * cross(before.vertices2d[t[1]] - before.vertices2d[t[0]],
                                   before.vertices2d[t[2]] - before.vertices2d[t[0]]);
      for (const Triangle& t : after.triangles) {
        const double a = 0.5 * cross(after.vertices2d[t[1]] - after.vertices2d[t[0]],
                                     after.vertices2d[t[2]] - after.vertices2d[t[0]]);
        EXPECT_GT(a, 0);  // the strip's own orientation
        area_after += a;
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR((after.vertices2d[t[i]] - after.vertices2d[t[(i + 1) % 3]]).norm(),
                      (after.vertices3d[t[i]] - after.vertices3d[t[(i + 1) % 3]]).norm(), 1e-9);
      }
      EXPECT_NEAR(area_after, area_before, 1e-9 * area_before);
      for (const BoundaryEdge& e : after.boundary) {
        if (e.kind != EdgeKind::Seam || e.partner_edge < 0) continue;
        const FlatStrip& other = *by_id.at(e.neighbour_strip);
        const BoundaryEdge& partner = other.boundary.at(e.partner_edge);
        EXPECT_EQ(partner.label, e.label);
        EXPECT_EQ(other.vertices3d[partner.v0], after.vertices3d[e.v1]);
        EXPECT_EQ(other.vertices3d[partner.v1], after.vertices3d[e.v0]);
      }
    }
    // Bit for bit: the layout pairs seam edges by their label and points. Each seam edge has
    // one edge with its label running the other way between the same points.
    using Key = std::tuple<std::string, std::array<double, 3>, std::array<double, 3>>;
    std::map<Key, int> edges;
    auto point = [](const Vec3& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
    for (const FlatStrip& s : divided)
      for (const BoundaryEdge& e : s.boundary)
        if (e.kind == EdgeKind::Seam)
          ++edges[{e.label, point(s.vertices3d[e.v0]), point(s.vertices3d[e.v1])}];
    int checked = 0;
    for (const auto& [key, count] : edges) {
      const auto& [label, a, b] = key;
      EXPECT_EQ(count, 1);
      const auto reverse = edges.find({label, b, a});
      EXPECT_TRUE(reverse != edges.end()) << "n " << n << " seam " << label;
      ++checked;
    }
    EXPECT_EQ(checked, 2 * (4 + 4 + 1) * n);  // T, B and A, each side divided in n
  }
}

// Cuts that meet near a vertex can leave a triangle many orders of magnitude below the
// strip's size; rounding decides its orientation, and it must not fail the model.
TEST(LayoutPages, VanishingSliverDoesNotFailTheLayout) {
  LayoutOptions options;
  options.scale = 1;
  FlatStrip strip;
  strip.id = 0;
  strip.source_strip = 0;
  // A (pushed past the segment E-F by 1e-11 mm, so A-E-F turns clockwise), E, B, C, D, F.
  const std::vector<Vec2> points = {{2e-11, 2e-11}, {1e-11, 0}, {10, 0},
                                    {10, 10},       {0, 10},    {0, 1e-11}};
  for (const Vec2& p : points) {
    strip.vertices2d.push_back(p);
    strip.vertices3d.emplace_back(p.x(), p.y(), 0.0);
  }
  strip.triangles = {{0, 1, 5}, {1, 2, 3}, {1, 3, 5}, {5, 3, 4}};
  strip.boundary = testing::open_boundary(strip.triangles);
  const Vec2 e1 = points[1] - points[0], e2 = points[5] - points[0];
  ASSERT_LT(e1.x() * e2.y() - e1.y() * e2.x(), 0.0);  // the sliver really is clockwise
  EXPECT_NO_THROW(layout_pages({strip}, options));

  // The same reversal at a visible size is still refused.
  FlatStrip visible = strip;
  visible.vertices2d[0] = {2, 2};
  visible.vertices2d[1] = {1, 0};
  visible.vertices2d[5] = {0, 1};
  EXPECT_THROW(layout_pages({visible}, options), InvalidInputException);
}

TEST(LayoutPages, BadInputThrows) {
  LayoutOptions options;
  options.scale = 1;
  const FlatStrip good = cell_strip(0, 2, 1, 10, 10);
  EXPECT_NO_THROW(layout_pages({good}, options));
  EXPECT_TRUE(layout_pages({}, options).pages.empty());

  FlatStrip clockwise = good;
  std::swap(clockwise.triangles[0][1], clockwise.triangles[0][2]);
  EXPECT_THROW(layout_pages({clockwise}, options), InvalidInputException);
  FlatStrip sizes = good;
  sizes.vertices3d.pop_back();
  EXPECT_THROW(layout_pages({sizes}, options), InvalidInputException);
  FlatStrip index = good;
  index.triangles[1][2] = 99;
  EXPECT_THROW(layout_pages({index}, options), InvalidInputException);
  FlatStrip inner = good;
  inner.boundary.push_back({0, 4, EdgeKind::Open, -1, ""});  // the first cell's diagonal
  EXPECT_THROW(layout_pages({inner}, options), InvalidInputException);
  EXPECT_THROW(layout_pages({good, good}, options), InvalidInputException);  // same id

  LayoutOptions bad = options;
  bad.margin_mm = -1;
  EXPECT_THROW(layout_pages({good}, bad), InvalidInputException);
  bad = options;
  bad.page = {40, 40};
  bad.margin_mm = 15;
  EXPECT_THROW(layout_pages({good}, bad), InvalidInputException);
  bad = LayoutOptions{};
  FlatStrip point = good;
  for (Vec3& v : point.vertices3d) v = Vec3::Zero();
  EXPECT_THROW(layout_scale({point}, bad), InvalidInputException);
  EXPECT_THROW(pack_rectangles({Vec2(300, 300)}, 190, 267, 2, PackingMethod::MaxRects),
               InvalidInputException);
}

}  // namespace
}  // namespace papercraft
