#include "core/piece_width.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "core/errors.h"

namespace papercraft {
namespace {

constexpr double kFar = 1e30;

// Per cell of each row of an nx by ny raster, the distance in cells along its row to the
// nearest cell for which `is_seed` holds (0 on such a cell), or kNone where the row has none.
constexpr int kNone = std::numeric_limits<int>::max();

template <typename IsSeed>
void row_distances(int nx, int ny, IsSeed is_seed, std::vector<int>& out) {
  out.assign(std::size_t(nx) * ny, kNone);
  for (int y = 0; y < ny; ++y) {
    int* row = &out[std::size_t(y) * nx];
    int last = -1;  // the last seed to the left
    for (int x = 0; x < nx; ++x) {
      if (is_seed(std::size_t(y) * nx + x)) last = x;
      if (last >= 0) row[x] = x - last;
    }
    last = -1;  // the last seed to the right
    for (int x = nx - 1; x >= 0; --x) {
      if (is_seed(std::size_t(y) * nx + x)) last = x;
      if (last >= 0) row[x] = std::min(row[x], last - x);
    }
  }
}

// For each row offset dy = 0..reach, the largest dx >= 0 such that offset (dx, dy) is `near`
// (near(dx * dx + dy * dy), a test monotone in the distance), or -1 where none is: a cell has a
// seed near it when for some dy a seed lies in row y +- dy within that dx.
template <typename Near>
std::vector<int> half_widths(int reach, Near near) {
  std::vector<int> width(std::size_t(reach) + 1, -1);
  for (int dy = 0; dy <= reach; ++dy)
    while (near(double(width[dy] + 1) * (width[dy] + 1) + double(dy) * dy)) ++width[dy];
  return width;
}

// Whether the cell (x, y) has a seed near it: a seed in row y + dy within width[|dy|] of x
// (`distances` from row_distances).
bool seed_near(const std::vector<int>& distances, const std::vector<int>& width, int nx, int ny,
               int x, int y) {
  const int reach = static_cast<int>(width.size()) - 1;
  for (int dy = -reach; dy <= reach; ++dy) {
    const int row = y + dy;
    const int w = width[std::abs(dy)];
    if (row < 0 || row >= ny || w < 0) continue;
    if (distances[std::size_t(row) * nx + x] <= w) return true;
  }
  return false;
}

}  // namespace

namespace {

// The raster both flat measures share: cells of size `cell` from `origin`, nx by ny.
struct NarrowCells {
  long inside = 0;  // cells whose centre a triangle covers
  long narrow = 0;  // of those, the ones no disc of diameter `width` inside covers
};

// Counts over the cells whose index lies in [x_lo, x_hi] x [y_lo, y_hi] (all of them by
// default); the triangles are checked by the callers.
// `narrow_mask`, where given, gets the narrow cells of the whole raster (1 where narrow).
NarrowCells narrow_cells(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles,
                         double width, const Vec2& origin, double cell, int nx, int ny,
                         std::array<int, 4> count_in = {0, 1 << 30, 0, 1 << 30},
                         std::vector<char>* narrow_mask = nullptr) {
  NarrowCells result;
  if (narrow_mask) narrow_mask->assign(std::size_t(nx) * ny, 0);
  // The counted cells, clamped to the raster.
  const int x_lo = std::max(0, count_in[0]), x_hi = std::min(nx - 1, count_in[1]);
  const int y_lo = std::max(0, count_in[2]), y_hi = std::min(ny - 1, count_in[3]);
  // Inside: cell centres covered by a triangle.
  std::vector<char> inside(std::size_t(nx) * ny, 0);
  bool any = false;
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
          inside[std::size_t(y) * nx + x] = 1, any = true;
      }
    }
  }
  if (!any) return result;
  for (int y = y_lo; y <= y_hi; ++y)
    for (int x = x_lo; x <= x_hi; ++x) result.inside += inside[std::size_t(y) * nx + x];

  // A disc of radius r (in cells) fits around an inside cell's centre when the nearest outside
  // cell centre is at least r plus half a cell away (the outline lies between the two); the
  // opening is every cell within r of such a centre. Both are tests of distance within a few
  // cells (r is 4 at the default cell size), so each checks the rows within reach, using each
  // row's distance to its nearest outside cell (or centre): exactly the tests
  // sqrt(d^2) - 1/2 >= r and sqrt(d^2) <= r on the nearest one, without a distance transform.
  const double radius = 0.5 * width / cell;
  const int reach = static_cast<int>(std::ceil(radius + 0.5)) + 1;
  const std::vector<int> outside_within =
      half_widths(reach, [radius](double squared) { return std::sqrt(squared) - 0.5 < radius; });
  const std::vector<int> centre_within =
      half_widths(reach, [radius](double squared) { return std::sqrt(squared) <= radius; });
  std::vector<int> distances;
  row_distances(
      nx, ny, [&](std::size_t i) { return !inside[i]; }, distances);
  std::vector<char> centres(inside.size(), 0);
  long centre_cells = 0;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const std::size_t i = std::size_t(y) * nx + x;
      if (inside[i] && !seed_near(distances, outside_within, nx, ny, x, y))
        centres[i] = 1, ++centre_cells;
    }
  if (centre_cells == 0) {
    result.narrow = result.inside;
    if (narrow_mask) *narrow_mask = inside;
    return result;
  }
  row_distances(
      nx, ny, [&](std::size_t i) { return centres[i] != 0; }, distances);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const bool counted = x >= x_lo && x <= x_hi && y >= y_lo && y <= y_hi;
      if (!counted && !narrow_mask) continue;
      const std::size_t i = std::size_t(y) * nx + x;
      const bool narrow = inside[i] && !seed_near(distances, centre_within, nx, ny, x, y);
      result.narrow += narrow && counted;
      if (narrow_mask) (*narrow_mask)[i] = narrow;
    }
  return result;
}

