#pragma once
// Plane geometry of the layout: convex hulls, oriented bounding boxes (rotating calipers),
// polygon clipping, convex overlap tests and the boxes text takes on the page.

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "core/triangle_mesh.h"

namespace papercraft::layout_internal {

inline constexpr double kDegree = std::numbers::pi / 180.0;
inline constexpr double kFitSlack = 1e-7;  // mm; rounding in rotations must not reject a fit
// Text boxes: an advance of 0.6 em per character (sans-serif digits and capitals) and
// 0.6 em either side of the centre line, as the exporters centre text.
inline constexpr double kCharWidthEm = 0.6;
inline constexpr double kHalfLineEm = 0.6;

/// The z component of the cross product of a and b (positive when b turns left of a).
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// `d` turned a quarter turn clockwise: its right-hand side in a y-up frame.
inline Vec2 right_normal(const Vec2& d) {
  return {d.y(), -d.x()};
}

/// Signed area of a polygon, positive when it is counter-clockwise.
double signed_area(const std::vector<Vec2>& polygon);

/// Convex hull by Andrew's monotone chain; counter-clockwise, collinear points dropped.
std::vector<Vec2> convex_hull(std::vector<Vec2> points);

/// The bounding rectangle of a hull rotated by -angle: the points p with R(-angle) p inside
/// [min, min + size].
struct OrientedBox {
  double angle = 0.0;
  Vec2 min = Vec2::Zero();
  Vec2 size = Vec2::Zero();
};

/// True when a rectangle of `size` fits width x height in one of its two orientations.
bool fits_area(const Vec2& size, double width, double height);

/// The tightest orientation of `hull`: minimal area among those fitting width x height, else
/// minimal area overall; turned so that size.x >= size.y. Sets *fits to whether one fits.
OrientedBox tightest_box(const std::vector<Vec2>& hull, double width, double height, bool* fits);

/// True when some orientation of `hull` fits width x height.
bool hull_fits(const std::vector<Vec2>& hull, double width, double height);

/// Separating axis test for convex polygons (either orientation): true when the interiors
/// overlap deeper than `depth` along every edge normal, so shared edges and touching
/// corners do not count.
bool convex_overlap(const Vec2* a, int na, const Vec2* b, int nb, double depth);

/// An axis-aligned box grown point by point; boxes that only touch do not overlap.
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

/// Keeps the part of convex or simple `polygon` where side(x) >= 0 (Sutherland-Hodgman).
std::vector<Vec2> clip(const std::vector<Vec2>& polygon,
                       const std::function<double(const Vec2&)>& side);

/// The parts of segment a-b outside the convex polygon (corners counter-clockwise or
/// clockwise): none, one or two segments (Cyrus-Beck).
std::vector<std::array<Vec2, 2>> segment_outside(const Vec2& a, const Vec2& b,
                                                 const std::array<Vec2, 4>& convex);

/// True when segment a-b passes through the interior of the convex quad.
bool segment_crosses(const Vec2& a, const Vec2& b, const std::array<Vec2, 4>& convex);

/// The box a line of `characters` characters of height `size` takes, centred on `centre`
/// and running along `direction`: corners counter-clockwise in the text's frame.
std::array<Vec2, 4> text_box(const Vec2& centre, const Vec2& direction, double size,
                             std::size_t characters);

}  // namespace papercraft::layout_internal
