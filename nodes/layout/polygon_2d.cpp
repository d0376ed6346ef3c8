// Plane geometry of the layout: convex hulls, oriented bounding boxes (rotating calipers),
// polygon clipping, convex overlap tests and text boxes.
#include "nodes/layout/polygon_2d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace papercraft::layout_internal {
namespace {

OrientedBox oriented_box(const std::vector<Vec2>& hull, double angle) {
  OrientedBox box;
  box.angle = angle;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  // Each point turned by -angle, the sine and cosine taken once for the whole hull.
  const double c = std::cos(-angle), s = std::sin(-angle);
  for (const Vec2& p : hull) {
    const Vec2 q(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  box.min = lo;
  box.size = hi - lo;
  return box;
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

// Akl and Toussaint's filter: the points farthest along eight directions (the axes and the
// diagonals) span a convex polygon inside the hull; a point inside it by more than a rounding
// margin is no corner of the hull, so it is dropped before the sort. Points on or near the
// polygon's sides stay, so the hull the monotone chain builds is the same.
void drop_deep_interior(std::vector<Vec2>& points) {
  if (points.size() < 32) return;
  // Counter-clockwise from the left: min x, min x+y, min y, max x-y, max x, max x+y, max y,
  // min x-y.
  const auto key = [](const Vec2& p, int k) {
    switch (k) {
      case 0: return -p.x();
      case 1: return -(p.x() + p.y());
      case 2: return -p.y();
      case 3: return p.x() - p.y();
      case 4: return p.x();
      case 5: return p.x() + p.y();
      case 6: return p.y();
      default: return -(p.x() - p.y());
    }
  };
  std::array<Vec2, 8> extreme;
  extreme.fill(points.front());
  for (const Vec2& p : points)
    for (int k = 0; k < 8; ++k)
      if (key(p, k) > key(extreme[k], k)) extreme[k] = p;
  std::vector<Vec2> polygon;
  for (const Vec2& p : extreme)
    if (polygon.empty() || (p != polygon.back() && p != polygon.front())) polygon.push_back(p);
  if (polygon.size() < 3) return;
  const double extent = (extreme[4].x() - extreme[0].x()) + (extreme[6].y() - extreme[2].y());
  const double margin = 1e-9 * extent;
  const auto deep_inside = [&](const Vec2& p) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2& a = polygon[i];
      const Vec2 d = polygon[(i + 1) % polygon.size()] - a;
      if (cross(d, p - a) <= margin * d.norm()) return false;
    }
    return true;
  };
  points.erase(std::remove_if(points.begin(), points.end(), deep_inside), points.end());
}

}  // namespace

double signed_area(const std::vector<Vec2>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    area += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * area;
}

std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  drop_deep_interior(points);
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

bool fits_area(const Vec2& size, double width, double height) {
  return (size.x() <= width + kFitSlack && size.y() <= height + kFitSlack) ||
         (size.y() <= width + kFitSlack && size.x() <= height + kFitSlack);
}

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

std::array<Vec2, 4> text_box(const Vec2& centre, const Vec2& direction, double size,
                             std::size_t characters) {
  const Vec2 along = direction.normalized() * (0.5 * kCharWidthEm * size * characters + 0.1 * size);
  const Vec2 across = Vec2(-direction.y(), direction.x()).normalized() * (kHalfLineEm * size);
  return {centre - along - across, centre + along - across, centre + along + across,
          centre - along + across};
}

namespace {

// The interval [t0, t1] of a + t (b - a), t in [0, 1], inside the convex polygon; empty when
// t0 >= t1.
std::pair<double, double> inside_interval(const Vec2& a, const Vec2& b,
                                          const std::array<Vec2, 4>& convex) {
  double area = 0;
  for (int i = 0; i < 4; ++i) area += cross(convex[i], convex[(i + 1) % 4]);
  const double orientation = area >= 0 ? 1.0 : -1.0;
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  for (int i = 0; i < 4; ++i) {
    const Vec2 p = convex[i], q = convex[(i + 1) % 4];
    // Inside: orientation * cross(q - p, x - p) > 0.
    const double at_a = orientation * cross(q - p, a - p);
    const double slope = orientation * cross(q - p, d);
    if (slope == 0) {
      if (at_a <= 0) return {1, 0};
      continue;
    }
    const double t = -at_a / slope;
    if (slope > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return {t0, t1};
}

}  // namespace

std::vector<std::array<Vec2, 2>> segment_outside(const Vec2& a, const Vec2& b,
                                                 const std::array<Vec2, 4>& convex) {
  const auto [t0, t1] = inside_interval(a, b, convex);
  if (t0 >= t1) return {{a, b}};
  std::vector<std::array<Vec2, 2>> parts;
  const Vec2 d = b - a;
  if (t0 > 1e-9) parts.push_back({a, a + t0 * d});
  if (t1 < 1 - 1e-9) parts.push_back({a + t1 * d, b});
  return parts;
}

bool segment_crosses(const Vec2& a, const Vec2& b, const std::array<Vec2, 4>& convex) {
  const auto [t0, t1] = inside_interval(a, b, convex);
  return t0 < t1;
}

}  // namespace papercraft::layout_internal
