#include "nodes/layout/pages.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <queue>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "core/errors.h"
#include "core/edge_map.h"
#include "core/flat_boundary.h"

namespace papercraft {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kFitSlack = 1e-7;  // mm; rounding in rotations must not reject a fit
// Text boxes: an advance of 0.6 em per character (sans-serif digits and capitals) and
// 0.6 em either side of the centre line, as the exporters centre text.
constexpr double kCharWidthEm = 0.6;
constexpr double kHalfLineEm = 0.6;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

Vec2 right_normal(const Vec2& d) {
  return {d.y(), -d.x()};
}

std::string format_number(double value, int precision) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

std::string format_mm(double value) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(0);
  out << value;
  return out.str();
}

double signed_area(const std::vector<Vec2>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    area += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * area;
}

// Andrew's monotone chain; counter-clockwise, collinear points dropped.
std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// The bounding rectangle of `hull` rotated by -angle: the points p with R(-angle) p inside
// [min, min + size].
struct OrientedBox {
  double angle = 0.0;
  Vec2 min = Vec2::Zero();
  Vec2 size = Vec2::Zero();
};

OrientedBox oriented_box(const std::vector<Vec2>& hull, double angle) {
  OrientedBox box;
  box.angle = angle;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  for (const Vec2& p : hull) {
    Vec2 q = rotate(p, -angle);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  box.min = lo;
  box.size = hi - lo;
  return box;
}

bool fits_area(const Vec2& size, double width, double height) {
  return (size.x() <= width + kFitSlack && size.y() <= height + kFitSlack) ||
         (size.y() <= width + kFitSlack && size.x() <= height + kFitSlack);
}

// Rotating calipers: the minimal-area rectangle has a side on a hull edge. The 1 degree
// samples add orientations that fit a page where the minimal-area one does not.
std::vector<double> candidate_angles(const std::vector<Vec2>& hull) {
  std::vector<double> angles;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    Vec2 d = hull[(i + 1) % hull.size()] - hull[i];
    if (d.squaredNorm() > 0) angles.push_back(std::atan2(d.y(), d.x()));
  }
  for (int degree = 0; degree < 180; ++degree) angles.push_back(degree * kDegree);
  return angles;
}

// The tightest orientation: minimal area among those fitting width x height, else minimal
// area overall; turned so that size.x >= size.y.
OrientedBox tightest_box(const std::vector<Vec2>& hull, double width, double height, bool* fits) {
  std::optional<OrientedBox> best_fitting, best_any;
  for (double angle : candidate_angles(hull)) {
    OrientedBox box = oriented_box(hull, angle);
    const double area = box.size.x() * box.size.y();
    auto better = [&](const std::optional<OrientedBox>& current) {
      if (!current) return true;
      const double current_area = current->size.x() * current->size.y();
      if (area < current_area - 1e-9) return true;
      return area <= current_area + 1e-9 &&
             std::min(box.size.x(), box.size.y()) <
                 std::min(current->size.x(), current->size.y()) - 1e-9;
    };
    if (better(best_any)) best_any = box;
    if (fits_area(box.size, width, height) && better(best_fitting)) best_fitting = box;
  }
  *fits = best_fitting.has_value();
  OrientedBox box = best_fitting ? *best_fitting : *best_any;
  if (box.size.y() > box.size.x()) box = oriented_box(hull, box.angle + std::numbers::pi / 2);
  return box;
}

bool hull_fits(const std::vector<Vec2>& hull, double width, double height) {
  if (width <= 0 || height <= 0) return false;
  for (double angle : candidate_angles(hull))
    if (fits_area(oriented_box(hull, angle).size, width, height)) return true;
  return false;
}

// Separating axis test for convex polygons (either orientation): true when the interiors
// overlap deeper than `depth` along every edge normal, so shared edges and touching
// corners do not count.
bool convex_overlap(const Vec2* a, int na, const Vec2* b, int nb, double depth) {
  bool tested = false;
  for (int pass = 0; pass < 2; ++pass) {
    const Vec2* poly = pass == 0 ? a : b;
    const int n = pass == 0 ? na : nb;
    for (int i = 0; i < n; ++i) {
      Vec2 edge = poly[(i + 1) % n] - poly[i];
      const double length = edge.norm();
      if (length <= 1e-12) continue;
      Vec2 axis = Vec2(-edge.y(), edge.x()) / length;
      double amin = std::numeric_limits<double>::infinity(), amax = -amin;
      double bmin = amin, bmax = amax;
      for (int k = 0; k < na; ++k) {
        const double t = a[k].dot(axis);
        amin = std::min(amin, t);
        amax = std::max(amax, t);
      }
      for (int k = 0; k < nb; ++k) {
        const double t = b[k].dot(axis);
        bmin = std::min(bmin, t);
        bmax = std::max(bmax, t);
      }
      tested = true;
      if (amax <= bmin + depth || bmax <= amin + depth) return false;
    }
  }
  return tested;
}

struct Box2 {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = Vec2::Constant(-std::numeric_limits<double>::infinity());
  void add(const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool overlaps(const Box2& o) const {
    return lo.x() < o.hi.x() && o.lo.x() < hi.x() && lo.y() < o.hi.y() && o.lo.y() < hi.y();
  }
};

// ---------------------------------------------------------------------------------------
// Packing. Rectangles get `spacing` added to both sides and the bin grows by `spacing`, so
// neighbours keep the gap and nothing crosses the real bin.

struct RectItem {
  int index = 0;
  double width = 0.0;  // with spacing
  double height = 0.0;
};

struct PackResult {
  std::vector<PackedRectangle> placements;
  int pages = 0;
};

bool fits_bin(double w, double h, double bin_w, double bin_h) {
  return w <= bin_w + kFitSlack && h <= bin_h + kFitSlack;
}

// Next-fit decreasing height: each rectangle lies with its long side along x when that fits.
PackResult shelf_pack(const std::vector<Vec2>& sizes, double bin_w, double bin_h) {
  std::vector<RectItem> items;
  for (int i = 0; i < static_cast<int>(sizes.size()); ++i) {
    double w = std::max(sizes[i].x(), sizes[i].y()), h = std::min(sizes[i].x(), sizes[i].y());
    if (!fits_bin(w, h, bin_w, bin_h)) std::swap(w, h);
    items.push_back({i, w, h});
  }
  std::stable_sort(items.begin(), items.end(),
                   [](const RectItem& a, const RectItem& b) { return a.height > b.height; });
  PackResult result;
  result.placements.resize(sizes.size());
  double x = 0, y = 0, shelf_height = 0;
  for (const RectItem& item : items) {
    if (result.pages == 0) result.pages = 1;
    if (x + item.width > bin_w + kFitSlack) {
      y += shelf_height;
      x = 0;
      shelf_height = 0;
    }
    if (y + item.height > bin_h + kFitSlack) {
      ++result.pages;
      x = y = shelf_height = 0;
    }
    PackedRectangle& placed = result.placements[item.index];
    placed.page = result.pages - 1;
    placed.x = x;
    placed.y = y;
    placed.rotated = (item.width != sizes[item.index].x());
    x += item.width;
    shelf_height = std::max(shelf_height, item.height);
  }
  return result;
}

// Maximal rectangles (Jylanki, "A thousand ways to pack the bin", 2010), one free list per page.
enum class FreeRectChoice { BestShortSideFit, BestAreaFit, TopLeft };

struct FreeRect {
  double x, y, w, h;
};

class MaxRectsPages {
 public:
  MaxRectsPages(double bin_w, double bin_h, FreeRectChoice choice, bool first_page_that_fits)
      : bin_w_(bin_w), bin_h_(bin_h), choice_(choice), first_fit_(first_page_that_fits) {}

  PackedRectangle insert(double w, double h) {
    struct Candidate {
      int page = -1;
      FreeRect rect{};
      bool rotated = false;
      double score1 = std::numeric_limits<double>::infinity(), score2 = score1;
    } best;
    for (int page = 0; page < static_cast<int>(pages_.size()); ++page) {
      for (const FreeRect& free : pages_[page]) {
        for (int turn = 0; turn < 2; ++turn) {
          const double rw = turn ? h : w, rh = turn ? w : h;
          if (rw > free.w + kFitSlack || rh > free.h + kFitSlack) continue;
          double s1 = 0, s2 = 0;
          switch (choice_) {
            case FreeRectChoice::BestShortSideFit:
              s1 = std::min(free.w - rw, free.h - rh);
              s2 = std::max(free.w - rw, free.h - rh);
              break;
            case FreeRectChoice::BestAreaFit:
              s1 = free.w * free.h - rw * rh;
              s2 = std::min(free.w - rw, free.h - rh);
              break;
            case FreeRectChoice::TopLeft:
              s1 = free.y + rh;
              s2 = free.x;
              break;
          }
          if (s1 < best.score1 - 1e-9 || (s1 <= best.score1 + 1e-9 && s2 < best.score2 - 1e-9)) {
            best = {page, {free.x, free.y, rw, rh}, turn == 1, s1, s2};
          }
        }
      }
      if (first_fit_ && best.page >= 0) break;
    }
    if (best.page < 0) {
      pages_.push_back({{0, 0, bin_w_, bin_h_}});
      best.page = static_cast<int>(pages_.size()) - 1;
      const bool turn = !fits_bin(w, h, bin_w_, bin_h_);
      best.rect = {0, 0, turn ? h : w, turn ? w : h};
      best.rotated = turn;
    }
    place(pages_[best.page], best.rect);
    return {best.page, best.rect.x, best.rect.y, best.rotated};
  }

