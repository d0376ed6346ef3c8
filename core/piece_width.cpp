#include "core/piece_width.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"

namespace papercraft {
namespace {

constexpr double kFar = 1e30;

// Squared distance transform of one row or column (Felzenszwalb & Huttenlocher): d[i] becomes
// min_j (i - j)^2 + d[j]. `v`, `z` and `out` are scratch of size n, n + 1 and n.
void distance_1d(double* d, int n, int stride, std::vector<int>& v, std::vector<double>& z,
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

// In place: each cell's value becomes the squared distance (in cells) to the nearest cell
// whose input value was 0 (others must be kFar).
void distance_transform(std::vector<double>& grid, int width, int height) {
  const int n = std::max(width, height);
  std::vector<int> v(n);
  std::vector<double> z(n + 1), out(n);
  for (int y = 0; y < height; ++y) distance_1d(&grid[std::size_t(y) * width], width, 1, v, z, out);
  for (int x = 0; x < width; ++x) distance_1d(&grid[x], height, width, v, z, out);
}

}  // namespace

double narrow_area_fraction(const std::vector<Vec2>& points,
                            const std::vector<Triangle>& triangles, double width,
                            const PieceWidthOptions& options) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw InvalidInputException("narrow_area_fraction: width must be positive and finite");
  const int count = static_cast<int>(points.size());
  Vec2 lo = Vec2::Constant(kFar), hi = Vec2::Constant(-kFar);
  for (const Triangle& t : triangles) {
    for (int i : t) {
      if (i < 0 || i >= count)
        throw InvalidInputException("narrow_area_fraction: triangle index " + std::to_string(i) +
                                    " out of range [0, " + std::to_string(count) + ")");
      if (!points[i].allFinite())
        throw InvalidInputException("narrow_area_fraction: point " + std::to_string(i) +
                                    " is not finite");
      lo = lo.cwiseMin(points[i]);
      hi = hi.cwiseMax(points[i]);
    }
  }
  if (triangles.empty()) return 0.0;
  // A margin of one disc around the piece, so the outside surrounds it.
  double cell = width * options.cell_fraction;
  const Vec2 extent = hi - lo + Vec2::Constant(2 * width);
  const double cells = (extent.x() / cell) * (extent.y() / cell);
  if (cells > double(options.max_cells)) cell *= std::sqrt(cells / double(options.max_cells));
  const int nx = static_cast<int>(std::ceil(extent.x() / cell)) + 1;
  const int ny = static_cast<int>(std::ceil(extent.y() / cell)) + 1;
  const Vec2 origin = lo - Vec2::Constant(width);

  // Inside: cell centres covered by a triangle.
  std::vector<char> inside(std::size_t(nx) * ny, 0);
  for (const Triangle& t : triangles) {
    const Vec2 a = (points[t[0]] - origin) / cell, b = (points[t[1]] - origin) / cell,
               c = (points[t[2]] - origin) / cell;
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (area == 0.0) continue;
    const double sign = area > 0 ? 1.0 : -1.0;
    const Vec2 tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
    const int x0 = std::max(0, int(std::floor(tlo.x() - 0.5))),
              x1 = std::min(nx - 1, int(std::ceil(thi.x() - 0.5)));
    const int y0 = std::max(0, int(std::floor(tlo.y() - 0.5))),
              y1 = std::min(ny - 1, int(std::ceil(thi.y() - 0.5)));
    auto edge = [sign](const Vec2& p, const Vec2& q, const Vec2& r) {
      return sign * ((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x());
    };
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Vec2 centre(x + 0.5, y + 0.5);
        if (edge(a, b, centre) >= 0 && edge(b, c, centre) >= 0 && edge(c, a, centre) >= 0)
          inside[std::size_t(y) * nx + x] = 1;
      }
    }
  }
  long inside_cells = 0;
  for (char i : inside) inside_cells += i;
  if (inside_cells == 0) return 0.0;

  // Distance of each inside cell to the outside: to the nearest outside cell centre less half
  // a cell (the outline lies between the two). A disc of radius r fits around a centre at
  // distance >= r.
  const double radius = 0.5 * width / cell;
  std::vector<double> grid(inside.size());
  for (std::size_t i = 0; i < inside.size(); ++i) grid[i] = inside[i] ? kFar : 0.0;
  distance_transform(grid, nx, ny);
  std::vector<double> centres(inside.size());
  long centre_cells = 0;
  for (std::size_t i = 0; i < inside.size(); ++i) {
    const bool centre = inside[i] && std::sqrt(grid[i]) - 0.5 >= radius;
    centres[i] = centre ? 0.0 : kFar;
    centre_cells += centre;
  }
  if (centre_cells == 0) return 1.0;
  // The opening: every cell within r of a centre.
  distance_transform(centres, nx, ny);
  long narrow = 0;
  for (std::size_t i = 0; i < inside.size(); ++i)
    narrow += inside[i] && std::sqrt(centres[i]) > radius;
  return double(narrow) / double(inside_cells);
}

}  // namespace papercraft
