// Raster bottom-left fill of pieces by their outlines (see nesting.h).
#include "nodes/layout/nesting.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace papercraft::layout_internal {
namespace {

// A shape rasterised at one rotation: per row, the covered cells as half-open intervals.
struct Mask {
  double angle = 0.0;
  Vec2 min = Vec2::Zero();  // area-frame coordinates of cell (0, 0)'s corner
  int width = 0;
  int height = 0;
  std::vector<std::vector<std::pair<int, int>>> rows;
  std::vector<int> widest;  // per row, the longest interval
  long cells = 0;
};

Vec2 turned(const Vec2& p, double c, double s) {
  return Vec2(c * p.x() - s * p.y(), -(s * p.x() + c * p.y()));
}

// The x range of convex polygon `poly` within the band lo <= y <= hi, if any.
bool band_range(const std::vector<Vec2>& poly, double lo, double hi, double* x0, double* x1) {
  double left = std::numeric_limits<double>::infinity(), right = -left;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    if (a.y() >= lo && a.y() <= hi) left = std::min(left, a.x()), right = std::max(right, a.x());
    for (const double y : {lo, hi}) {
      if ((a.y() - y) * (b.y() - y) < 0) {
        const double x = a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
        left = std::min(left, x);
        right = std::max(right, x);
      }
    }
  }
  *x0 = left;
  *x1 = right;
  return left <= right;
}

// Conservative: every cell the shape touches is covered.
Mask rasterise(const NestShape& shape, double angle, double cell) {
  Mask mask;
  mask.angle = angle;
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<std::vector<Vec2>> polygons;
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& poly : shape.convex) {
    std::vector<Vec2> moved;
    for (const Vec2& p : poly) {
      moved.push_back(turned(p, c, s));
      lo = lo.cwiseMin(moved.back());
      hi = hi.cwiseMax(moved.back());
    }
    polygons.push_back(std::move(moved));
  }
  if (polygons.empty()) return mask;
  mask.min = lo;
  mask.width = static_cast<int>(std::floor((hi.x() - lo.x()) / cell)) + 1;
  mask.height = static_cast<int>(std::floor((hi.y() - lo.y()) / cell)) + 1;
  mask.rows.assign(mask.height, {});
  for (const auto& poly : polygons) {
    double ylo = std::numeric_limits<double>::infinity(), yhi = -ylo;
    for (const Vec2& p : poly) ylo = std::min(ylo, p.y()), yhi = std::max(yhi, p.y());
    const int r0 = std::max(0, static_cast<int>(std::floor((ylo - lo.y()) / cell)));
    const int r1 = std::min(mask.height - 1, static_cast<int>(std::floor((yhi - lo.y()) / cell)));
    for (int r = r0; r <= r1; ++r) {
      double x0, x1;
      if (!band_range(poly, lo.y() + r * cell, lo.y() + (r + 1) * cell, &x0, &x1)) continue;
      const int c0 = std::max(0, static_cast<int>(std::floor((x0 - lo.x()) / cell)));
      const int c1 = std::min(mask.width - 1, static_cast<int>(std::floor((x1 - lo.x()) / cell)));
      mask.rows[r].push_back({c0, c1 + 1});
    }
  }
  for (auto& row : mask.rows) {
    std::sort(row.begin(), row.end());
    std::vector<std::pair<int, int>> merged;
    for (const auto& interval : row) {
      if (!merged.empty() && interval.first <= merged.back().second)
        merged.back().second = std::max(merged.back().second, interval.second);
      else
        merged.push_back(interval);
    }
    row = std::move(merged);
    int widest = 0;
    for (const auto& [a, b] : row) mask.cells += b - a, widest = std::max(widest, b - a);
    mask.widest.push_back(widest);
  }
  return mask;
}

// A page's occupied cells (grown by the spacing) and, per cell, the run to its right: the free
// cells from it (> 0) where it is free, minus the occupied cells from it (< 0) where it is not.
class Sheet {
 public:
  Sheet(int width, int height)
      : width_(width),
        height_(height),
        used_(std::size_t(width) * height, 0),
        run_(std::size_t(width) * height),
        max_run_(height, 0),
        free_cells_(long(width) * height) {
    for (int y = 0; y < height_; ++y) update_row(y);
  }