  int page_count() const { return static_cast<int>(pages_.size()); }

 private:
  static void place(std::vector<FreeRect>& free_rects, const FreeRect& used) {
    std::vector<FreeRect> next;
    for (const FreeRect& f : free_rects) {
      const bool overlap = used.x < f.x + f.w && f.x < used.x + used.w && used.y < f.y + f.h &&
                           f.y < used.y + used.h;
      if (!overlap) {
        next.push_back(f);
        continue;
      }
      if (used.x > f.x) next.push_back({f.x, f.y, used.x - f.x, f.h});
      if (used.x + used.w < f.x + f.w)
        next.push_back({used.x + used.w, f.y, f.x + f.w - used.x - used.w, f.h});
      if (used.y > f.y) next.push_back({f.x, f.y, f.w, used.y - f.y});
      if (used.y + used.h < f.y + f.h)
        next.push_back({f.x, used.y + used.h, f.w, f.y + f.h - used.y - used.h});
    }
    auto contains = [](const FreeRect& outer, const FreeRect& inner) {
      return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.w <= outer.x + outer.w &&
             inner.y + inner.h <= outer.y + outer.h;
    };
    std::vector<bool> drop(next.size(), false);
    for (std::size_t i = 0; i < next.size(); ++i) {
      if (next[i].w <= 1e-9 || next[i].h <= 1e-9) drop[i] = true;
      for (std::size_t j = 0; j < next.size() && !drop[i]; ++j) {
        if (i == j || drop[j]) continue;
        if (contains(next[j], next[i])) drop[i] = true;
      }
    }
    free_rects.clear();
    for (std::size_t i = 0; i < next.size(); ++i)
      if (!drop[i]) free_rects.push_back(next[i]);
  }

  double bin_w_, bin_h_;
  FreeRectChoice choice_;
  bool first_fit_;
  std::vector<std::vector<FreeRect>> pages_;
};

PackResult maxrects_pack(const std::vector<Vec2>& sizes, double bin_w, double bin_h) {
  using Key = std::function<double(const Vec2&)>;
  const std::vector<Key> orders = {
      [](const Vec2& s) { return s.x() * s.y(); },
      [](const Vec2& s) { return std::max(s.x(), s.y()); },
      [](const Vec2& s) { return std::min(s.x(), s.y()); },
      [](const Vec2& s) { return s.x() + s.y(); },
  };
  std::optional<PackResult> best;
  for (const Key& key : orders) {
    std::vector<int> order(sizes.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return key(sizes[a]) > key(sizes[b]); });
    for (FreeRectChoice choice :
         {FreeRectChoice::BestShortSideFit, FreeRectChoice::BestAreaFit, FreeRectChoice::TopLeft}) {
      for (bool first_fit : {false, true}) {
        MaxRectsPages packer(bin_w, bin_h, choice, first_fit);
        PackResult result;
        result.placements.resize(sizes.size());
        for (int index : order) {
          PackedRectangle placed = packer.insert(sizes[index].x(), sizes[index].y());
          result.placements[index] = placed;
        }
        result.pages = packer.page_count();
        if (!best || result.pages < best->pages) best = std::move(result);
      }
    }
  }
  // The baseline is one more candidate, so MaxRects never needs more pages than Shelf.
  PackResult shelf = shelf_pack(sizes, bin_w, bin_h);
  if (!best || shelf.pages < best->pages) best = std::move(shelf);
  return *best;
}

PackResult pack_with_spacing(const std::vector<Vec2>& sizes, double bin_width, double bin_height,
                             double spacing, PackingMethod method) {
  if (!(bin_width > 0) || !(bin_height > 0) || !(spacing >= 0))
    throw InvalidInputException("packing bin must have positive size and spacing >= 0");
  std::vector<Vec2> spaced;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const Vec2& s = sizes[i];
    if (!(s.x() > 0) || !(s.y() > 0))
      throw InvalidInputException("rectangle " + std::to_string(i) + " has a non-positive size");
    if (!fits_area(s, bin_width, bin_height))
      throw InvalidInputException("rectangle " + std::to_string(i) + " (" + format_mm(s.x()) +
                                  " x " + format_mm(s.y()) + ") fits no orientation of the " +
                                  format_mm(bin_width) + " x " + format_mm(bin_height) + " bin");
    spaced.push_back(s + Vec2::Constant(spacing));
  }
  const double w = bin_width + spacing, h = bin_height + spacing;
  return method == PackingMethod::Shelf ? shelf_pack(spaced, w, h) : maxrects_pack(spaced, w, h);
}

// ---------------------------------------------------------------------------------------
// Strips, pieces, seams.

struct StripData {
  const FlatStrip* strip = nullptr;
  std::vector<Vec2> points;                                    // vertices2d in mm
  std::vector<int> triangles;                                  // usable triangle indices
  std::unordered_map<std::uint64_t, int> owner;                // directed edge -> triangle
  std::unordered_map<std::uint64_t, int> boundary_of;          // directed edge -> boundary index
  std::unordered_map<std::uint64_t, std::string> split_label;  // unordered inner edge
  bool missing_boundary_warned = false;
};

struct PieceEdge {
  int v0 = -1, v1 = -1;
  EdgeKind kind = EdgeKind::Cut;
  std::string label;    // as given (or a split's label)
  std::string printed;  // as printed
  int flap = -1;        // index into Piece::flaps covering this edge
  bool flap_first = false;
};

struct Flap {
  std::vector<Vec2> base;             // p_a .. p_b+1, strip frame mm
  std::vector<Vec2> outer;            // q_a .. q_b+1
  int tab = -1;                       // index into Piece::tabs
  std::vector<TexturePatch> texture;  // strip frame mm
};

struct PieceTab {
  std::string label;
  std::vector<int> flaps;
};

struct PieceLabel {
  std::string text;
  Vec2 position;
  Vec2 direction;
  double size;
  int chain = -1;  // the seam chain it names
};

struct Piece {
  int strip = -1;  // index into strips
  int index = 0;
  int count = 1;
  std::vector<int> triangles;
  std::vector<std::vector<PieceEdge>> loops;
  std::vector<Flap> flaps;
  std::vector<PieceTab> tabs;
  std::vector<PieceLabel> labels;
  std::optional<PieceLabel> number;  // set by arrange_labels
  std::vector<std::array<Vec2, 2>> marks;  // strip frame mm (see PlacedPiece::marks)
};

std::string strip_name(const FlatStrip& strip) {
  return "strip " + std::to_string(strip.id);
}

void validate_strip(const FlatStrip& strip) {
  const std::string name = strip_name(strip);
  const int n = static_cast<int>(strip.vertices2d.size());
  if (strip.vertices3d.size() != strip.vertices2d.size())
    throw InvalidInputException(name + " has " + std::to_string(strip.vertices3d.size()) +
                                " 3D vertices but " + std::to_string(n) + " 2D vertices");
  if (!strip.uvs.empty() && static_cast<int>(strip.uvs.size()) != n)
    throw InvalidInputException(name + " has " + std::to_string(strip.uvs.size()) + " uvs for " +
                                std::to_string(n) + " vertices");
  for (int i = 0; i < n; ++i)
    if (!strip.vertices2d[i].allFinite() || !strip.vertices3d[i].allFinite())
      throw InvalidInputException(name + " vertex " + std::to_string(i) +
                                  " has a non-finite coordinate");
  for (std::size_t t = 0; t < strip.triangles.size(); ++t)
    for (int v : strip.triangles[t])
      if (v < 0 || v >= n)
        throw InvalidInputException(name + " triangle " + std::to_string(t) + " has vertex index " +
                                    std::to_string(v) + " out of range");
  for (const BoundaryEdge& e : strip.boundary)
    if (e.v0 < 0 || e.v0 >= n || e.v1 < 0 || e.v1 >= n)
      throw InvalidInputException(name + " boundary edge " + std::to_string(e.v0) + "-" +
                                  std::to_string(e.v1) + " has a vertex index out of range");
}

StripData prepare_strip(const FlatStrip& strip, double mm_per_unit) {
  StripData data;
  data.strip = &strip;
  for (const Vec2& v : strip.vertices2d) data.points.push_back(v * mm_per_unit);
  const std::string name = strip_name(strip);
  if (const int t = first_clockwise_triangle(strip.vertices2d, strip.triangles, 1e-9); t >= 0)
    throw InvalidInputException(name + " triangle " + std::to_string(t) +
                                " is clockwise in 2D (a mirrored unfolding)");
  for (int t = 0; t < static_cast<int>(strip.triangles.size()); ++t) {
    const Triangle& tri = strip.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    for (int i = 0; i < 3; ++i) {
      if (!data.owner.emplace(directed_edge_key(tri[i], tri[(i + 1) % 3]), t).second)
        throw InvalidInputException(name + " edge " + std::to_string(tri[i]) + "-" +
                                    std::to_string(tri[(i + 1) % 3]) +
                                    " belongs to two triangles in the same direction");
    }
    data.triangles.push_back(t);
  }
  for (int i = 0; i < static_cast<int>(strip.boundary.size()); ++i) {
    const BoundaryEdge& e = strip.boundary[i];
    const std::uint64_t key = directed_edge_key(e.v0, e.v1);
    if (!data.owner.count(key) || data.owner.count(directed_edge_key(e.v1, e.v0)))
      throw InvalidInputException(name + " boundary edge " + std::to_string(e.v0) + "-" +
                                  std::to_string(e.v1) +
                                  " is not a boundary edge of its triangles with the strip on "
                                  "its left");
    data.boundary_of[key] = i;
  }
  return data;
}

