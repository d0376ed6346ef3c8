// Collision tests against a piece's own triangles and tab slices.
#include "nodes/layout/piece_shapes.h"

#include <algorithm>
#include <cstddef>

namespace papercraft::layout_internal {
namespace {

bool inside_triangles(const Vec2& p, const PieceShapes& shapes) {
  Box2 at;
  at.add(p - Vec2::Constant(1e-9));
  at.add(p + Vec2::Constant(1e-9));
  bool inside = false;
  shapes.near(at, [&](int t) {
    if (inside) return;
    const Box2& box = shapes.triangle_boxes[t];
    if (p.x() < box.lo.x() - 1e-9 || p.x() > box.hi.x() + 1e-9 || p.y() < box.lo.y() - 1e-9 ||
        p.y() > box.hi.y() + 1e-9)
      return;
    const auto& c = shapes.triangles[t];
    const double scale = 1e-9 * (box.hi - box.lo).squaredNorm();
    inside = cross(c[1] - c[0], p - c[0]) >= -scale && cross(c[2] - c[1], p - c[1]) >= -scale &&
             cross(c[0] - c[2], p - c[2]) >= -scale;
  });
  return inside;
}

}  // namespace

PieceShapes piece_shapes(const StripData& data, const Piece& piece) {
  PieceShapes shapes;
  for (int t : piece.triangles) {
    const Triangle& tri = data.strip->triangles[t];
    std::array<Vec2, 3> corners{data.points[tri[0]], data.points[tri[1]], data.points[tri[2]]};
    Box2 box;
    for (const Vec2& c : corners) box.add(c);
    shapes.triangles.push_back(corners);
    shapes.triangle_boxes.push_back(box);
    shapes.bounds.add(box.lo);
    shapes.bounds.add(box.hi);
  }
  if (shapes.triangles.empty()) return shapes;
  const Vec2 extent = shapes.bounds.hi - shapes.bounds.lo;
  shapes.bucket_mm = std::max(shapes.bucket_mm, extent.maxCoeff() / 256.0);
  shapes.columns =
      static_cast<int>((shapes.bounds.hi.x() - shapes.bounds.lo.x()) / shapes.bucket_mm) + 1;
  shapes.rows =
      static_cast<int>((shapes.bounds.hi.y() - shapes.bounds.lo.y()) / shapes.bucket_mm) + 1;
  shapes.buckets.resize(static_cast<std::size_t>(shapes.columns) * shapes.rows);
  for (int t = 0; t < static_cast<int>(shapes.triangles.size()); ++t) {
    const auto [c0, r0] = shapes.bucket(shapes.triangle_boxes[t].lo);
    const auto [c1, r1] = shapes.bucket(shapes.triangle_boxes[t].hi);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        shapes.buckets[static_cast<std::size_t>(r) * shapes.columns + c].push_back(t);
  }
  return shapes;
}

bool overlaps_triangles(const Vec2* polygon, int n, const PieceShapes& shapes, double depth) {
  Box2 box;
  for (int i = 0; i < n; ++i) box.add(polygon[i]);
  bool hit = false;
  shapes.near(box, [&](int t) {
    hit = hit || (box.overlaps(shapes.triangle_boxes[t]) &&
                  convex_overlap(polygon, n, shapes.triangles[t].data(), 3, depth));
  });
  return hit;
}

bool slices_collide(const std::vector<std::vector<Vec2>>& slices, const PieceShapes& shapes,
                    double depth) {
  for (const auto& slice : slices) {
    Box2 box;
    for (const Vec2& c : slice) box.add(c);
    const int n = static_cast<int>(slice.size());
    if (overlaps_triangles(slice.data(), n, shapes, depth)) return true;
    for (std::size_t q = 0; q < shapes.slices.size(); ++q)
      if (box.overlaps(shapes.slice_boxes[q]) &&
          convex_overlap(slice.data(), n, shapes.slices[q].data(),
                         static_cast<int>(shapes.slices[q].size()), depth))
        return true;
  }
  return false;
}

bool box_on_piece(const std::array<Vec2, 4>& box, const PieceShapes& shapes) {
  for (int i = 0; i < 4; ++i) {
    if (!inside_triangles(box[i], shapes)) return false;
    if (!inside_triangles(0.5 * (box[i] + box[(i + 1) % 4]), shapes)) return false;
  }
  return inside_triangles(0.25 * (box[0] + box[1] + box[2] + box[3]), shapes);
}

}  // namespace papercraft::layout_internal
