#include "core/closest_point.h"

#include <algorithm>
#include <cmath>

namespace papercraft {
namespace {

// Below this value of |(b-a)x(c-a)|^2 / (longest edge)^4 (a height/length ratio of about
// 1e-5) the region tests of Ericson's method rest on cancelling products, so the result is
// cross-checked against the three edges. Every candidate lies on the triangle, so taking
// the minimum can only improve it.
constexpr double kSliverQuality = 1e-10;

TriangleClosestPoint make_result(const Vec3& p, const Vec3& point, double wa, double wb,
                                 double wc) {
  return {point, Vec3(wa, wb, wc), (p - point).squaredNorm()};
}

TriangleClosestPoint closest_on_edges(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  double t = 0.0;
  Vec3 q = closest_point_on_segment(p, a, b, &t);
  TriangleClosestPoint best = make_result(p, q, 1.0 - t, t, 0.0);
  q = closest_point_on_segment(p, b, c, &t);
  double d2 = (p - q).squaredNorm();
  if (d2 < best.squared_distance) best = {q, Vec3(0.0, 1.0 - t, t), d2};
  q = closest_point_on_segment(p, c, a, &t);
  d2 = (p - q).squaredNorm();
  if (d2 < best.squared_distance) best = {q, Vec3(t, 0.0, 1.0 - t), d2};
  return best;
}

// Ericson, Real-Time Collision Detection, 5.1.5 (ClosestPtPointTriangle).
// \pre the triangle has non-zero area (every divisor below is then positive).
TriangleClosestPoint closest_by_regions(const Vec3& p, const Vec3& a, const Vec3& b,
                                        const Vec3& c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return make_result(p, a, 1.0, 0.0, 0.0);

  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return make_result(p, b, 0.0, 1.0, 0.0);

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return make_result(p, a + v * ab, 1.0 - v, v, 0.0);
  }

  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return make_result(p, c, 0.0, 0.0, 1.0);

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return make_result(p, a + w * ac, 1.0 - w, 0.0, w);
  }

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return make_result(p, b + w * (c - b), 0.0, 1.0 - w, w);
  }

  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator;
  const double w = vc * denominator;
  return make_result(p, a + ab * v + ac * w, 1.0 - v - w, v, w);
}

}  // namespace

double TriangleClosestPoint::distance() const {
  return std::sqrt(squared_distance);
}

Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b, double* parameter) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  double t = 0.0;
  if (length2 > 0.0) t = std::clamp(ab.dot(p - a) / length2, 0.0, 1.0);
  if (parameter) *parameter = t;
  if (t == 1.0) return b;
  return a + t * ab;
}

bool is_regular_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double normal2 = (b - a).cross(c - a).squaredNorm();
  const double longest2 =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return normal2 > kSliverQuality * longest2 * longest2;
}

TriangleClosestPoint closest_point_on_regular_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                                       const Vec3& c) {
  return closest_by_regions(p, a, b, c);
}

TriangleClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                               const Vec3& c) {
  if (is_regular_triangle(a, b, c)) return closest_by_regions(p, a, b, c);
  const double normal2 = (b - a).cross(c - a).squaredNorm();
  TriangleClosestPoint best = closest_on_edges(p, a, b, c);
  if (normal2 > 0.0) {
    TriangleClosestPoint by_regions = closest_by_regions(p, a, b, c);
    if (by_regions.squared_distance < best.squared_distance) best = by_regions;
  }
  return best;
}

double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return closest_point_on_triangle(p, a, b, c).squared_distance;
}

}  // namespace papercraft
