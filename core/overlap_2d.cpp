#include "core/overlap_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.h"

namespace papercraft {
namespace {

constexpr std::int64_t kMaxCellsPerTriangle = 4096;

// Overlap of the projections of p and q onto the unit normal of edge (a, b); +infinity
// when the edge has no length (it defines no axis).
double axis_overlap(const Vec2& a, const Vec2& b, const Triangle2& p, const Triangle2& q) {
  Vec2 edge = b - a;
  double length = edge.norm();
  if (length == 0.0) return std::numeric_limits<double>::infinity();
  Vec2 normal(-edge.y() / length, edge.x() / length);
  double p_min = std::numeric_limits<double>::infinity(), p_max = -p_min;
  double q_min = p_min, q_max = -p_min;
  for (int i = 0; i < 3; ++i) {
    double s = normal.dot(p[i]);
    p_min = std::min(p_min, s);
    p_max = std::max(p_max, s);
    double t = normal.dot(q[i]);
    q_min = std::min(q_min, t);
    q_max = std::max(q_max, t);
  }
  return std::min(p_max, q_max) - std::max(p_min, q_min);
}

bool has_interior(const Triangle2& t) {
  Vec2 u = t[1] - t[0], v = t[2] - t[0];
  return u.x() * v.y() - u.y() * v.x() != 0.0;
}

std::int64_t clamp_cell(double coordinate) {
  constexpr double kLimit = 1e9;
  return static_cast<std::int64_t>(std::floor(std::clamp(coordinate, -kLimit, kLimit)));
}

}  // namespace

double triangle_penetration(const Triangle2& p, const Triangle2& q) {
  if (!has_interior(p) || !has_interior(q)) return 0.0;
  double depth = std::numeric_limits<double>::infinity();
  for (const Triangle2* t : {&p, &q}) {
    for (int i = 0; i < 3; ++i) {
      depth = std::min(depth, axis_overlap((*t)[i], (*t)[(i + 1) % 3], p, q));
      if (depth <= 0.0) return depth;
    }
  }
  // Every edge of a triangle with interior has a length, so depth is finite here.
  return depth;
}

TriangleGrid2::TriangleGrid2(double cell_size) : cell_size_(cell_size) {
  if (!(cell_size > 0.0) || !std::isfinite(cell_size))
    throw InvalidInputException("overlap grid: cell size must be positive and finite");
}

std::array<std::int64_t, 4> TriangleGrid2::cell_range(const Triangle2& t) const {
  Vec2 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]);
  Vec2 hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
  return {clamp_cell(lo.x() / cell_size_), clamp_cell(lo.y() / cell_size_),
          clamp_cell(hi.x() / cell_size_), clamp_cell(hi.y() / cell_size_)};
}

void TriangleGrid2::insert(const Triangle2& triangle) {
  int id = static_cast<int>(triangles_.size());
  triangles_.push_back(triangle);
  stamp_.push_back(0);
  auto [x0, y0, x1, y1] = cell_range(triangle);
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerTriangle) {
    oversized_.push_back(id);
    return;
  }
  for (std::int64_t ix = x0; ix <= x1; ++ix)
    for (std::int64_t iy = y0; iy <= y1; ++iy) cells_[key(ix, iy)].push_back(id);
}

bool TriangleGrid2::overlaps(const Triangle2& triangle, double tolerance) {
  ++query_;
  auto test = [&](int id) {
    if (stamp_[id] == query_) return false;
    stamp_[id] = query_;
    return triangle_penetration(triangle, triangles_[id]) > tolerance;
  };
  for (int id : oversized_)
    if (test(id)) return true;
  auto [x0, y0, x1, y1] = cell_range(triangle);
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerTriangle) {
    for (int id = 0; id < static_cast<int>(triangles_.size()); ++id)
      if (test(id)) return true;
    return false;
  }
  for (std::int64_t ix = x0; ix <= x1; ++ix) {
    for (std::int64_t iy = y0; iy <= y1; ++iy) {
      auto it = cells_.find(key(ix, iy));
      if (it == cells_.end()) continue;
      for (int id : it->second)
        if (test(id)) return true;
    }
  }
  return false;
}

}  // namespace papercraft