  // The highest, then leftmost, cell where `mask` fits, among those whose bottom lies above
  // `bound` (exclusive); false when none does.
  bool find(const Mask& mask, int bound, int* out_x, int* out_y) const {
    if (mask.width > width_ || mask.height > height_) return false;
    if (mask.cells > free_cells_) return false;
    // The row that failed last is tried first: where a row of the mask meets an occupied
    // cell, the next offsets usually fail on the same row. Any failing row gives a jump that
    // skips only offsets that fail, so the order of the rows does not change the answer.
    int hot = 0;
    for (int oy = 0; oy + mask.height <= height_ && oy + mask.height < bound; ++oy) {
      // No offset on this row when a row of the mask is wider than every free run it meets.
      if (max_run_[oy + hot] < mask.widest[hot]) continue;
      bool possible = true;
      for (int r = 0; r < mask.height && possible; ++r)
        if (max_run_[oy + r] < mask.widest[r]) possible = false, hot = r;
      if (!possible) continue;
      int ox = 0;
      while (ox + mask.width <= width_) {
        int next = -1;
        for (int k = -1; k < mask.height && next < 0; ++k) {
          const int r = k < 0 ? hot : k;
          if (k == hot) continue;
          const int* run = &run_[std::size_t(oy + r) * width_];
          for (const auto& [a, b] : mask.rows[r]) {
            const int here = run[ox + a];
            if (here < b - a) {
              // Every start of this interval up to the end of the occupied cells it meets
              // first (at q, free or not from ox + a) covers one of them: the next offset to
              // try puts it on the first free cell after them.
              const int q = ox + a + std::max(here, 0);
              next = q < width_ ? q - run[q] - a : width_;
              hot = r;
              break;
            }
          }
        }
        if (next < 0) {
          *out_x = ox;
          *out_y = oy;
          return true;
        }
        ox = next;
      }
    }
    return false;
  }

  void place(const Mask& mask, int ox, int oy, int grow) {
    int y_lo = height_, y_hi = -1;
    for (int r = 0; r < mask.height; ++r) {
      for (const auto& [a, b] : mask.rows[r]) {
        const int y0 = std::max(0, oy + r - grow), y1 = std::min(height_ - 1, oy + r + grow);
        const int x0 = std::max(0, ox + a - grow), x1 = std::min(width_, ox + b + grow);
        for (int y = y0; y <= y1; ++y) {
          char* row = used_.data() + std::size_t(y) * width_;
          for (int x = x0; x < x1; ++x) {
            free_cells_ -= row[x] == 0;
            row[x] = 1;
          }
        }
        y_lo = std::min(y_lo, y0);
        y_hi = std::max(y_hi, y1);
      }
    }
    for (int y = y_lo; y <= y_hi; ++y) update_row(y);
  }

 private:
  void update_row(int y) {
    int free = 0, occupied = 0, longest = 0;
    for (int x = width_ - 1; x >= 0; --x) {
      if (used_[std::size_t(y) * width_ + x]) {
        free = 0, ++occupied;
        run_[std::size_t(y) * width_ + x] = -occupied;
      } else {
        occupied = 0, ++free;
        run_[std::size_t(y) * width_ + x] = free;
      }
      longest = std::max(longest, free);
    }
    max_run_[y] = longest;
  }

  int width_, height_;
  std::vector<char> used_;
  std::vector<int> run_;
  std::vector<int> max_run_;  // per row, the longest free run
  long free_cells_;  // cells not yet used
};

}  // namespace