std::vector<Vec2> piece_points(const StripData& data, const std::vector<int>& triangles) {
  std::vector<Vec2> points;
  for (int t : triangles)
    for (int v : data.strip->triangles[t]) points.push_back(data.points[v]);
  return points;
}

// Boundary loops of a set of triangles, following each boundary edge to the next around
// their shared vertex through the set's triangles (right at pinch vertices).
std::vector<std::vector<PieceEdge>> piece_loops(StripData& data, const std::vector<int>& triangles,
                                                std::vector<std::string>& warnings) {
  const FlatStrip& strip = *data.strip;
  std::unordered_map<int, char> in_piece;
  for (int t : triangles) in_piece[t] = 1;
  auto inner = [&](int a, int b) {  // (a, b) has a piece triangle on its right too
    auto it = data.owner.find(directed_edge_key(b, a));
    return it != data.owner.end() && in_piece.count(it->second);
  };
  auto third = [&](int t, int a, int b) {
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (tri[i] == a && tri[(i + 1) % 3] == b) return tri[(i + 2) % 3];
    return -1;
  };
  std::vector<std::pair<int, int>> edges;
  for (int t : triangles) {
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (!inner(tri[i], tri[(i + 1) % 3])) edges.emplace_back(tri[i], tri[(i + 1) % 3]);
  }
  std::sort(edges.begin(), edges.end());
  std::set<std::pair<int, int>> used;
  std::vector<std::vector<PieceEdge>> loops;
  for (const auto& start : edges) {
    if (used.count(start)) continue;
    std::vector<PieceEdge> loop;
    std::pair<int, int> current = start;
    while (!used.count(current)) {
      used.insert(current);
      PieceEdge edge;
      edge.v0 = current.first;
      edge.v1 = current.second;
      const std::uint64_t key = directed_edge_key(edge.v0, edge.v1);
      if (auto b = data.boundary_of.find(key); b != data.boundary_of.end()) {
        const BoundaryEdge& given = strip.boundary[b->second];
        edge.kind = given.kind;
        if (given.kind == EdgeKind::Seam) edge.label = given.label;
      } else if (auto s = data.split_label.find(
                     directed_edge_key(std::min(edge.v0, edge.v1), std::max(edge.v0, edge.v1)));
                 s != data.split_label.end()) {
        edge.kind = EdgeKind::Seam;
        edge.label = s->second;
      } else if (!data.owner.count(directed_edge_key(edge.v1, edge.v0)) && !data.missing_boundary_warned) {
        data.missing_boundary_warned = true;
        warnings.push_back(strip_name(strip) + ": boundary edge " + std::to_string(edge.v0) + "-" +
                           std::to_string(edge.v1) +
                           " is missing from its boundary list; drawn as a plain cut");
      }
      loop.push_back(edge);
      // Rotate around v1 through the piece's triangles to the next boundary edge.
      int a = current.first, b = current.second;
      int t = data.owner.at(directed_edge_key(a, b));
      std::pair<int, int> next{-1, -1};
      for (std::size_t guard = 0; guard <= triangles.size(); ++guard) {
        const int c = third(t, a, b);
        if (!inner(b, c)) {
          next = {b, c};
          break;
        }
        t = data.owner.at(directed_edge_key(c, b));
        a = c;
      }
      if (next.first < 0) break;
      current = next;
    }
    loops.push_back(std::move(loop));
  }
  auto loop_area = [&](const std::vector<PieceEdge>& loop) {
    std::vector<Vec2> polygon;
    for (const PieceEdge& e : loop) polygon.push_back(data.points[e.v0]);
    return signed_area(polygon);
  };
  std::stable_sort(loops.begin(), loops.end(),
                   [&](const auto& a, const auto& b) { return loop_area(a) > loop_area(b); });
  return loops;
}

// Connected components of a triangle set over shared inner edges.
std::vector<std::vector<int>> components(const StripData& data, const std::vector<int>& set) {
  std::unordered_map<int, int> component;
  for (int t : set) component[t] = -1;
  std::vector<std::vector<int>> result;
  for (int seed : set) {
    if (component[seed] >= 0) continue;
    const int id = static_cast<int>(result.size());
    result.emplace_back();
    std::vector<int> stack{seed};
    component[seed] = id;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      result[id].push_back(t);
      const Triangle& tri = data.strip->triangles[t];
      for (int i = 0; i < 3; ++i) {
        auto it = data.owner.find(directed_edge_key(tri[(i + 1) % 3], tri[i]));
        if (it == data.owner.end()) continue;
        auto c = component.find(it->second);
        if (c != component.end() && c->second < 0) {
          c->second = id;
          stack.push_back(it->second);
        }
      }
    }
    std::sort(result[id].begin(), result[id].end());
  }
  return result;
}

// Triangles of `set` in Dijkstra order (centroid distances over shared edges) from `seed`.
std::vector<int> dijkstra_order(const StripData& data, const std::vector<int>& set, int seed,
                                std::vector<double>* distances = nullptr) {
  const FlatStrip& strip = *data.strip;
  std::unordered_map<int, double> distance;
  for (int t : set) distance[t] = std::numeric_limits<double>::infinity();
  auto centroid = [&](int t) {
    const Triangle& tri = strip.triangles[t];
    return Vec2((data.points[tri[0]] + data.points[tri[1]] + data.points[tri[2]]) / 3.0);
  };
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  distance[seed] = 0;
  queue.push({0, seed});
  std::vector<int> order;
  std::unordered_map<int, char> done;
  while (!queue.empty()) {
    auto [d, t] = queue.top();
    queue.pop();
    if (done.count(t)) continue;
    done[t] = 1;
    order.push_back(t);
    if (distances) distances->push_back(d);
    const Triangle& tri = strip.triangles[t];
    for (int i = 0; i < 3; ++i) {
      auto it = data.owner.find(directed_edge_key(tri[(i + 1) % 3], tri[i]));
      if (it == data.owner.end()) continue;
      auto n = distance.find(it->second);
      if (n == distance.end() || done.count(it->second)) continue;
      const double nd = d + (centroid(t) - centroid(it->second)).norm();
      if (nd < n->second) {
        n->second = nd;
        queue.push({nd, it->second});
      }
    }
  }
  return order;
}

std::string unique_label(const std::string& wanted, std::set<std::string>& used) {
  std::string label = wanted;
  while (used.count(label)) label += "'";
  used.insert(label);
  return label;
}

// Splits the strip into connected triangle sets each fitting width x height: a Dijkstra
// prefix from one end of the set (a ruled strip is a path of triangles, so the cut is one
// ruling), repeated on what is left. The prefix is not the largest that fits (that leaves
// a sliver at the end) but the one nearest 1/k of the set's length, where k is the number
// of pieces the greedy split needs, among those that leave a rest still splittable into
// k - 1 pieces: the pieces come out of similar length.
std::vector<std::vector<int>> split_to_fit(StripData& data, double width, double height,
                                           std::set<std::string>& used_labels) {
  std::vector<std::vector<int>> done;
  std::vector<std::vector<int>> work = components(data, data.triangles);
  int next_label = 1;
  // A piece must fit in its tightest orientation: one that fits only diagonally would take
  // a page to itself.
  auto fits = [&](const std::vector<int>& set) {
    bool unused = false;
    const OrientedBox box = tightest_box(convex_hull(piece_points(data, set)), -1, -1, &unused);
    return fits_area(box.size, width, height);
  };
  while (!work.empty()) {
    std::vector<int> set = std::move(work.front());
    work.erase(work.begin());
    if (set.size() <= 1 || fits(set)) {
      done.push_back(std::move(set));
      continue;
    }
    std::vector<int> from_first = dijkstra_order(data, set, set.front());
    std::vector<double> distance;
    std::vector<int> order = dijkstra_order(data, set, from_first.back(), &distance);
    // The longest prefix of order[begin..] that fits (at least one triangle).
    auto longest_fitting = [&](std::size_t begin) {
      std::size_t lo = begin + 1, hi = order.size();
      while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (fits(std::vector<int>(order.begin() + begin, order.begin() + mid)))
          lo = mid;
        else
          hi = mid - 1;
      }
      return lo;
    };
    auto greedy_count = [&](std::size_t begin) {
      int count = 0;
      for (; begin < order.size(); ++count) begin = longest_fitting(begin);
      return count;
    };
    std::size_t lo = std::min(longest_fitting(0), order.size() - 1);
    const int pieces = greedy_count(0);
    if (pieces >= 2 && lo > 1) {
      // Smallest cut whose rest still splits into pieces - 1 (the count only falls as the
      // cut moves on), then the cut nearest 1/pieces of the length within [first, lo].
      std::size_t first = 1, last = lo;
      while (first < last) {
        const std::size_t mid = (first + last) / 2;
        if (greedy_count(mid) <= pieces - 1)
          last = mid;
        else
          first = mid + 1;
      }
      const double target = distance.back() / pieces;
      std::size_t cut =
          std::lower_bound(distance.begin(), distance.end(), target) - distance.begin();
      cut = std::clamp(cut, first, lo);
      if (cut < lo && fits(std::vector<int>(order.begin(), order.begin() + cut)) &&
          components(data, std::vector<int>(order.begin() + cut, order.end())).size() == 1)
        lo = cut;
    }
    std::vector<int> head(order.begin(), order.begin() + lo);
    std::sort(head.begin(), head.end());
    std::vector<int> rest;
    std::set_difference(set.begin(), set.end(), head.begin(), head.end(), std::back_inserter(rest));
    std::unordered_map<int, char> in_head;
    for (int t : head) in_head[t] = 1;
    for (std::vector<int>& part : components(data, rest)) {
      const std::string label = unique_label(
          std::to_string(data.strip->id) + "-" + std::to_string(next_label++), used_labels);
      for (int t : part) {
        const Triangle& tri = data.strip->triangles[t];
        for (int i = 0; i < 3; ++i) {
          const int a = tri[i], b = tri[(i + 1) % 3];
          auto it = data.owner.find(directed_edge_key(b, a));
          if (it != data.owner.end() && in_head.count(it->second))
            data.split_label[directed_edge_key(std::min(a, b), std::max(a, b))] = label;
        }
      }
      work.push_back(std::move(part));
    }
    done.push_back(std::move(head));
  }
  return done;
}