void check_flat_piece(const char* what, const std::vector<Vec2>& points,
                      const std::vector<Triangle>& triangles, double width) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw InvalidInputException(std::string(what) + ": width must be positive and finite");
  const int count = static_cast<int>(points.size());
  for (const Triangle& t : triangles)
    for (int i : t) {
      if (i < 0 || i >= count)
        throw InvalidInputException(std::string(what) + ": triangle index " + std::to_string(i) +
                                    " out of range [0, " + std::to_string(count) + ")");
      if (!points[i].allFinite())
        throw InvalidInputException(std::string(what) + ": point " + std::to_string(i) +
                                    " is not finite");
    }
}

// narrow_raster, and the narrow cells of its raster (nx by ny) where `narrow_mask` is given.
NarrowRaster raster_of(const char* what, const std::vector<Vec2>& points,
                       const std::vector<Triangle>& triangles, double width,
                       const PieceWidthOptions& options, std::vector<char>* narrow_mask = nullptr,
                       int* nx_out = nullptr) {
  check_flat_piece(what, points, triangles, width);
  NarrowRaster raster;
  if (triangles.empty()) return raster;
  Vec2 lo = Vec2::Constant(kFar), hi = Vec2::Constant(-kFar);
  for (const Triangle& t : triangles)
    for (int i : t) lo = lo.cwiseMin(points[i]), hi = hi.cwiseMax(points[i]);
  // A margin of one disc around the piece, so the outside surrounds it.
  double cell = width * options.cell_fraction;
  const Vec2 extent = hi - lo + Vec2::Constant(2 * width);
  const double cells = (extent.x() / cell) * (extent.y() / cell);
  if (cells > double(options.max_cells)) cell *= std::sqrt(cells / double(options.max_cells));
  const int nx = static_cast<int>(std::ceil(extent.x() / cell)) + 1;
  const int ny = static_cast<int>(std::ceil(extent.y() / cell)) + 1;
  raster.origin = lo - Vec2::Constant(width);
  raster.cell = cell;
  const NarrowCells counts = narrow_cells(points, triangles, width, raster.origin, cell, nx, ny,
                                          {0, 1 << 30, 0, 1 << 30}, narrow_mask);
  raster.inside = counts.inside;
  raster.narrow = counts.narrow;
  if (nx_out) *nx_out = nx;
  return raster;
}

}  // namespace

