// Collision tests against a piece's own triangles and tab slices.
#include "nodes/layout/piece_shapes.h"

#include <cstddef>

namespace papercraft::layout_internal {
namespace {

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
  }
  return shapes;
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

bool box_on_piece(const std::array<Vec2, 4>& box, const PieceShapes& shapes) {
  for (int i = 0; i < 4; ++i) {
    if (!inside_triangles(box[i], shapes)) return false;
    if (!inside_triangles(0.5 * (box[i] + box[(i + 1) % 4]), shapes)) return false;
  }
  return inside_triangles(0.25 * (box[0] + box[1] + box[2] + box[3]), shapes);
}

}  // namespace papercraft::layout_internal