// Seam edges of all pieces, each matched to the edge with the same label running the other
// way between the same 3D points (label_seams makes glued points bit-identical).
struct SeamEdges {
  std::vector<std::array<int, 3>> refs;           // piece, loop, index in loop
  std::vector<std::vector<std::vector<int>>> id;  // [piece][loop][index] -> edge id or -1
  std::vector<int> partner;                       // edge id or -1
};

SeamEdges match_seam_edges(const std::vector<Piece>& pieces, const std::vector<StripData>& strips) {
  using Key = std::pair<std::string, std::array<double, 6>>;
  auto key = [](const std::string& label, const Vec3& a, const Vec3& b) {
    return Key{label, {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}};
  };
  SeamEdges seams;
  std::map<Key, std::vector<int>> by_key;
  seams.id.resize(pieces.size());
  for (int p = 0; p < static_cast<int>(pieces.size()); ++p) {
    const FlatStrip& strip = *strips[pieces[p].strip].strip;
    seams.id[p].resize(pieces[p].loops.size());
    for (int l = 0; l < static_cast<int>(pieces[p].loops.size()); ++l) {
      const auto& loop = pieces[p].loops[l];
      seams.id[p][l].assign(loop.size(), -1);
      for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
        if (loop[i].kind != EdgeKind::Seam) continue;
        const int id = static_cast<int>(seams.refs.size());
        seams.refs.push_back({p, l, i});
        seams.id[p][l][i] = id;
        by_key[key(loop[i].label, strip.vertices3d[loop[i].v0], strip.vertices3d[loop[i].v1])]
            .push_back(id);
      }
    }
  }
  seams.partner.assign(seams.refs.size(), -1);
  for (int e = 0; e < static_cast<int>(seams.refs.size()); ++e) {
    if (seams.partner[e] >= 0) continue;
    const auto [p, l, i] = seams.refs[e];
    const PieceEdge& edge = pieces[p].loops[l][i];
    const FlatStrip& strip = *strips[pieces[p].strip].strip;
    auto it = by_key.find(key(edge.label, strip.vertices3d[edge.v1], strip.vertices3d[edge.v0]));
    if (it == by_key.end()) continue;
    for (int f : it->second)
      if (f != e && seams.partner[f] < 0) {
        seams.partner[e] = f;
        seams.partner[f] = e;
        break;
      }
  }
  return seams;
}

// A run of consecutive seam edges with one label on one boundary loop whose partners run
// consecutively the other way on one loop (so a cap glued to a band split in two gets two
// chains), or of unmatched edges with one label.
struct Chain {
  int piece = -1;
  int loop = -1;
  int start = 0;
  int count = 0;
  bool closed = false;
  std::string label;
  Vec3 first = Vec3::Zero();  // 3D start and end points
  Vec3 last = Vec3::Zero();
  int partner_edge = -1;  // partner of the first edge, when matched
};

std::vector<Chain> seam_chains(const std::vector<Piece>& pieces,
                               const std::vector<StripData>& strips, const SeamEdges& seams,
                               double tolerance3d) {
  std::vector<Chain> chains;
  for (int p = 0; p < static_cast<int>(pieces.size()); ++p) {
    const Piece& piece = pieces[p];
    const FlatStrip& strip = *strips[piece.strip].strip;
    for (int l = 0; l < static_cast<int>(piece.loops.size()); ++l) {
      const std::vector<PieceEdge>& loop = piece.loops[l];
      const int n = static_cast<int>(loop.size());
      auto joins = [&](int i) {
        const int a = i, b = (i + 1) % n;
        const int ea = seams.id[p][l][a], eb = seams.id[p][l][b];
        if (ea < 0 || eb < 0 || loop[a].label != loop[b].label) return false;
        const int pa = seams.partner[ea], pb = seams.partner[eb];
        if (pa >= 0 && pb >= 0) {
          if (pb == ea) return false;  // the two sides of an opened cone apex
          const auto& ra = seams.refs[pa];
          const auto& rb = seams.refs[pb];
          const int m = static_cast<int>(pieces[ra[0]].loops[ra[1]].size());
          return rb[0] == ra[0] && rb[1] == ra[1] && rb[2] == (ra[2] + m - 1) % m;
        }
        if (pa >= 0 || pb >= 0) return false;
        // Unmatched: one chain unless the second edge comes straight back in 3D.
        return (strip.vertices3d[loop[b].v1] - strip.vertices3d[loop[a].v0]).norm() > tolerance3d;
      };
      auto make = [&](int start, int count, bool closed) {
        Chain c;
        c.piece = p;
        c.loop = l;
        c.start = start;
        c.count = count;
        c.closed = closed;
        c.label = loop[start].label;
        c.first = strip.vertices3d[loop[start].v0];
        c.last = strip.vertices3d[loop[(start + count - 1) % n].v1];
        c.partner_edge = seams.partner[seams.id[p][l][start]];
        chains.push_back(c);
      };
      bool all = true;
      for (int i = 0; i < n && all; ++i) all = joins(i);
      if (all) {
        make(0, n, true);
        continue;
      }
      for (int i = 0; i < n; ++i) {
        if (loop[i].kind != EdgeKind::Seam || joins((i + n - 1) % n)) continue;
        int count = 1;
        while (joins((i + count - 1) % n)) ++count;
        make(i, count, false);
      }
    }
  }
  return chains;
}

struct SeamPair {
  int first = -1;  // chain indices; second = -1 when the seam has no partner
  int second = -1;
  std::string printed;
};

std::vector<SeamPair> pair_chains(const std::vector<Chain>& chains, const SeamEdges& seams,
                                  const std::vector<Piece>& pieces, double tolerance3d,
                                  std::vector<std::string>& warnings) {
  std::vector<int> chain_of_edge(seams.refs.size(), -1);
  for (int c = 0; c < static_cast<int>(chains.size()); ++c) {
    const Chain& chain = chains[c];
    const int n = static_cast<int>(pieces[chain.piece].loops[chain.loop].size());
    for (int i = 0; i < chain.count; ++i)
      chain_of_edge[seams.id[chain.piece][chain.loop][(chain.start + i) % n]] = c;
  }
  std::map<std::string, std::vector<SeamPair>> by_label;
  std::vector<bool> paired(chains.size(), false);
  for (int c = 0; c < static_cast<int>(chains.size()); ++c) {
    if (paired[c] || chains[c].partner_edge < 0) continue;
    const int d = chain_of_edge[chains[c].partner_edge];
    if (d < 0 || d == c || paired[d]) continue;
    paired[c] = paired[d] = true;
    by_label[chains[c].label].push_back({c, d, chains[c].label});
  }
  // Edges without an exact partner (a neighbour with extra vertices on the seam): pair
  // whole chains of one label by their nearest ends.
  std::map<std::string, std::vector<int>> unpaired;
  for (int c = 0; c < static_cast<int>(chains.size()); ++c)
    if (!paired[c]) unpaired[chains[c].label].push_back(c);
  for (const auto& [label, members] : unpaired) {
    std::vector<bool> taken(members.size(), false);
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (taken[i]) continue;
      taken[i] = true;
      const Chain& a = chains[members[i]];
      int best = -1;
      double best_error = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < members.size(); ++j) {
        if (taken[j]) continue;
        const Chain& b = chains[members[j]];
        const double error = (a.first - b.last).norm() + (a.last - b.first).norm();
        if (error < best_error) {
          best_error = error;
          best = static_cast<int>(j);
        }
      }
      if (best < 0) {
        warnings.push_back("seam " + label + " has no partner edge; its tab is glued by eye");
        by_label[label].push_back({members[i], -1, label});
        continue;
      }
      taken[best] = true;
      if (members.size() > 2 && best_error > 2 * tolerance3d)
        warnings.push_back("seam " + label + " is used by " + std::to_string(members.size()) +
                           " edge chains whose ends do not match; paired by nearest ends");
      by_label[label].push_back({members[i], members[best], label});
    }
  }
  std::vector<SeamPair> pairs;
  for (auto& [label, these] : by_label) {
    if (these.size() > 1)
      for (std::size_t k = 0; k < these.size(); ++k)
        these[k].printed = label + "." + std::to_string(k + 1);
    pairs.insert(pairs.end(), these.begin(), these.end());
  }
  return pairs;
}