namespace {

// One bottom-left fill of the shapes in `order`; sets *pages and *last_cells (the cells the
// last page's pieces cover).
// With `run` (a run index per shape, runs consecutive in `order`), the pieces of a run go on
// the page where its first piece went or later, and that first piece on the page where the
// run before began or later: runs stay together.
std::vector<NestPlacement> fill_in_order(const std::vector<std::vector<Mask>>& masks,
                                         const std::vector<int>& order, int width, int height,
                                         int grow, double cell, int* pages, long* last_cells,
                                         const std::vector<int>* run = nullptr) {
  std::vector<NestPlacement> placements(masks.size());
  std::vector<Sheet> sheets;
  std::vector<long> cells;
  const Sheet empty(std::max(width, 1), std::max(height, 1));
  std::size_t floor = 0, run_floor = 0;  // first page tried: in this run, in the run before
  int current_run = -1;
  bool run_started = false;
  for (int i : order) {
    if (run && (*run)[i] != current_run) {
      current_run = (*run)[i];
      run_floor = floor;
      run_started = false;
    }
    if (run && !run_started) floor = run_floor;
    if (masks[i].empty() || masks[i][0].cells == 0) continue;
    bool fits_somewhere = false;
    for (const Mask& mask : masks[i]) {
      int x, y;
      if (empty.find(mask, std::numeric_limits<int>::max(), &x, &y)) {
        fits_somewhere = true;
        break;
      }
    }
    if (!fits_somewhere) continue;
    for (std::size_t page = run ? floor : 0;; ++page) {
      if (page == sheets.size()) {
        sheets.emplace_back(width, height);
        cells.push_back(0);
      }
      int best = -1, best_x = 0, best_y = 0, bound = std::numeric_limits<int>::max();
      for (int k = 0; k < static_cast<int>(masks[i].size()); ++k) {
        const Mask& mask = masks[i][k];
        int x, y;
        if (!sheets[page].find(mask, bound, &x, &y)) continue;
        const int bottom = y + mask.height;
        if (best < 0 || bottom < bound || (bottom == bound && x < best_x)) {
          best = k, best_x = x, best_y = y, bound = bottom;
        }
      }
      if (best < 0) continue;
      const Mask& mask = masks[i][best];
      sheets[page].place(mask, best_x, best_y, grow);
      cells[page] += mask.cells;
      placements[i].page = static_cast<int>(page);
      placements[i].angle = mask.angle;
      placements[i].offset = Vec2(best_x * cell, best_y * cell) - mask.min;
      if (run && !run_started) {
        floor = page;
        run_started = true;
      }
      break;
    }
  }
  *pages = static_cast<int>(sheets.size());
  *last_cells = cells.empty() ? 0 : cells.back();
  return placements;
}

}  // namespace