NarrowRaster narrow_raster(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles,
                           double width, const PieceWidthOptions& options) {
  return raster_of("narrow_raster", points, triangles, width, options);
}

double largest_narrow_region(const std::vector<Vec2>& points,
                             const std::vector<Triangle>& triangles, double width,
                             const PieceWidthOptions& options, NarrowRaster* raster_out) {
  std::vector<char> narrow;
  int nx = 0;
  const NarrowRaster raster =
      raster_of("largest_narrow_region", points, triangles, width, options, &narrow, &nx);
  if (raster_out) *raster_out = raster;
  if (raster.narrow == 0) return 0.0;
  const int ny = static_cast<int>(narrow.size()) / nx;
  // Regions of narrow cells joined across sides, by flood fill. Not across corners: along a
  // straight edge slanted to the grid, the cells the rasterised discs just miss form a
  // staircase one cell wide, each step touching the next at a corner, which joined would make
  // the whole outline of a large square turned by 30 to 60 degrees one "sliver" of 200 mm^2. A
  // band narrower than the disc but a cell or more wide (a cell is an eighth of the width) is
  // rows of cells that meet across sides; one thinner than a cell may break up.
  std::vector<char> seen(narrow.size(), 0);
  std::vector<std::size_t> stack;
  long largest = 0;
  for (std::size_t start = 0; start < narrow.size(); ++start) {
    if (!narrow[start] || seen[start]) continue;
    long size = 0;
    seen[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++size;
      const int x = static_cast<int>(i % nx), y = static_cast<int>(i / nx);
      constexpr int kSides[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (const auto& [dx, dy] : kSides) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || v < 0 || u >= nx || v >= ny) continue;
        const std::size_t j = std::size_t(v) * nx + u;
        if (narrow[j] && !seen[j]) seen[j] = 1, stack.push_back(j);
      }
    }
    largest = std::max(largest, size);
  }
  return double(largest) * raster.cell * raster.cell;
}

double narrow_area_fraction(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles,
                            double width, const PieceWidthOptions& options) {
  return narrow_raster(points, triangles, width, options).fraction();
}

NarrowRaster narrow_raster_in_box(const std::vector<Vec2>& points,
                                  const std::vector<Triangle>& triangles, double width,
                                  const Vec2& lo, const Vec2& hi, const NarrowRaster& grid) {
  check_flat_piece("narrow_raster_in_box", points, triangles, width);
  if (!lo.allFinite() || !hi.allFinite() || !(lo.x() <= hi.x()) || !(lo.y() <= hi.y()))
    throw InvalidInputException("narrow_raster_in_box: the box must be finite, lo <= hi");
  if (!(grid.cell > 0.0) || !std::isfinite(grid.cell) || !grid.origin.allFinite())
    throw InvalidInputException(
        "narrow_raster_in_box: the grid needs a finite origin and cell > 0");
  NarrowRaster result;
  result.origin = grid.origin;
  result.cell = grid.cell;
  // Whether a cell is narrow depends on the piece within one disc (`width`) of it; a margin of
  // one more disc keeps the raster's own edge far from the box.
  const double margin = 2.0 * width;
  const Vec2 reach_lo = lo - Vec2::Constant(margin), reach_hi = hi + Vec2::Constant(margin);
  std::vector<Triangle> near;
  for (const Triangle& t : triangles) {
    Vec2 tlo = points[t[0]], thi = points[t[0]];
    for (int i : t) tlo = tlo.cwiseMin(points[i]), thi = thi.cwiseMax(points[i]);
    if (thi.x() >= reach_lo.x() && tlo.x() <= reach_hi.x() && thi.y() >= reach_lo.y() &&
        tlo.y() <= reach_hi.y())
      near.push_back(t);
  }
  if (near.empty()) return result;
  // The reach, in whole cells of the grid: cell k of it is the grid's cell first + k.
  const double cell = grid.cell;
  const long first_x = static_cast<long>(std::floor((reach_lo.x() - grid.origin.x()) / cell));
  const long first_y = static_cast<long>(std::floor((reach_lo.y() - grid.origin.y()) / cell));
  const int nx = static_cast<int>(std::ceil((reach_hi.x() - grid.origin.x()) / cell) - first_x) + 1;
  const int ny = static_cast<int>(std::ceil((reach_hi.y() - grid.origin.y()) / cell) - first_y) + 1;
  const Vec2 origin = grid.origin + cell * Vec2(double(first_x), double(first_y));
  // Cell k's centre lies at origin + (k + 0.5) cell.
  auto first = [&](double from) { return static_cast<int>(std::ceil(from / cell - 0.5)); };
  auto last = [&](double to) { return static_cast<int>(std::floor(to / cell - 0.5)); };
  const std::array<int, 4> box = {first(lo.x() - origin.x()), last(hi.x() - origin.x()),
                                  first(lo.y() - origin.y()), last(hi.y() - origin.y())};
  const NarrowCells counts = narrow_cells(points, near, width, origin, cell, nx, ny, box);
  result.inside = counts.inside;
  result.narrow = counts.narrow;
  return result;
}

}  // namespace papercraft