// Ticks of `length` across the cut line at the ends of `chain` where the boundary goes on
// as another seam: the places where two seams meet, printed on both pieces.
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

// ---------------------------------------------------------------------------------------
// Tabs.

struct TabGeometry {
  double width;
  double angle;  // radians
  double min_height;
  double overlap_depth;
};

// Triangles of a piece in mm with their boxes, for collision tests.
struct PieceShapes {
  std::vector<std::array<Vec2, 3>> triangles;
  std::vector<Box2> triangle_boxes;
  std::vector<std::vector<Vec2>> slices;  // convex slices of accepted flaps
  std::vector<Box2> slice_boxes;
};

PieceShapes piece_shapes(const StripData& data, const Piece& piece) {
  PieceShapes shapes;
  for (int t : piece.triangles) {
    const Triangle& tri = data.strip->triangles[t];
    std::array<Vec2, 3> corners{data.points[tri[0]], data.points[tri[1]], data.points[tri[2]]};
    Box2 box;
    for (const Vec2& c : corners) box.add(c);
    shapes.triangles.push_back(corners);
    shapes.triangle_boxes.push_back(box);
  }
  return shapes;
}

// Keeps the part of convex or simple `polygon` where side(x) >= 0 (Sutherland-Hodgman).
std::vector<Vec2> clip(const std::vector<Vec2>& polygon,
                       const std::function<double(const Vec2&)>& side) {
  std::vector<Vec2> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = polygon[i], &b = polygon[(i + 1) % n];
    const double sa = side(a), sb = side(b);
    if (sa >= 0) out.push_back(a);
    if ((sa >= 0) != (sb >= 0)) out.push_back(a + (sa / (sa - sb)) * (b - a));
  }
  return out;
}

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

bool slices_collide(const std::vector<std::vector<Vec2>>& slices, const PieceShapes& shapes,
                    double depth) {
  for (const auto& slice : slices) {
    Box2 box;
    for (const Vec2& c : slice) box.add(c);
    const int n = static_cast<int>(slice.size());
    for (std::size_t t = 0; t < shapes.triangles.size(); ++t)
      if (box.overlaps(shapes.triangle_boxes[t]) &&
          convex_overlap(slice.data(), n, shapes.triangles[t].data(), 3, depth))
        return true;
    for (std::size_t q = 0; q < shapes.slices.size(); ++q)
      if (box.overlaps(shapes.slice_boxes[q]) &&
          convex_overlap(slice.data(), n, shapes.slices[q].data(),
                         static_cast<int>(shapes.slices[q].size()), depth))
        return true;
  }
  return false;
}

struct FlapPlan {
  std::vector<int> edges;  // loop edge indices, in order
  std::vector<Vec2> base;
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> slices;
  std::vector<int> slice_edges;  // index into `edges` of each slice's base edge
};

