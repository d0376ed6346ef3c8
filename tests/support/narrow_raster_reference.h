#pragma once
// Reference computations of narrow_raster's counts (core/piece_width.h) on a given grid (its
// origin and cell), for the tests and the merge bench: by brute force over the cells a disc
// spans, and by squared Euclidean distance transforms (Felzenszwalb & Huttenlocher 2012), the
// method narrow_raster used before it checked rows. Both see the piece as narrow_raster does: a
// cell is inside when a triangle covers its centre; a disc centre when no outside cell centre
// lies closer than r + 1/2 cells (r the disc's radius in cells); narrow when inside and no
// disc centre lies within r.

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/piece_width.h"

namespace papercraft::testing {

// The cells of `grid` around the piece (its bounding box and `pad` cells more on each side)
// whose centre a triangle covers: `inside` is nx by ny, cell (x, y) being the grid's cell
// (x0 + x, y0 + y).
struct InsideCells {
  int x0 = 0, y0 = 0, nx = 0, ny = 0;
  std::vector<char> inside;
};

inline InsideCells inside_cells(const std::vector<Vec2>& points,
                                const std::vector<Triangle>& triangles, const NarrowRaster& grid,
                                int pad) {
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  InsideCells cells;
  cells.x0 = static_cast<int>(std::floor((lo.x() - grid.origin.x()) / grid.cell)) - pad;
  cells.y0 = static_cast<int>(std::floor((lo.y() - grid.origin.y()) / grid.cell)) - pad;
  cells.nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / grid.cell)) + 2 * pad + 1;
  cells.ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / grid.cell)) + 2 * pad + 1;
  cells.inside.assign(std::size_t(cells.nx) * cells.ny, 0);
  auto cross = [](const Vec2& p, const Vec2& q, const Vec2& s) {
    return (q - p).x() * (s - p).y() - (q - p).y() * (s - p).x();
  };
  for (const Triangle& t : triangles) {
    Vec2 v[3];
    for (int k = 0; k < 3; ++k) v[k] = (points[t[k]] - grid.origin) / grid.cell;
    const double area = cross(v[0], v[1], v[2]);
    if (area == 0.0) continue;
    const double sign = area > 0 ? 1.0 : -1.0;
    for (int y = 0; y < cells.ny; ++y)
      for (int x = 0; x < cells.nx; ++x) {
        const Vec2 c(cells.x0 + x + 0.5, cells.y0 + y + 0.5);
        if (sign * cross(v[0], v[1], c) >= 0 && sign * cross(v[1], v[2], c) >= 0 &&
            sign * cross(v[2], v[0], c) >= 0)
          cells.inside[std::size_t(y) * cells.nx + x] = 1;
      }
  }
  return cells;
}

inline NarrowRaster brute_force_narrow_raster(const std::vector<Vec2>& points,
                                              const std::vector<Triangle>& triangles, double width,
                                              const NarrowRaster& grid) {
  const double r = 0.5 * width / grid.cell;
  const InsideCells cells =
      inside_cells(points, triangles, grid, static_cast<int>(std::ceil(r)) + 2);
  const int nx = cells.nx, ny = cells.ny;
  auto at = [&](const std::vector<char>& mask, int x, int y) {
    return x >= 0 && x < nx && y >= 0 && y < ny && mask[std::size_t(y) * nx + x];
  };
  const int reach = static_cast<int>(std::ceil(r)) + 1;
  std::vector<char> centre(cells.inside.size(), 0);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (!at(cells.inside, x, y)) continue;
      bool fits = true;
      for (int dy = -reach; dy <= reach && fits; ++dy)
        for (int dx = -reach; dx <= reach && fits; ++dx)
          if (!at(cells.inside, x + dx, y + dy) && std::sqrt(double(dx * dx + dy * dy)) - 0.5 < r)
            fits = false;
      centre[std::size_t(y) * nx + x] = fits;
    }
  NarrowRaster result = grid;
  result.inside = result.narrow = 0;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (!at(cells.inside, x, y)) continue;
      ++result.inside;
      bool covered = false;
      for (int dy = -reach; dy <= reach && !covered; ++dy)
        for (int dx = -reach; dx <= reach && !covered; ++dx)
          covered = at(centre, x + dx, y + dy) && std::sqrt(double(dx * dx + dy * dy)) <= r;
      result.narrow += !covered;
    }
  return result;
}

namespace detail {

constexpr double kFar = 1e30;

// Squared distance transform of one row or column: d[i] becomes min_j (i - j)^2 + d[j].
inline void distance_1d(double* d, int n, int stride, std::vector<int>& v, std::vector<double>& z,
                        std::vector<double>& out) {
  auto f = [&](int i) { return d[std::size_t(i) * stride] + double(i) * i; };
  int k = 0;
  v[0] = 0;
  z[0] = -kFar;
  z[1] = kFar;
  for (int q = 1; q < n; ++q) {
    double s = (f(q) - f(v[k])) / (2.0 * (q - v[k]));
    while (k > 0 && s <= z[k]) {
      --k;
      s = (f(q) - f(v[k])) / (2.0 * (q - v[k]));
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kFar;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    out[q] = dq * dq + d[std::size_t(v[k]) * stride];
  }
  for (int q = 0; q < n; ++q) d[std::size_t(q) * stride] = out[q];
}

// In place: each cell's value becomes the squared distance (in cells) to the nearest cell whose
// value was 0 (the others kFar).
inline void distance_transform(std::vector<double>& grid, int width, int height) {
  const int n = std::max(width, height);
  std::vector<int> v(n);
  std::vector<double> z(n + 1), out(n);
  for (int y = 0; y < height; ++y) distance_1d(&grid[std::size_t(y) * width], width, 1, v, z, out);
  for (int x = 0; x < width; ++x) distance_1d(&grid[x], height, width, v, z, out);
}

}  // namespace detail

/// The same counts by two distance transforms over the piece's cells (and a margin of one
/// width), as narrow_raster computed them before; given the inside cells already found.
inline NarrowRaster distance_transform_narrow_raster(const InsideCells& cells, double width,
                                                     const NarrowRaster& grid) {
  const double radius = 0.5 * width / grid.cell;
  const std::size_t n = cells.inside.size();
  std::vector<double> distance(n);
  for (std::size_t i = 0; i < n; ++i) distance[i] = cells.inside[i] ? detail::kFar : 0.0;
  detail::distance_transform(distance, cells.nx, cells.ny);
  std::vector<double> centres(n);
  for (std::size_t i = 0; i < n; ++i)
    centres[i] = cells.inside[i] && std::sqrt(distance[i]) - 0.5 >= radius ? 0.0 : detail::kFar;
  detail::distance_transform(centres, cells.nx, cells.ny);
  NarrowRaster result = grid;
  result.inside = result.narrow = 0;
  for (std::size_t i = 0; i < n; ++i) {
    result.inside += cells.inside[i];
    result.narrow += cells.inside[i] && !(std::sqrt(centres[i]) <= radius);
  }
  return result;
}

}  // namespace papercraft::testing
