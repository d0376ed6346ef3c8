#pragma once
// Exact closest points on segments and triangles (Ericson, Real-Time Collision Detection,
// section 5.1.5), robust for degenerate triangles: a triangle with zero area (collinear or
// coincident corners, e.g. the segment triangle (a, b, b)) is treated as the union of its
// three edges.

#include "core/triangle_mesh.h"

namespace papercraft {

/// The point of a triangle (a, b, c) nearest to a query point.
struct TriangleClosestPoint {
  Vec3 point;
  /// Weights of a, b, c (non-negative, summing to 1) with point = wa a + wb b + wc c.
  Vec3 barycentric;
  double squared_distance = 0.0;

  double distance() const;
};

/// The point of the triangle (a, b, c) nearest to p. Any corners may coincide.
/// \pre all coordinates are finite.
TriangleClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                               const Vec3& c);

/// True when (a, b, c) is far enough from degenerate (height/longest edge above about 1e-5)
/// for Ericson's region tests alone to be accurate; such triangles may be queried with
/// closest_point_on_regular_triangle, skipping the shape test of closest_point_on_triangle.
bool is_regular_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

/// closest_point_on_triangle for a triangle known to be regular (a BVH caches the test).
/// \pre is_regular_triangle(a, b, c).
TriangleClosestPoint closest_point_on_regular_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                                       const Vec3& c);

/// Squared distance from p to the triangle (a, b, c); same contract as
/// closest_point_on_triangle.
double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// The point of the segment [a, b] nearest to p, as a + t (b - a) with t in [0, 1] returned
/// in `parameter` (0 when a == b).
Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b,
                              double* parameter = nullptr);

}  // namespace papercraft