// Flaps along a chain: one per nearly straight run of edges (a flap cannot fold along a
// bend), each as high as fits up to the tab width, dropped where none fits.
std::vector<FlapPlan> plan_flaps(const StripData& data, const Piece& piece, const Chain& chain,
                                 const TabGeometry& geometry, PieceShapes& shapes) {
  const std::vector<PieceEdge>& loop = piece.loops[chain.loop];
  const int n = static_cast<int>(loop.size());
  std::vector<int> edges;
  for (int i = 0; i < chain.count; ++i) edges.push_back((chain.start + i) % n);
  auto point = [&](int v) { return data.points[v]; };
  auto direction = [&](int e) { return Vec2(point(loop[e].v1) - point(loop[e].v0)); };
  auto turn = [&](int e0, int e1) {  // signed turning angle from edge e0 to edge e1
    const Vec2 a = direction(e0), b = direction(e1);
    return std::atan2(cross(a, b), a.dot(b));
  };
  const double max_joint = 15 * kDegree, max_run = 30 * kDegree;
  if (chain.closed) {  // start at the sharpest joint so runs break there
    int best = 0;
    double sharpest = -1;
    for (int i = 0; i < chain.count; ++i) {
      const double t = std::abs(turn(edges[(i + chain.count - 1) % chain.count], edges[i]));
      if (t > sharpest) {
        sharpest = t;
        best = i;
      }
    }
    std::rotate(edges.begin(), edges.begin() + best, edges.end());
  }
  // Runs: break at sharp joints, after too much accumulated turning, at zero-length edges.
  std::vector<std::vector<int>> runs;
  std::vector<double> joint_before, joint_after;  // turning angle at each run's ends
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
    auto end_angle = [&](bool at_start) {
      double angle = geometry.angle;
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
    const double start_angle = end_angle(true), stop_angle = end_angle(false);
    if (start_angle <= 2 * kDegree || stop_angle <= 2 * kDegree) continue;
    FlapPlan plan;
    plan.edges = run;
    plan.base.push_back(point(loop[run.front()].v0));
    double length = 0;
    for (int e : run) {
      plan.base.push_back(point(loop[e].v1));
      length += direction(e).norm();
    }
    const double chord = (plan.base.back() - plan.base.front()).norm();
    const double h0 =
        std::min(geometry.width, 0.9 * std::min(length, chord) /
                                     (1 / std::tan(start_angle) + 1 / std::tan(stop_angle)));
    for (double factor : {1.0, 0.7, 0.5, 0.35}) {
      const double h = h0 * factor;
      if (h < geometry.min_height) break;
      std::vector<Vec2> outer;
      std::vector<int> slice_edges;
      auto slices = flap_slices(plan.base, h, start_angle, stop_angle, &outer, &slice_edges);
      if (slices.empty() || slices_collide(slices, shapes, geometry.overlap_depth)) continue;
      plan.outer = std::move(outer);
      plan.slices = std::move(slices);
      plan.slice_edges = std::move(slice_edges);
      break;
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

double plans_length(const std::vector<FlapPlan>& plans) {
  double length = 0;
  for (const FlapPlan& plan : plans)
    for (std::size_t i = 0; i + 1 < plan.base.size(); ++i)
      length += (plan.base[i + 1] - plan.base[i]).norm();
  return length;
}

double chain_length(const StripData& data, const Piece& piece, const Chain& chain) {
  const auto& loop = piece.loops[chain.loop];
  double length = 0;
  for (int i = 0; i < chain.count; ++i) {
    const PieceEdge& e = loop[(chain.start + i) % loop.size()];
    length += (data.points[e.v1] - data.points[e.v0]).norm();
  }
  return length;
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
    for (std::size_t i = 0; i < plan.edges.size(); ++i) {
      PieceEdge& edge = piece.loops[chain.loop][plan.edges[i]];
      edge.flap = flap_index;
      edge.flap_first = (i == 0);
    }
  }
  piece.tabs.push_back(std::move(tab));
}

// The seam label of a chain: centred on the chain's arc-length midpoint, inside the piece,
// along the edge there, smaller where the chain is short.
PieceLabel chain_label(const StripData& data, const Piece& piece, const Chain& chain,
                       const std::string& text, double size) {
  const auto& loop = piece.loops[chain.loop];
  const double total = chain_length(data, piece, chain);
  const double text_width = 0.6 * static_cast<double>(text.size());
  size = std::max(std::min(size, (total - 0.5) / std::max(text_width, 1e-9)), std::min(size, 1.5));
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
  return {text, a + at * (b - a) + Vec2(-d.y(), d.x()) * (0.6 * size + 0.6), d, size};
}

// ---------------------------------------------------------------------------------------
// Folds and numbers.

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
    const Triangle& tri = data.strip->triangles[t];
    const Vec2 &a = data.points[tri[0]], &b = data.points[tri[1]], &c = data.points[tri[2]];
    const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
    const double perimeter = la + lb + lc;
    if (perimeter <= 0) continue;
    const double twice_area = std::abs(cross(b - a, c - a));
    centroid += twice_area * (a + b + c) / 3.0;
    area += twice_area;
    candidates.push_back({(la * a + lb * b + lc * c) / perimeter, twice_area / perimeter});
    largest = std::max(largest, candidates.back().radius);
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

double upright_degrees(const Vec2& page_direction) {
  double angle = std::atan2(page_direction.y(), page_direction.x()) / kDegree;
  if (angle > 90.0 + 1e-9) angle -= 180.0;
  if (angle <= -90.0 + 1e-9) angle += 180.0;
  return angle;
}

PieceLabel piece_number(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const LayoutOptions& options) {
  auto [centre, radius] = number_spot(data, piece);
  PieceLabel number;
  number.text = std::to_string(data.strip->id);
  if (piece.count > 1) number.text += "." + std::to_string(piece.index + 1);
  number.position = centre;
  number.size = std::min(options.number_size_mm, std::max(1.5, 1.8 * radius));
  number.direction = Vec2(std::cos(box.angle), std::sin(box.angle));
  return number;
}

std::array<Vec2, 4> text_box(const Vec2& centre, const Vec2& direction, double size,
                             std::size_t characters) {
  const Vec2 along = direction.normalized() * (0.5 * kCharWidthEm * size * characters + 0.1 * size);
  const Vec2 across = Vec2(-direction.y(), direction.x()).normalized() * (kHalfLineEm * size);
  return {centre - along - across, centre + along - across, centre + along + across,
          centre - along + across};
}

bool inside_triangles(const Vec2& p, const PieceShapes& shapes) {
  for (std::size_t t = 0; t < shapes.triangles.size(); ++t) {
    const Box2& box = shapes.triangle_boxes[t];
    if (p.x() < box.lo.x() - 1e-9 || p.x() > box.hi.x() + 1e-9 || p.y() < box.lo.y() - 1e-9 ||
        p.y() > box.hi.y() + 1e-9)
      continue;
    const auto& c = shapes.triangles[t];
    const double scale = 1e-9 * (box.hi - box.lo).squaredNorm();
    if (cross(c[1] - c[0], p - c[0]) >= -scale && cross(c[2] - c[1], p - c[1]) >= -scale &&
        cross(c[0] - c[2], p - c[2]) >= -scale)
      return true;
  }
  return false;
}

// A text box lies on the piece: its corners and edge midpoints are on triangles of it.
bool box_on_piece(const std::array<Vec2, 4>& box, const PieceShapes& shapes) {
  for (int i = 0; i < 4; ++i) {
    if (!inside_triangles(box[i], shapes)) return false;
    if (!inside_triangles(0.5 * (box[i] + box[(i + 1) % 4]), shapes)) return false;
  }
  return inside_triangles(0.25 * (box[0] + box[1] + box[2] + box[3]), shapes);
}

// Moves each seam label along its chain (and shrinks it, down to 1.2 mm) until its text box
// lies on the piece and clear of the piece number and the labels placed before it; a label
// that finds no such spot keeps its first one. The number stays where number_spot puts it.
void arrange_labels(const StripData& data, Piece& piece, const std::vector<Chain>& chains,
                    const OrientedBox& box, const LayoutOptions& options) {
  const PieceShapes shapes = piece_shapes(data, piece);
  piece.number = piece_number(data, piece, box, options);
  std::vector<std::array<Vec2, 4>> taken;
  taken.push_back(text_box(piece.number->position, piece.number->direction, piece.number->size,
                           piece.number->text.size()));
  auto clear = [&](const std::array<Vec2, 4>& candidate) {
    for (const auto& other : taken)
      if (convex_overlap(candidate.data(), 4, other.data(), 4, 0.0)) return false;
    return true;
  };
  for (PieceLabel& label : piece.labels) {
    if (label.chain < 0) continue;
    const Chain& chain = chains[label.chain];
    const auto& loop = piece.loops[chain.loop];
    const double total = chain_length(data, piece, chain);
    auto point_at = [&](double at, Vec2* direction) {
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
      *direction = Vec2::UnitX();
      return label.position;
    };
    bool placed = false;
    const auto first_box = text_box(label.position, label.direction, label.size, label.text.size());
    if (box_on_piece(first_box, shapes) && clear(first_box)) {
      taken.push_back(first_box);
      continue;
    }
    for (double size : {label.size, 0.8 * label.size, 0.65 * label.size, 0.5 * label.size}) {
      if (size < std::min(1.2, label.size) - 1e-12) break;
      for (double fraction : {0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9, 0.05, 0.95}) {
        for (double gap : {0.6, 0.3, 1.2}) {
          Vec2 direction;
          const Vec2 on_edge = point_at(fraction * total, &direction);
          const Vec2 centre =
              on_edge + Vec2(-direction.y(), direction.x()) * (kHalfLineEm * size + gap);
          const auto candidate = text_box(centre, direction, size, label.text.size());
          if (!box_on_piece(candidate, shapes) || !clear(candidate)) continue;
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
    if (!placed) taken.push_back(first_box);
  }
}

void validate_options(const LayoutOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0) || !std::isfinite(v))
      throw InvalidInputException(std::string("layout option ") + name + " must be > 0");
  };
  auto non_negative = [](double v, const char* name) {
    if (!(v >= 0) || !std::isfinite(v))
      throw InvalidInputException(std::string("layout option ") + name + " must be >= 0");
  };
  positive(o.page.width_mm, "page width");
  positive(o.page.height_mm, "page height");
  non_negative(o.margin_mm, "margin_mm");
  non_negative(o.height_mm, "height_mm");
  non_negative(o.scale, "scale");
  non_negative(o.tab_width_mm, "tab_width_mm");
  non_negative(o.fold_angle_degrees, "fold_angle_degrees");
  non_negative(o.strong_fold_angle_degrees, "strong_fold_angle_degrees");
  non_negative(o.spacing_mm, "spacing_mm");
  positive(o.label_size_mm, "label_size_mm");
  positive(o.number_size_mm, "number_size_mm");
  non_negative(o.footer_mm, "footer_mm");
  if (!(o.tab_angle_degrees > 0 && o.tab_angle_degrees <= 90))
    throw InvalidInputException("layout option tab_angle_degrees must be in (0, 90]");
  if (!(o.scale > 0) && !(o.height_mm > 0))
    throw InvalidInputException("layout needs height_mm > 0 or scale > 0");
}

// Room kept around a piece for its tabs while splitting: a flap stays within its height of
// the seam but for the mitres at joints of up to 15 degrees and its short angled ends.
double tab_reserve_for(const LayoutOptions& o) {
  return 1.15 * o.tab_width_mm;
}

// The printable area less the footer (and the gap above it).
Vec2 usable_area(const LayoutOptions& o) {
  const double footer = o.footer_mm > 0 ? o.footer_mm + o.spacing_mm : 0.0;
  const Vec2 area(o.page.width_mm - 2 * o.margin_mm, o.page.height_mm - 2 * o.margin_mm - footer);
  const double reserve = 2 * tab_reserve_for(o);
  if (area.x() - reserve < 1.0 || area.y() - reserve < 1.0)
    throw InvalidInputException("page " + format_mm(o.page.width_mm) + " x " +
                                format_mm(o.page.height_mm) +
                                " mm leaves no room inside margins "
                                "of " +
                                format_mm(o.margin_mm) + " mm for pieces with tabs");
  return area;
}

}  // namespace

PageSize page_size_from_name(std::string_view name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const std::map<std::string, PageSize> named = {
      {"a3", {297.0, 420.0}},     {"a4", {210.0, 297.0}},    {"a5", {148.0, 210.0}},
      {"letter", {215.9, 279.4}}, {"legal", {215.9, 355.6}}, {"tabloid", {279.4, 431.8}},
  };
  if (auto it = named.find(lower); it != named.end()) return it->second;
  const std::size_t x = lower.find('x');
  if (x != std::string::npos) {
    double w = 0, h = 0;
    const char* begin = lower.data();
    const char* end = begin + lower.size();
    auto [wend, werr] = std::from_chars(begin, begin + x, w);
    auto [hend, herr] = std::from_chars(begin + x + 1, end, h);
    if (werr == std::errc() && herr == std::errc() && wend == begin + x && hend == end && w > 0 &&
        h > 0 && std::isfinite(w) && std::isfinite(h))
      return {w, h};
  }
  throw InvalidInputException("unknown page size '" + std::string(name) +
                              "': use A3, A4, A5, Letter, Legal, Tabloid or <width>x<height> in "
                              "mm (e.g. 200x300)");
}

std::string page_size_name(const PageSize& page) {
  static const std::pair<const char*, PageSize> named[] = {
      {"A3", {297.0, 420.0}},     {"A4", {210.0, 297.0}},    {"A5", {148.0, 210.0}},
      {"Letter", {215.9, 279.4}}, {"Legal", {215.9, 355.6}}, {"Tabloid", {279.4, 431.8}},
  };
  for (const auto& [name, size] : named) {
    if (size.width_mm == page.width_mm && size.height_mm == page.height_mm) return name;
  }
  std::ostringstream text;
  text << page.width_mm << "x" << page.height_mm;
  return text.str();
}

double layout_scale(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  validate_options(options);
  if (options.scale > 0) return options.scale;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const FlatStrip& strip : strips)
    for (const Vec3& v : strip.vertices3d) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  const double side = (hi - lo).maxCoeff();
  if (!(side > 0) || !std::isfinite(side))
    throw InvalidInputException(
        "cannot scale the strips to height_mm: their 3D bounding box has no extent (give a "
        "scale in mm per model unit instead)");
  return options.height_mm / side;
}