std::vector<NestPlacement> nest_shapes(const std::vector<NestShape>& shapes, const Vec2& area,
                                       const NestOptions& options, int* pages) {
  // A raster of at most ~1.5 million cells per page.
  double cell = options.cell_mm;
  if (area.prod() / (cell * cell) > 1.5e6) cell = std::sqrt(area.prod() / 1.5e6);
  const int width = static_cast<int>(std::floor(area.x() / cell));
  const int height = static_cast<int>(std::floor(area.y() / cell));
  const int grow = static_cast<int>(std::ceil(options.spacing_mm / cell - 1e-9));
  const int rotations = std::max(1, options.rotations);

  std::vector<std::vector<Mask>> masks(shapes.size());
  tbb::parallel_for(std::size_t{0}, shapes.size(), [&](std::size_t i) {
    for (int k = 0; k < rotations; ++k)
      masks[i].push_back(rasterise(shapes[i], 2 * std::numbers::pi * k / rotations, cell));
  });
  // Orders to fill in, each largest first by a different measure (ties in input order): the
  // area covered, the longest side, the area of the bounding rectangle. The fill that needs
  // the fewest pages, then leaves the least on its last page (fuller pages before it), wins.
  auto measure = [&](int by, int i) -> double {
    if (masks[i].empty()) return 0.0;
    const Mask& m = masks[i][0];
    if (by == 0) return static_cast<double>(m.cells);
    if (by == 1) {
      double longest = 0;
      for (const Mask& r : masks[i]) longest = std::max(longest, double(std::max(r.width, r.height)));
      return longest;
    }
    double tightest = std::numeric_limits<double>::infinity();
    for (const Mask& r : masks[i]) tightest = std::min(tightest, double(r.width) * r.height);
    return tightest;
  };
  const int orders = std::clamp(options.orders, 1, 3);
  struct Fill {
    std::vector<NestPlacement> placements;
    int pages = 0;
    long last = 0;
  };
  std::vector<Fill> fills(orders);
  std::vector<std::vector<int>> order_of(orders);
  tbb::parallel_for(0, orders, [&](int by) {
    std::vector<int>& order = order_of[by];
    order.resize(shapes.size());
    std::vector<double> key(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      order[i] = static_cast<int>(i);
      key[i] = measure(by, static_cast<int>(i));
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] > key[b]; });
    Fill& fill = fills[by];
    fill.placements = fill_in_order(masks, order, width, height, grow, cell, &fill.pages, &fill.last);
  });
  auto better = [](const Fill& a, const Fill& b) {
    return a.pages < b.pages || (a.pages == b.pages && a.last < b.last);
  };
  std::size_t best = 0;
  for (std::size_t k = 1; k < fills.size(); ++k)
    if (better(fills[k], fills[best])) best = k;
  Fill kept = std::move(fills[best]);
  std::vector<int> order = std::move(order_of[best]);
  for (int repack = 0; repack < options.repacks && kept.pages > 1; ++repack) {
    std::stable_partition(order.begin(), order.end(), [&](int i) {
      return kept.placements[i].page == kept.pages - 1;
    });
    Fill again;
    again.placements =
        fill_in_order(masks, order, width, height, grow, cell, &again.pages, &again.last);
    if (!better(again, kept)) break;
    kept = std::move(again);
  }
  // Pieces of one region of the model near each other, where that costs no page: the pieces
  // (given in the model's order, so a region's pieces come together) taken in runs of half a
  // page of paper or more (on to the first shape glued to none of the run, up to a page),
  // each run largest first and kept on the pages from where the run
  // before began; kept where that fill needs no more pages and puts more glued pieces on one
  // page.
  if (options.grouped && kept.pages > 1 && !options.neighbours.empty()) {
    const double run_cells = 0.5 * static_cast<double>(width) * height;
    std::vector<int> grouped, run, run_of(shapes.size(), 0);
    double cells = 0;
    int runs = 0;
    auto flush = [&] {
      std::stable_sort(run.begin(), run.end(),
                       [&](int a, int b) { return measure(0, a) > measure(0, b); });
      for (int i : run) run_of[i] = runs;
      ++runs;
      grouped.insert(grouped.end(), run.begin(), run.end());
      run.clear();
      cells = 0;
    };
    std::vector<std::vector<int>> glued(shapes.size());
    for (const auto& [a, b] : options.neighbours) {
      glued[a].push_back(b);
      glued[b].push_back(a);
    }
    std::vector<char> in_run(shapes.size(), 0);
    for (int i = 0; i < static_cast<int>(shapes.size()); ++i) {
      run.push_back(i);
      in_run[i] = 1;
      cells += measure(0, i);
      // A run ends past half a page where the next shape is glued to none of it, and at a
      // page whatever comes next.
      const int next = i + 1;
      const bool joined = next < static_cast<int>(shapes.size()) &&
                          std::any_of(glued[next].begin(), glued[next].end(),
                                      [&](int j) { return in_run[j] != 0; });
      if (cells >= 2 * run_cells || (cells >= run_cells && !joined)) {
        for (int j : run) in_run[j] = 0;
        flush();
      }
    }
    flush();
    Fill near;
    near.placements =
        fill_in_order(masks, grouped, width, height, grow, cell, &near.pages, &near.last, &run_of);
    auto together = [&](const Fill& fill) {
      int count = 0;
      for (const auto& [a, b] : options.neighbours)
        count += fill.placements[a].page == fill.placements[b].page;
      return count;
    };
    if (near.pages <= kept.pages && together(near) > together(kept)) kept = std::move(near);
  }
  *pages = kept.pages;
  return std::move(kept.placements);
}

}  // namespace papercraft::layout_internal