namespace papercraft {
namespace {

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

Cell cell_of(const Vec3& p, double size) {
  return {static_cast<std::int64_t>(std::floor(p.x() / size)),
          static_cast<std::int64_t>(std::floor(p.y() / size)),
          static_cast<std::int64_t>(std::floor(p.z() / size))};
}

double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

}  // namespace

namespace {

// narrow_area_fraction's samples of a 3D piece: each with its share of the area and whether it
// is narrow; `step` bounds the distance between neighbouring samples of a triangle.
struct Samples3d {
  struct Sample {
    Vec3 point;
    double area;
    bool narrow;
  };
  std::vector<Sample> samples;
  double area = 0.0;
  double step = 0.0;
  std::size_t count = 0;  // samples laid out, those left out (far from the boundary) included
};

// Where samples near a piece's boundary lie (narrow_samples): the cells of `size` next to
// each boundary piece's midpoint.
struct NearBoundary {
  double size = 0.0;
  std::unordered_set<Cell, CellHash> cells;
};

// Lays out the samples of every triangle of `piece`, at most `spacing` apart: out.step and
// out.count take all of them, out.samples only those of the triangles marked in `emit` (none
// when it is empty): 1, those in `near`'s cells, looked up one by one; 2, all.
void sample_triangles(const TriangleMesh& piece, double spacing, const std::vector<char>& emit,
                      const NearBoundary& near, Samples3d& out) {
  std::vector<Samples3d::Sample>& samples = out.samples;
  bool check_each = false;  // whether the current triangle's samples are looked up one by one
  auto take = [&](const Vec3& point, double share) {
    if (!check_each || near.cells.count(cell_of(point, near.size)) > 0)
      samples.push_back({point, share, false});
  };
  for (std::size_t n = 0; n < piece.triangles.size(); ++n) {
    const Triangle& t = piece.triangles[n];
    const bool keep = !emit.empty() && emit[n] != 0;
    check_each = keep && emit[n] == 1;
    const std::array<Vec3, 3> corner = {piece.vertices[t[0]], piece.vertices[t[1]],
                                        piece.vertices[t[2]]};
    const Vec3 &a = corner[0], &b = corner[1], &c = corner[2];
    // Edge e runs from corner e to corner e + 1.
    const std::array<double, 3> length = {(b - a).norm(), (c - b).norm(), (a - c).norm()};
    const int e =
        static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
    const double longest = length[e];
    const double triangle_area = 0.5 * (b - a).cross(c - a).norm();
    const double height = longest > 0.0 ? 2.0 * triangle_area / longest : 0.0;
    if (longest > spacing && longest > 4.0 * height) {
      const Vec3 &p = corner[e], &q = corner[(e + 1) % 3], &r = corner[(e + 2) % 3];
      const int rows = std::clamp(static_cast<int>(std::ceil(height / spacing)), 1, 256);
      out.step = std::max(out.step, height / rows);
      for (int j = 0; j < rows; ++j) {
        // Row j runs across the band between heights j / rows and (j + 1) / rows, at its
        // middle: from p towards r and from q towards r by that share.
        const double from = double(j) / rows, to = double(j + 1) / rows, at = (j + 0.5) / rows;
        const double band = triangle_area * ((1 - from) * (1 - from) - (1 - to) * (1 - to));
        const Vec3 start = p + at * (r - p), end = q + at * (r - q);
        const int count =
            std::clamp(static_cast<int>(std::ceil((end - start).norm() / spacing)), 1, 65536);
        out.step = std::max(out.step, (end - start).norm() / count);
        out.count += count;
        if (!keep) continue;
        for (int i = 0; i < count; ++i)
          take(start + ((i + 0.5) / count) * (end - start), band / count);
      }
      continue;
    }
    const int k = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 256);
    const double share = triangle_area / (double(k) * k);
    out.step = std::max(out.step, longest / k);
    out.count += std::size_t(k) * k;
    if (!keep) continue;
    const Vec3 u = (b - a) / k, v = (c - a) / k;
    for (int i = 0; i < k; ++i) {
      for (int j = 0; i + j < k; ++j) {
        take(a + (i + 1.0 / 3) * u + (j + 1.0 / 3) * v, share);  // upright
        if (i + j + 1 < k) take(a + (i + 2.0 / 3) * u + (j + 2.0 / 3) * v, share);
      }
    }
  }
}

// The cells within reach of the boundary pieces (a point within `size` - its half of one lies
// in a cell next to the piece's midpoint's).
NearBoundary near_boundary(
    const std::unordered_map<Cell, std::vector<std::pair<Vec3, Vec3>>, CellHash>& boundary,
    double size) {
  NearBoundary near;
  near.size = size;
  for (const auto& entry : boundary) {
    for (const auto& [a, b] : entry.second) {
      const Cell c = cell_of(0.5 * (a + b), size);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
          for (std::int64_t dz = -1; dz <= 1; ++dz)
            near.cells.insert({c[0] + dx, c[1] + dy, c[2] + dz});
    }
  }
  return near;
}

// Per triangle, which of its samples to take (sample_triangles' `emit`): 0, none (it meets no
// cell near the boundary); 2, all (it lies in such cells only); 1, each looked up.
std::vector<char> triangles_near(const TriangleMesh& piece, const NearBoundary& near) {
  std::vector<char> emit(piece.triangles.size(), 0);
  for (std::size_t n = 0; n < piece.triangles.size(); ++n) {
    const Triangle& t = piece.triangles[n];
    Vec3 low = piece.vertices[t[0]], high = low;
    for (int k = 1; k < 3; ++k) {
      low = low.cwiseMin(piece.vertices[t[k]]);
      high = high.cwiseMax(piece.vertices[t[k]]);
    }
    const Cell from = cell_of(low, near.size), to = cell_of(high, near.size);
    const std::int64_t cells = (to[0] - from[0] + 1) * (to[1] - from[1] + 1) * (to[2] - from[2] + 1);
    if (cells > static_cast<std::int64_t>(near.cells.size())) {
      emit[n] = 1;  // a large triangle: its samples are looked up one by one
      continue;
    }
    std::int64_t in = 0;
    for (std::int64_t x = from[0]; x <= to[0]; ++x)
      for (std::int64_t y = from[1]; y <= to[1]; ++y)
        for (std::int64_t z = from[2]; z <= to[2]; ++z) in += near.cells.count({x, y, z});
    emit[n] = in == 0 ? 0 : in == cells ? 2 : 1;
  }
  return emit;
}

Samples3d narrow_samples(const char* what, const TriangleMesh& piece, double width,
                         const PieceWidthOptions& options) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw InvalidInputException(std::string(what) + ": width must be positive and finite");
  Samples3d out;
  const int count = static_cast<int>(piece.vertices.size());
  std::map<std::pair<int, int>, int> edge_uses;
  double area = 0.0;
  for (const Triangle& t : piece.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= count)
        throw InvalidInputException(std::string(what) + ": triangle index " + std::to_string(t[k]) +
                                    " out of range [0, " + std::to_string(count) + ")");
      const int a = t[k], b = t[(k + 1) % 3];
      ++edge_uses[{std::min(a, b), std::max(a, b)}];
    }
    const Vec3& p = piece.vertices[t[0]];
    area += 0.5 * (piece.vertices[t[1]] - p).cross(piece.vertices[t[2]] - p).norm();
  }
  out.area = area;
  if (!(area > 0.0)) return out;
  const double radius = 0.5 * width;
  // Boundary edges, cut into pieces no longer than the radius, in a grid of cells of the
  // radius: every boundary point within the radius of a sample lies in the sample's cell or
  // one of its 26 neighbours.
  std::unordered_map<Cell, std::vector<std::pair<Vec3, Vec3>>, CellHash> boundary;
  bool has_boundary = false;
  for (const auto& [edge, uses] : edge_uses) {
    if (uses != 1) continue;
    has_boundary = true;
    const Vec3& a = piece.vertices[edge.first];
    const Vec3& b = piece.vertices[edge.second];
    const int parts = std::max(1, static_cast<int>(std::ceil((b - a).norm() / radius)));
    for (int i = 0; i < parts; ++i) {
      const Vec3 p = a + (b - a) * (double(i) / parts), q = a + (b - a) * (double(i + 1) / parts);
      boundary[cell_of(0.5 * (p + q), radius)].emplace_back(p, q);
    }
  }
  if (!has_boundary) return out;
  // Samples: the centroids of a k x k subdivision of each triangle, k so that they are at
  // most `spacing` apart; each carries its share of the area. A thin triangle (its longest
  // edge over four times its height) is sampled in rows along that edge instead, each row
  // `spacing` apart at most and its samples too: k x k samples, k set by the longest edge,
  // would crowd its small area (a 20 x 0.25 needle of a CAD mesh would take 54 x 54 of them).
  double spacing = width * options.cell_fraction;
  if (area / (spacing * spacing) > double(options.max_cells))
    spacing = std::sqrt(area / double(options.max_cells));
  std::vector<Samples3d::Sample>& samples = out.samples;
  // Only samples within the radius and a reach (below) of the boundary bear on the outcome: one
  // farther out is a centre, and covers only samples that are no centres, within the radius of
  // the boundary. So a sample farther than that is left out, and what is measured stays the
  // same. Boundary pieces are at most a radius long: a point within that distance (twice the
  // radius and a step) of one lies within the near size of its midpoint, so in a cell of that
  // size next to the midpoint's. The first pass finds the step the reach depends on; the second
  // takes the samples near the boundary, of the triangles that come near it.
  sample_triangles(piece, spacing, {}, NearBoundary{}, out);
  const NearBoundary near_cells = near_boundary(boundary, 2.5 * radius + out.step);
  const std::vector<char> emit = triangles_near(piece, near_cells);
  out.step = 0.0;
  out.count = 0;
  sample_triangles(piece, spacing, emit, near_cells, out);
  // Samples are taken cell by cell: a cell's samples share the 27 cells around it, looked up
  // once for all of them (a thin triangle puts many samples into one cell).
  auto by_cell = [&](double size, auto&& take) {
    std::unordered_map<Cell, std::vector<int>, CellHash> cells;
    for (int i = 0; i < static_cast<int>(samples.size()); ++i)
      if (take(i)) cells[cell_of(samples[i].point, size)].push_back(i);
    return cells;
  };
  // A sample is a centre when no boundary point lies within the radius of it.
  std::vector<char> is_centre(samples.size(), 0);
  std::vector<const std::vector<std::pair<Vec3, Vec3>>*> segments;
  for (const auto& [c, members] : by_cell(radius, [](int) { return true; })) {
    segments.clear();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = boundary.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it != boundary.end()) segments.push_back(&it->second);
        }
    for (int i : members) {
      bool near = false;
      for (const auto* list : segments) {
        for (const auto& [a, b] : *list)
          if (segment_distance(samples[i].point, a, b) < radius) {
            near = true;
            break;
          }
        if (near) break;
      }
      is_centre[i] = !near;
    }
  }
  // A sample is wide when a centre lies within the radius and one step: the disc that covers a
  // point on the boundary is centred exactly one radius in, where a sample lies only to within
  // a step; without the step, a line of samples along every boundary edge would read narrow.
  const double reach = radius + out.step;
  std::unordered_map<Cell, std::vector<Vec3>, CellHash> centres;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (is_centre[i]) centres[cell_of(samples[i].point, reach)].push_back(samples[i].point);
  std::vector<const std::vector<Vec3>*> around;
  for (const auto& [c, members] : by_cell(reach, [&](int i) { return !is_centre[i]; })) {
    around.clear();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = centres.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it != centres.end()) around.push_back(&it->second);
        }
    for (int i : members) {  // a centre covers itself
      Samples3d::Sample& s = samples[i];
      bool covered = false;
      for (const auto* list : around) {
        for (const Vec3& centre : *list)
          if ((centre - s.point).squaredNorm() <= reach * reach) {
            covered = true;
            break;
          }
        if (covered) break;
      }
      s.narrow = !covered;
    }
  }
  return out;
}

}  // namespace