namespace {

struct Prepared {
  double mm_per_unit = 1;
  Vec2 area = Vec2::Zero();
  double reserve = 0;
  double tolerance3d = 0;
  std::vector<StripData> strips;
};

Prepared prepare(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  validate_options(options);
  std::set<int> ids;
  for (const FlatStrip& strip : strips) {
    validate_strip(strip);
    if (!ids.insert(strip.id).second)
      throw InvalidInputException("two strips have id " + std::to_string(strip.id));
  }
  Prepared p;
  p.area = usable_area(options);
  p.reserve = tab_reserve_for(options);
  if (strips.empty()) {
    p.mm_per_unit = options.scale > 0 ? options.scale : 1.0;
    return p;
  }
  p.mm_per_unit = layout_scale(strips, options);
  double largest = 0;
  for (const FlatStrip& strip : strips)
    for (const Vec3& v : strip.vertices3d) largest = std::max(largest, v.cwiseAbs().maxCoeff());
  p.tolerance3d = 1e-9 * std::max(largest, 1e-300);
  for (const FlatStrip& strip : strips) p.strips.push_back(prepare_strip(strip, p.mm_per_unit));
  return p;
}

bool strip_fits(const StripData& data, const Prepared& p) {
  return hull_fits(convex_hull(piece_points(data, data.triangles)), p.area.x() - 2 * p.reserve,
                   p.area.y() - 2 * p.reserve);
}

using ChainKey = std::tuple<int, int, int, int>;

ChainKey chain_key(const Chain& c, const std::vector<Piece>& pieces,
                   const std::vector<StripData>& strips) {
  const Piece& piece = pieces[c.piece];
  return {strips[piece.strip].strip->id, piece.index, c.loop, c.start};
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
    if (!strip2.uvs.empty() && owner != other.owner.end()) {
      const int d = third(strip2, owner->second, f.v0, f.v1);
      const Vec2 p0 = other.points[f.v0], p1 = other.points[f.v1], q = other.points[d];
      const double length = (p1 - p0).norm(), own_length = (a - b).norm();
      if (d >= 0 && length > 0 && own_length > 0) {
        // f runs v0 -> v1 glued to this edge's v1 -> v0: the same frame along (b -> a).
        const Vec2 along = (p1 - p0) / length, own_along = (a - b) / own_length;
        const double s = (q - p0).dot(along), t = cross(along, q - p0);
        const Vec2 unfolded = b + s * own_along + t * Vec2(-own_along.y(), own_along.x());
        return TexturePatch{
            {b, a, unfolded}, {strip2.uvs[f.v0], strip2.uvs[f.v1], strip2.uvs[d]}, {}};
      }
    }
  }
  const FlatStrip& strip = *data.strip;
  if (strip.uvs.empty()) return std::nullopt;
  auto owner = data.owner.find(directed_edge_key(e.v0, e.v1));
  if (owner == data.owner.end()) return std::nullopt;
  const int c = third(strip, owner->second, e.v0, e.v1);
  if (c < 0) return std::nullopt;
  return TexturePatch{{a, b, data.points[c]}, {strip.uvs[e.v0], strip.uvs[e.v1], strip.uvs[c]}, {}};
}

void add_tabs(std::vector<Piece>& pieces, const std::vector<StripData>& strips,
              const std::vector<Chain>& chains, const std::vector<SeamPair>& pairs,
              const SeamEdges& seams, const LayoutOptions& options,
              std::vector<std::string>& warnings) {
  const TabGeometry geometry{options.tab_width_mm, options.tab_angle_degrees * kDegree,
                             std::min(1.0, 0.2 * options.tab_width_mm), 1e-6};
  std::vector<std::optional<PieceShapes>> shapes(pieces.size());
  auto shapes_of = [&](int piece) -> PieceShapes& {
    if (!shapes[piece]) shapes[piece] = piece_shapes(strips[pieces[piece].strip], pieces[piece]);
    return *shapes[piece];
  };
  for (const SeamPair& pair : pairs) {
    std::vector<int> sides{pair.first};
    if (pair.second >= 0) {
      sides.push_back(pair.second);
      if (chain_key(chains[pair.second], pieces, strips) <
          chain_key(chains[pair.first], pieces, strips))
        std::swap(sides[0], sides[1]);
    }
    int best_side = -1;
    std::vector<FlapPlan> best_plans;
    double best_length = 0;
    for (int side : sides) {
      const Chain& chain = chains[side];
      const Piece& piece = pieces[chain.piece];
      const StripData& data = strips[piece.strip];
      PieceShapes& piece_shapes_ = shapes_of(chain.piece);
      const std::size_t slices_before = piece_shapes_.slices.size();
      std::vector<FlapPlan> plans = plan_flaps(data, piece, chain, geometry, piece_shapes_);
      piece_shapes_.slices.resize(slices_before);
      piece_shapes_.slice_boxes.resize(slices_before);
      const double length = plans_length(plans);
      if (length > best_length + 1e-9) {
        best_side = side;
        best_plans = std::move(plans);
        best_length = length;
      }
      if (best_length >= 0.5 * chain_length(data, piece, chain)) break;
    }
    if (best_side < 0) {
      warnings.push_back("seam " + pair.printed + " has no room for a glue tab on either side");
      continue;
    }
    const Chain& chain = chains[best_side];
    PieceShapes& piece_shapes_ = shapes_of(chain.piece);
    for (const FlapPlan& plan : best_plans)
      for (const auto& slice : plan.slices) {
        Box2 box;
        for (const Vec2& c : slice) box.add(c);
        piece_shapes_.slices.push_back(slice);
        piece_shapes_.slice_boxes.push_back(box);
      }
    commit_flaps(pieces[chain.piece], chain, pair.printed, best_plans, [&](int edge) {
      return tab_texture(pieces, strips, seams, chain.piece, chain.loop, edge);
    });
  }
}

struct Orientation {
  OrientedBox box;
  bool fits = true;
};

Orientation orient_piece(const StripData& data, const Piece& piece, const Vec2& area) {
  std::vector<Vec2> points = piece_points(data, piece.triangles);
  for (const Flap& flap : piece.flaps)
    points.insert(points.end(), flap.outer.begin(), flap.outer.end());
  Orientation o;
  o.box = tightest_box(convex_hull(points), area.x(), area.y(), &o.fits);
  return o;
}

PlacedPiece place_piece(const StripData& data, const Piece& piece, const OrientedBox& box,
                        const PackedRectangle& at, const LayoutOptions& options,
                        double mm_per_unit) {
  const FlatStrip& strip = *data.strip;
  double theta = -box.angle;
  double min_x = box.min.x(), max_y = box.min.y() + box.size.y();
  if (at.rotated) {
    theta += std::numbers::pi / 2;
    min_x = -(box.min.y() + box.size.y());
    max_y = box.min.x() + box.size.x();
  }
  Eigen::Matrix2d rotation;
  rotation << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  const Eigen::Matrix2d linear = Eigen::Vector2d(1, -1).asDiagonal() * rotation;
  const Vec2 translation(options.margin_mm + at.x - min_x, options.margin_mm + at.y + max_y);
  auto to_page = [&](const Vec2& p) { return Vec2(linear * p + translation); };
  auto direction_degrees = [&](const Vec2& d) { return upright_degrees(linear * d); };

  PlacedPiece placed;
  placed.strip_id = strip.id;
  placed.piece_index = piece.index;
  placed.piece_count = piece.count;
  placed.transform.linear = linear * mm_per_unit;
  placed.transform.translation = translation;
  placed.transform.rotation_degrees = theta / kDegree;

  std::unordered_map<int, int> local;
  auto local_index = [&](int v) {
    auto [it, inserted] = local.emplace(v, static_cast<int>(placed.vertices.size()));
    if (inserted) {
      placed.vertices.push_back(to_page(data.points[v]));
      placed.strip_vertex.push_back(v);
      if (!strip.uvs.empty()) placed.uvs.push_back(strip.uvs[v]);
    }
    return it->second;
  };
  for (int t : piece.triangles) {
    const Triangle& tri = strip.triangles[t];
    placed.triangles.push_back({local_index(tri[0]), local_index(tri[1]), local_index(tri[2])});
  }
  for (const auto& loop : piece.loops) {
    std::vector<Vec2> outline, cut;
    for (const PieceEdge& e : loop) {
      const Vec2 a = to_page(data.points[e.v0]), b = to_page(data.points[e.v1]);
      outline.push_back(a);
      if (e.flap < 0) {
        cut.push_back(a);
      } else if (e.flap_first) {
        cut.push_back(a);
        for (const Vec2& q : piece.flaps[e.flap].outer) cut.push_back(to_page(q));
      }
      placed.edges.push_back({a, b, e.kind, e.printed, e.flap >= 0});
    }
    placed.outline.push_back(std::move(outline));
    placed.cut_outline.push_back(std::move(cut));
  }
  for (FoldLine fold :
       piece_folds(data, piece, options.fold_angle_degrees, options.strong_fold_angle_degrees)) {
    fold.a = to_page(fold.a);
    fold.b = to_page(fold.b);
    placed.folds.push_back(fold);
  }
  for (const PieceTab& pieceTab : piece.tabs) {
    Tab tab;
    tab.label = pieceTab.label;
    for (int f : pieceTab.flaps) {
      const Flap& flap = piece.flaps[f];
      std::vector<Vec2> polygon, base;
      for (auto it = flap.base.rbegin(); it != flap.base.rend(); ++it)
        polygon.push_back(to_page(*it));
      for (const Vec2& q : flap.outer) polygon.push_back(to_page(q));
      for (const Vec2& p : flap.base) base.push_back(to_page(p));
      tab.flaps.push_back(std::move(polygon));
      tab.bases.push_back(std::move(base));
      for (TexturePatch patch : flap.texture) {
        for (Vec2& corner : patch.corners) corner = to_page(corner);
        for (Vec2& point : patch.clip) point = to_page(point);
        tab.texture.push_back(std::move(patch));
      }
    }
    placed.tabs.push_back(std::move(tab));
  }
  for (const auto& mark : piece.marks) placed.marks.push_back({to_page(mark[0]), to_page(mark[1])});
  for (const PieceLabel& label : piece.labels)
    placed.labels.push_back(
        {label.text, to_page(label.position), direction_degrees(label.direction), label.size});
  const PieceLabel number = piece.number ? *piece.number : piece_number(data, piece, box, options);
  placed.number = {number.text, to_page(number.position), direction_degrees(number.direction),
                   number.size};
  return placed;
}

void add_page_furniture(Page& page, int index, int count, const LayoutOptions& options,
                        double mm_per_unit) {
  const double bottom = options.page.height_mm - options.margin_mm;
  const double width = options.page.width_mm - 2 * options.margin_mm;
  const double text = std::min(3.0, 0.4 * options.footer_mm);
  page.footer.text = "page " + std::to_string(index + 1) + " / " + std::to_string(count);
  page.footer.size_mm = text;
  const double footer_width = 0.6 * text * static_cast<double>(page.footer.text.size());
  page.footer.position = Vec2(options.page.width_mm - options.margin_mm - 0.5 * footer_width,
                              bottom - 0.5 * options.footer_mm);
  ScaleBar& bar = page.scale_bar;
  if (options.footer_mm <= 0) {
    bar.length_mm = 0;
    page.footer.text.clear();
    return;
  }
  bar.length_mm = 10;
  for (double length : {20.0, 50.0, 100.0})
    if (length <= width / 3) bar.length_mm = length;
  bar.tick_spacing_mm = bar.length_mm / 5;
  bar.tick_height_mm = std::min(2.0, 0.3 * options.footer_mm);
  bar.start = Vec2(options.margin_mm, bottom - 0.5 * (options.footer_mm - bar.tick_height_mm));
  bar.caption.text =
      format_mm(bar.length_mm) + " mm (1 model unit = " + format_number(mm_per_unit, 4) + " mm)";
  bar.caption.size_mm = text;
  const double caption_width = 0.6 * text * static_cast<double>(bar.caption.text.size());
  bar.caption.position = Vec2(options.margin_mm + bar.length_mm + 3 + 0.5 * caption_width,
                              bottom - 0.5 * options.footer_mm);
}

}  // namespace

std::vector<int> strips_exceeding_page(const std::vector<FlatStrip>& strips,
                                       const LayoutOptions& options) {
  Prepared p = prepare(strips, options);
  std::vector<int> ids;
  for (const StripData& data : p.strips)
    if (!data.triangles.empty() && !strip_fits(data, p)) ids.push_back(data.strip->id);
  return ids;
}

PatternLayout layout_pages(const std::vector<FlatStrip>& strips, const LayoutOptions& options) {
  Prepared p = prepare(strips, options);
  PatternLayout layout;
  layout.page = options.page;
  layout.margin_mm = options.margin_mm;
  layout.mm_per_unit = p.mm_per_unit;
  std::vector<std::string>& warnings = layout.warnings;

  std::set<std::string> used_labels;
  for (const FlatStrip& strip : strips)
    for (const BoundaryEdge& e : strip.boundary)
      if (e.kind == EdgeKind::Seam) used_labels.insert(e.label);

  std::vector<Piece> pieces;
  for (int s = 0; s < static_cast<int>(p.strips.size()); ++s) {
    StripData& data = p.strips[s];
    if (data.triangles.empty()) {
      warnings.push_back(strip_name(*data.strip) + " has no triangles; skipped");
      continue;
    }
    std::vector<std::vector<int>> sets;
    if (strip_fits(data, p)) {
      sets.push_back(data.triangles);
    } else {
      const double w = p.area.x() - 2 * p.reserve, h = p.area.y() - 2 * p.reserve;
      sets = split_to_fit(data, w, h, used_labels);
      bool unused = false;
      const OrientedBox box =
          tightest_box(convex_hull(piece_points(data, data.triangles)), w, h, &unused);
      warnings.push_back(strip_name(*data.strip) + " (" + format_mm(box.size.x()) + " x " +
                         format_mm(box.size.y()) +
                         " mm) fits no page orientation with room "
                         "for tabs (" +
                         format_mm(w) + " x " + format_mm(h) + " mm); split into " +
                         std::to_string(sets.size()) + " pieces at inner edges");
    }
    for (int k = 0; k < static_cast<int>(sets.size()); ++k) {
      Piece piece;
      piece.strip = s;
      piece.index = k;
      piece.count = static_cast<int>(sets.size());
      piece.triangles = std::move(sets[k]);
      piece.loops = piece_loops(data, piece.triangles, warnings);
      pieces.push_back(std::move(piece));
    }
  }

  const SeamEdges seams = match_seam_edges(pieces, p.strips);
  const std::vector<Chain> chains = seam_chains(pieces, p.strips, seams, p.tolerance3d);
  const std::vector<SeamPair> pairs = pair_chains(chains, seams, pieces, p.tolerance3d, warnings);
  for (const SeamPair& pair : pairs) {
    for (int side : {pair.first, pair.second}) {
      if (side < 0) continue;
      const Chain& chain = chains[side];
      Piece& piece = pieces[chain.piece];
      auto& loop = piece.loops[chain.loop];
      for (int i = 0; i < chain.count; ++i)
        loop[(chain.start + i) % loop.size()].printed = pair.printed;
      piece.labels.push_back(
          chain_label(p.strips[piece.strip], piece, chain, pair.printed, options.label_size_mm));
      piece.labels.back().chain = side;
      add_alignment_marks(p.strips[piece.strip], piece, chain, options.alignment_mark_mm);
    }
  }
  if (options.tab_width_mm > 0) add_tabs(pieces, p.strips, chains, pairs, seams, options, warnings);

  std::vector<Orientation> orientations;
  std::vector<int> packed, oversized;
  std::vector<Vec2> sizes;
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i) {
    orientations.push_back(orient_piece(p.strips[pieces[i].strip], pieces[i], p.area));
    const Orientation& o = orientations.back();
    arrange_labels(p.strips[pieces[i].strip], pieces[i], chains, o.box, options);
    if (o.fits && o.box.size.minCoeff() > 0) {
      packed.push_back(i);
      sizes.push_back(o.box.size);
    } else {
      oversized.push_back(i);
      if (!o.fits)
        warnings.push_back("piece " + std::to_string(p.strips[pieces[i].strip].strip->id) +
                           (pieces[i].count > 1 ? "." + std::to_string(pieces[i].index + 1) : "") +
                           " (" + format_mm(o.box.size.x()) + " x " + format_mm(o.box.size.y()) +
                           " mm with tabs) does not fit the printable area (" +
                           format_mm(p.area.x()) + " x " + format_mm(p.area.y()) +
                           " mm) and overflows its page: lower height_mm or use a larger page");
    }
  }
  const PackResult result =
      pack_with_spacing(sizes, p.area.x(), p.area.y(), options.spacing_mm, options.packing);
  layout.shelf_page_count = (options.packing == PackingMethod::Shelf
                                 ? result.pages
                                 : pack_with_spacing(sizes, p.area.x(), p.area.y(),
                                                     options.spacing_mm, PackingMethod::Shelf)
                                       .pages) +
                            static_cast<int>(oversized.size());
  layout.pages.resize(result.pages + oversized.size());
  for (std::size_t k = 0; k < packed.size(); ++k) {
    const int i = packed[k];
    const PackedRectangle& at = result.placements[k];
    layout.pages[at.page].pieces.push_back(place_piece(
        p.strips[pieces[i].strip], pieces[i], orientations[i].box, at, options, p.mm_per_unit));
  }
  for (std::size_t k = 0; k < oversized.size(); ++k) {
    const int i = oversized[k];
    layout.pages[result.pages + k].pieces.push_back(
        place_piece(p.strips[pieces[i].strip], pieces[i], orientations[i].box, {0, 0, 0, false},
                    options, p.mm_per_unit));
  }
  for (int i = 0; i < static_cast<int>(layout.pages.size()); ++i)
    add_page_furniture(layout.pages[i], i, static_cast<int>(layout.pages.size()), options,
                       p.mm_per_unit);
  return layout;
}

std::array<Vec2, 4> label_box(const Label& label) {
  const double angle = label.angle_degrees * kDegree;
  return text_box(label.position, Vec2(std::cos(angle), std::sin(angle)), label.size_mm,
                  label.text.size());
}

std::vector<PackedRectangle> pack_rectangles(const std::vector<Vec2>& sizes, double bin_width,
                                             double bin_height, double spacing,
                                             PackingMethod method) {
  return pack_with_spacing(sizes, bin_width, bin_height, spacing, method).placements;
}

int shelf_pack_page_count(const std::vector<Vec2>& sizes, double bin_width, double bin_height,
                          double spacing) {
  return pack_with_spacing(sizes, bin_width, bin_height, spacing, PackingMethod::Shelf).pages;
}

}  // namespace papercraft