double narrow_area_fraction(const TriangleMesh& piece, double width,
                            const PieceWidthOptions& options) {
  const Samples3d measured = narrow_samples("narrow_area_fraction", piece, width, options);
  if (!(measured.area > 0.0)) return 0.0;
  double narrow = 0.0;
  for (const Samples3d::Sample& s : measured.samples)
    if (s.narrow) narrow += s.area;
  return std::min(1.0, narrow / measured.area);
}

NarrowMeasure narrow_measure(const TriangleMesh& piece, double width,
                             const PieceWidthOptions& options) {
  const Samples3d measured = narrow_samples("narrow_measure", piece, width, options);
  NarrowMeasure result;
  result.samples = measured.count;
  if (!(measured.area > 0.0)) return result;
  // Narrow samples joined when closer than 1.5 steps (neighbours on one triangle or across a
  // shared edge), by union-find over a grid of cells of that size.
  std::vector<int> narrow;
  for (std::size_t i = 0; i < measured.samples.size(); ++i)
    if (measured.samples[i].narrow) narrow.push_back(static_cast<int>(i));
  if (narrow.empty()) return result;
  const double link = 1.5 * measured.step;
  // Cells small enough that any two samples in one lie within the link of each other (their
  // diagonal is the link): a cell's samples are one region at once, and two cells, up to two
  // apart, are joined by the first pair of their samples within the link. A thin triangle
  // holds samples close together, which pair by pair would cost their square.
  const double size = link / std::sqrt(3.0);
  std::unordered_map<Cell, std::vector<int>, CellHash> grid;
  for (int n = 0; n < static_cast<int>(narrow.size()); ++n)
    grid[cell_of(measured.samples[narrow[n]].point, size)].push_back(n);
  std::vector<int> parent(narrow.size());
  for (std::size_t n = 0; n < parent.size(); ++n) parent[n] = static_cast<int>(n);
  auto root = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const auto& [cell, members] : grid)
    for (int m : members) parent[root(m)] = root(members.front());
  for (const auto& [cell, members] : grid) {
    for (std::int64_t dx = -2; dx <= 2; ++dx)
      for (std::int64_t dy = -2; dy <= 2; ++dy)
        for (std::int64_t dz = -2; dz <= 2; ++dz) {
          const Cell other{cell[0] + dx, cell[1] + dy, cell[2] + dz};
          if (!(cell < other)) continue;  // each pair of cells once
          const auto it = grid.find(other);
          if (it == grid.end() || root(it->second.front()) == root(members.front())) continue;
          bool joined = false;
          for (int n : members) {
            const Vec3& p = measured.samples[narrow[n]].point;
            for (int m : it->second)
              if ((measured.samples[narrow[m]].point - p).squaredNorm() <= link * link) {
                joined = true;
                break;
              }
            if (joined) break;
          }
          if (joined) parent[root(it->second.front())] = root(members.front());
        }
  }
  std::vector<double> region(narrow.size(), 0.0);
  double total = 0.0;
  for (int n = 0; n < static_cast<int>(narrow.size()); ++n) {
    const double a = measured.samples[narrow[n]].area;
    region[root(n)] += a;
    total += a;
  }
  result.fraction = std::min(1.0, total / measured.area);
  result.largest_region = *std::max_element(region.begin(), region.end());
  return result;
}

}  // namespace papercraft
