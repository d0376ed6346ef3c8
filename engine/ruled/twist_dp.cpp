#include "engine/ruled/twist_dp.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/errors.h"

namespace papercraft {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A normal (a_i - b_j) x d is undefined below this fraction of |a_i - b_j| |d|.
constexpr double kDegenerateNormal = 1e-12;
// Cost tables up to this many cells are stored in double precision (32 MiB), up to the second
// limit in single precision (128 MiB; the path is then optimal for costs rounded to ~1e-7);
// larger grids recompute costs on demand, several times slower.
constexpr std::size_t kMaxExactTableCells = std::size_t{1} << 22;
constexpr std::size_t kMaxRoundedTableCells = std::size_t{1} << 25;

std::vector<Vec3> unit_tangents(const std::vector<Vec3>& points, bool closed) {
  const int n = static_cast<int>(points.size());
  std::vector<Vec3> tangents(n, Vec3::Zero());
  for (int i = 0; i < n; ++i) {
    int previous = i - 1;
    int next = i + 1;
    if (closed) {
      previous = (previous + n) % n;
      next = next % n;
    } else {
      previous = std::max(previous, 0);
      next = std::min(next, n - 1);
    }
    const Vec3 d = points[next] - points[previous];
    const double length = d.norm();
    if (length > 0.0) tangents[i] = d / length;
  }
  return tangents;
}

// 1 - <n_a, n_b> of the ruling a b (paper section 3.2.2); 1 where a normal is undefined.
// The cost is symmetric in (a, ta) <-> (b, tb).
double ruling_twist(const Vec3& a, const Vec3& a_tangent, const Vec3& b, const Vec3& b_tangent) {
  const Vec3 ruling = a - b;
  const Vec3 normal_a = ruling.cross(a_tangent);
  const Vec3 normal_b = ruling.cross(b_tangent);
  const double squared_a = normal_a.squaredNorm();
  const double squared_b = normal_b.squaredNorm();
  const double threshold = kDegenerateNormal * kDegenerateNormal * ruling.squaredNorm();
  if (!(squared_a > threshold) || !(squared_b > threshold)) return 1.0;
  return 1.0 - normal_a.dot(normal_b) / std::sqrt(squared_a * squared_b);
}

class CostGrid;

// The objectives of one grid row, from whichever table the grid keeps.
struct RowCosts {
  const double* exact = nullptr;
  const float* rounded = nullptr;
  const CostGrid* grid = nullptr;
  int row = 0;

  double operator[](int j) const;
};

// The ruling costs of a grid: rows are the vertices of one polyline, columns those of the
// other, each with its traversal-direction tangents.
class CostGrid {
 public:
  CostGrid(const std::vector<Vec3>& row_points, const std::vector<Vec3>& row_tangents,
           const std::vector<Vec3>& column_points, const std::vector<Vec3>& column_tangents,
           double length_weight)
      : row_points_(row_points),
        row_tangents_(row_tangents),
        column_points_(column_points),
        column_tangents_(column_tangents),
        rows_(static_cast<int>(row_points.size())),
        columns_(static_cast<int>(column_points.size())),
        length_weight_(length_weight) {
    const std::size_t cells = static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_);
    if (cells <= kMaxExactTableCells) {
      exact_.resize(cells);
      for (int i = 0; i < rows_; ++i) {
        for (int j = 0; j < columns_; ++j) exact_[index(i, j)] = compute(i, j);
      }
    } else if (cells <= kMaxRoundedTableCells) {
      rounded_.resize(cells);
      for (int i = 0; i < rows_; ++i) {
        for (int j = 0; j < columns_; ++j)
          rounded_[index(i, j)] = static_cast<float>(compute(i, j));
      }
    }
  }

  int rows() const { return rows_; }
  int columns() const { return columns_; }

  /// Objective of ruling (i, j). \pre 0 <= i < rows(), 0 <= j < columns().
  double operator()(int i, int j) const { return row(i)[j]; }

  RowCosts row(int i) const {
    RowCosts costs;
    costs.grid = this;
    costs.row = i;
    if (!exact_.empty()) costs.exact = exact_.data() + index(i, 0);
    if (!rounded_.empty()) costs.rounded = rounded_.data() + index(i, 0);
    return costs;
  }

  double compute(int i, int j) const {
    return twist(i, j) + length_weight_ * (row_points_[i] - column_points_[j]).norm();
  }

  double twist(int i, int j) const {
    return ruling_twist(row_points_[i], row_tangents_[i], column_points_[j], column_tangents_[j]);
  }

 private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(columns_) +
           static_cast<std::size_t>(j);
  }

  const std::vector<Vec3>& row_points_;
  const std::vector<Vec3>& row_tangents_;
  const std::vector<Vec3>& column_points_;
  const std::vector<Vec3>& column_tangents_;
  int rows_;
  int columns_;
  double length_weight_;
  std::vector<double> exact_;
  std::vector<float> rounded_;
};

inline double RowCosts::operator[](int j) const {
  if (exact) return exact[j];
  if (rounded) return rounded[j];
  return grid->compute(row, j);
}

// A monotone path in the grid: in row i it covers columns first[i]..last[i], and it steps
// down from (i, last[i]) to (i + 1, last[i]) = (i + 1, first[i + 1]).
struct RowSpans {
  std::vector<int> first;
  std::vector<int> last;
};

RowSpans shifted(const RowSpans& path, int columns) {
  RowSpans out = path;
  for (int& j : out.first) j += columns;
  for (int& j : out.last) j += columns;
  return out;
}

// Reused buffers of the band searches.
struct Workspace {
  std::vector<int> offset;
  std::vector<std::uint8_t> back;
  std::vector<double> previous;
  std::vector<double> current;
};

// Narrows the band to cells that a monotone path from (0, start) to (last_row, end) can
// visit and lays out one slot per cell (work.offset). Throws std::logic_error on an empty row.
void prepare_band(int last_row, int start, int end, std::vector<int>& from, std::vector<int>& to,
                  Workspace& work) {
  const int row_count = last_row + 1;
  from[0] = start;
  to[last_row] = end;
  for (int i = 1; i < row_count; ++i) from[i] = std::max(from[i], from[i - 1]);
  for (int i = last_row - 1; i >= 0; --i) to[i] = std::min(to[i], to[i + 1]);
  work.offset.assign(row_count + 1, 0);
  for (int i = 0; i < row_count; ++i) {
    if (from[i] > to[i]) throw std::logic_error("twist_dp: empty band row");
    work.offset[i + 1] = work.offset[i] + (to[i] - from[i] + 1);
  }
}

// Walks a path back from (last_row, end) to (0, start); step(i, j) moves one cell back and
// returns true when the previous cell was reached from above.
template <class Step>
void trace_back(int last_row, int start, int end, Step step, RowSpans& path) {
  path.first.assign(last_row + 1, 0);
  path.last.assign(last_row + 1, 0);
  int i = last_row;
  int j = end;
  path.last[i] = j;
  while (true) {
    path.first[i] = j;
    if (i == 0 && j == start) break;
    if (step(i, j)) {
      --i;
      path.last[i] = j;
    } else {
      --j;
    }
  }
}

// The cheapest monotone path from (0, start) to (last_row, end) whose cells in row i lie in
// columns [from[i], to[i]]; cell (i, j) costs grid(i mod rows, j mod columns). Returns the
// sum over the path's cells and writes the path.
double band_shortest_path(const CostGrid& grid, int last_row, int start, int end,
                          std::vector<int> from, std::vector<int> to, Workspace& work,
                          RowSpans& path) {
  prepare_band(last_row, start, end, from, to, work);
  work.back.resize(work.offset[last_row + 1]);
  const int columns = grid.columns();
  for (int i = 0; i <= last_row; ++i) {
    const int width = to[i] - from[i] + 1;
    const int grid_row = i % grid.rows();
    const RowCosts row_costs = grid.row(grid_row);
    work.current.assign(width, kInfinity);
    std::uint8_t* back = work.back.data() + work.offset[i];
    for (int k = 0; k < width; ++k) {
      const int j = from[i] + k;
      const int grid_column = j < columns ? j : j - columns;  // j < 2 columns
      const double cost = row_costs[grid_column];
      double above = kInfinity;
      if (i == 0) {
        if (j == start) above = 0.0;
      } else if (j >= from[i - 1] && j <= to[i - 1]) {
        above = work.previous[j - from[i - 1]];
      }
      const double left = k > 0 ? work.current[k - 1] : kInfinity;
      back[k] = above <= left ? 1 : 0;
      work.current[k] = std::min(above, left) + cost;
    }
    std::swap(work.previous, work.current);
  }
  const double total = work.previous[end - from[last_row]];
  if (!std::isfinite(total)) throw std::logic_error("twist_dp: band has no path");
  trace_back(
      last_row, start, end,
      [&](int i, int j) { return work.back[work.offset[i] + (j - from[i])] != 0; }, path);
  return total;
}

// A path of the unrolled cyclic grid (rows 0..rows, `columns` horizontal steps) is a "double
// fan" when it has a full row or a full column: it then visits one ruling twice and the strip
// is non-manifold there. Equivalently it has at most 3 maximal straight runs.
bool is_double_fan(const RowSpans& path, int columns) {
  const int last_row = static_cast<int>(path.first.size()) - 1;
  if (path.last[0] == path.first[last_row]) return true;
  for (int i = 0; i <= last_row; ++i) {
    if (path.last[i] - path.first[i] >= columns) return true;
  }
  return false;
}

// States of the search without double fans: the direction of the step into the cell
// (0 from the left, 1 from above) times the number of runs so far minus one, capped at 3.
constexpr int kRunStates = 4;
constexpr int kStates = 2 * kRunStates;
constexpr std::uint8_t kFromStart = 255;

// band_shortest_path restricted to paths of at least 4 runs (not double fans). Returns
// infinity, leaving `path` untouched, when the band holds no such path.
double band_shortest_path_without_double_fans(const CostGrid& grid, int last_row, int start,
                                              int end, std::vector<int> from, std::vector<int> to,
                                              Workspace& work, RowSpans& path) {
  prepare_band(last_row, start, end, from, to, work);
  work.back.resize(static_cast<std::size_t>(work.offset[last_row + 1]) * kStates);
  const int columns = grid.columns();
  const double start_cost = grid(0, start % columns);
  for (int i = 0; i <= last_row; ++i) {
    const int width = to[i] - from[i] + 1;
    const RowCosts row_costs = grid.row(i % grid.rows());
    work.current.assign(static_cast<std::size_t>(width) * kStates, kInfinity);
    for (int k = 0; k < width; ++k) {
      const int j = from[i] + k;
      if (i == 0 && j == start) continue;
      const double cost = row_costs[j < columns ? j : j - columns];
      double* value = work.current.data() + static_cast<std::size_t>(k) * kStates;
      std::uint8_t* back =
          work.back.data() + static_cast<std::size_t>(work.offset[i] + k) * kStates;
      for (int direction = 0; direction < 2; ++direction) {
        const double* before = nullptr;
        bool after_start = false;
        if (direction == 0 && k > 0) {
          before = work.current.data() + static_cast<std::size_t>(k - 1) * kStates;
          after_start = i == 0 && j - 1 == start;
        } else if (direction == 1 && i > 0 && j >= from[i - 1] && j <= to[i - 1]) {
          before = work.previous.data() + static_cast<std::size_t>(j - from[i - 1]) * kStates;
          after_start = i == 1 && j == start;
        }
        if (before == nullptr) continue;
        if (after_start) {
          value[direction * kRunStates] = start_cost + cost;
          back[direction * kRunStates] = kFromStart;
          continue;
        }
        const int other = 1 - direction;
        for (int runs = 0; runs < kRunStates; ++runs) {
          int best_state = direction * kRunStates + runs;
          double best = before[best_state];
          const auto consider = [&](int state) {
            if (before[state] < best) {
              best = before[state];
              best_state = state;
            }
          };
          if (runs > 0) consider(other * kRunStates + runs - 1);
          if (runs == kRunStates - 1) consider(other * kRunStates + runs);
          value[direction * kRunStates + runs] = best + cost;
          back[direction * kRunStates + runs] = static_cast<std::uint8_t>(best_state);
        }
      }
    }
    std::swap(work.previous, work.current);
  }
  const double* final_values =
      work.previous.data() + static_cast<std::size_t>(end - from[last_row]) * kStates;
  int state = 2 * kRunStates - 1;
  if (final_values[kRunStates - 1] <= final_values[state]) state = kRunStates - 1;
  const double total = final_values[state];
  if (!std::isfinite(total)) return kInfinity;
  trace_back(
      last_row, start, end,
      [&](int i, int j) {
        const bool from_above = state >= kRunStates;
        const std::size_t cell = static_cast<std::size_t>(work.offset[i] + (j - from[i]));
        const std::uint8_t previous = work.back[cell * kStates + state];
        state = previous == kFromStart ? 0 : previous;
        return from_above;
      },
      path);
  return total;
}

std::vector<std::pair<int, int>> path_cells(const RowSpans& path) {
  std::vector<std::pair<int, int>> cells;
  for (int i = 0; i < static_cast<int>(path.first.size()); ++i) {
    for (int j = path.first[i]; j <= path.last[i]; ++j) cells.emplace_back(i, j);
  }
  return cells;
}

struct CyclicPath {
  double cost = kInfinity;
  RowSpans path;  // rows 0..rows, columns in [0, 2 columns]
};

// Cyclic correspondence with a free start: row 0 is matched to column s for the best s.
// Rows of the unrolled grid are 0..rows (row `rows` is row 0 again), columns 0..2 columns.
class CyclicSolver {
 public:
  CyclicSolver(const CostGrid& grid, bool without_double_fans)
      : grid_(grid), without_double_fans_(without_double_fans) {}

  CyclicPath solve() {
    const int rows = grid_.rows();
    const int columns = grid_.columns();
    RowSpans first_path;
    const double cost = path_for_start(0, std::vector<int>(rows + 1, 0),
                                       std::vector<int>(rows + 1, columns), first_path);
    best_ = {cost, first_path};
    recurse(0, first_path, columns, shifted(first_path, columns));
    return best_;
  }

  // Every start with the whole grid as its band: O(n m^2), for small grids.
  CyclicPath solve_each_start() {
    const int rows = grid_.rows();
    const int columns = grid_.columns();
    for (int start = 0; start < columns; ++start) {
      RowSpans path;
      const double cost = path_for_start(start, std::vector<int>(rows + 1, start),
                                         std::vector<int>(rows + 1, start + columns), path);
      if (cost < best_.cost) best_ = {cost, path};
    }
    return best_;
  }

 private:
  // The cost of the best path for `start` in the band, with the closing ruling (rows, start +
  // columns), which is the starting one, charged once. Without double fans and no such path
  // in the band, returns infinity and the plain optimum as `path` (still a valid bound).
  double path_for_start(int start, std::vector<int> from, std::vector<int> to, RowSpans& path) {
    const int rows = grid_.rows();
    const int columns = grid_.columns();
    const double start_cost = grid_(0, start % columns);
    if (without_double_fans_) {
      const double total = band_shortest_path_without_double_fans(
          grid_, rows, start, start + columns, from, to, work_, path);
      if (std::isfinite(total)) return total - start_cost;
    }
    const double total = band_shortest_path(grid_, rows, start, start + columns, std::move(from),
                                            std::move(to), work_, path);
    return without_double_fans_ ? kInfinity : total - start_cost;
  }

  // Optimal paths for the starts strictly between low and high, searched between the
  // (non-crossing) optimal paths of low and high.
  void recurse(int low, const RowSpans& low_path, int high, const RowSpans& high_path) {
    if (high - low < 2) return;
    const int middle = low + (high - low) / 2;
    RowSpans middle_path;
    const double cost = path_for_start(middle, low_path.first, high_path.last, middle_path);
    if (cost < best_.cost) best_ = {cost, middle_path};
    recurse(low, low_path, middle, middle_path);
    recurse(middle, middle_path, high, high_path);
  }

  const CostGrid& grid_;
  bool without_double_fans_;
  Workspace work_;
  CyclicPath best_;
};

CyclicPath best_cyclic_path(const CostGrid& grid, std::size_t max_each_start_work) {
  CyclicPath best = CyclicSolver(grid, false).solve();
  if (!is_double_fan(best.path, grid.columns())) return best;
  // The plain optimum is non-manifold. Non-crossing is not proven for the restricted paths,
  // so small grids search every start; larger ones keep the divide and conquer.
  const std::size_t work = static_cast<std::size_t>(grid.rows() + 1) *
                           static_cast<std::size_t>(grid.columns() + 1) *
                           static_cast<std::size_t>(grid.columns());
  CyclicSolver restricted(grid, true);
  return work <= max_each_start_work ? restricted.solve_each_start() : restricted.solve();
}

void check_polyline(const Polyline& polyline, const char* name) {
  const std::string label(name);
  if (polyline.points.empty()) throw InvalidInputException("polyline " + label + " is empty");
  if (polyline.closed && polyline.points.size() == 2) {
    throw InvalidInputException("closed polyline " + label + " has 2 points; need at least 3");
  }
  if (!polyline.uvs.empty() && polyline.uvs.size() != polyline.points.size()) {
    throw InvalidInputException("polyline " + label + " has " +
                                std::to_string(polyline.uvs.size()) + " uvs for " +
                                std::to_string(polyline.points.size()) + " points");
  }
  for (std::size_t i = 0; i < polyline.points.size(); ++i) {
    if (!polyline.points[i].allFinite()) {
      throw InvalidInputException("polyline " + label + " point " + std::to_string(i) +
                                  " is not finite");
    }
  }
}

double length_weight(const Polyline& a, const Polyline& b, const TwistOptions& options) {
  std::vector<Vec3> all = a.points;
  all.insert(all.end(), b.points.begin(), b.points.end());
  const auto box = bounding_box(all);
  const double diameter = (box[1] - box[0]).norm();
  return diameter > 0.0 ? options.ruling_length_weight / diameter : 0.0;
}

RuledStrip empty_strip(const Polyline& a, const Polyline& b) {
  RuledStrip strip;
  strip.a_count = static_cast<int>(a.points.size());
  strip.b_count = static_cast<int>(b.points.size());
  strip.a_closed = a.closed && !a.is_point();
  strip.b_closed = b.closed && !b.is_point();
  strip.mesh.vertices = a.points;
  strip.mesh.vertices.insert(strip.mesh.vertices.end(), b.points.begin(), b.points.end());
  if (!a.uvs.empty() && !b.uvs.empty()) {
    strip.uvs = a.uvs;
    strip.uvs.insert(strip.uvs.end(), b.uvs.begin(), b.uvs.end());
  }
  return strip;
}

// Triangles of a correspondence given as cells (a, b) in traversal indices (unrolled: taken
// modulo the counts); b_vertex maps a traversal index of B to its strip vertex.
template <class BVertex>
void add_triangles(const std::vector<std::pair<int, int>>& cells, int a_count, BVertex b_vertex,
                   std::vector<Triangle>& triangles) {
  for (std::size_t k = 0; k + 1 < cells.size(); ++k) {
    const auto [a, b] = cells[k];
    const auto [next_a, next_b] = cells[k + 1];
    if (next_a != a) {
      triangles.push_back({next_a % a_count, a % a_count, b_vertex(b)});
    } else {
      triangles.push_back({a % a_count, b_vertex(b), b_vertex(next_b)});
    }
  }
}

RuledStrip fan_strip(const Polyline& a, const Polyline& b) {
  RuledStrip strip = empty_strip(a, b);
  const int n = strip.a_count;
  const int m = strip.b_count;
  auto& triangles = strip.mesh.triangles;
  if (a.is_point() && b.is_point()) {
    triangles.push_back({0, 1, 1});
  } else if (b.is_point()) {
    for (int i = 0; i + 1 < n; ++i) triangles.push_back({i + 1, i, n});
    if (strip.a_closed) triangles.push_back({0, n - 1, n});
  } else {
    for (int j = 0; j + 1 < m; ++j) triangles.push_back({0, 1 + j, 2 + j});
    if (strip.b_closed) triangles.push_back({0, m, 1});
  }
  return strip;
}

RuledStrip open_strip(const Polyline& a, const Polyline& b, const TwistOptions& options) {
  RuledStrip strip = empty_strip(a, b);
  const int n = strip.a_count;
  const int m = strip.b_count;
  const auto a_tangents = unit_tangents(a.points, false);
  const auto b_tangents = unit_tangents(b.points, false);
  const CostGrid grid(a.points, a_tangents, b.points, b_tangents, length_weight(a, b, options));
  Workspace work;
  RowSpans path;
  band_shortest_path(grid, n - 1, 0, m - 1, std::vector<int>(n, 0), std::vector<int>(n, m - 1),
                     work, path);
  const auto cells = path_cells(path);
  for (const auto& [i, j] : cells) strip.twist_cost += grid.twist(i, j);
  add_triangles(
      cells, n, [n](int j) { return n + j; }, strip.mesh.triangles);
  return strip;
}

struct CyclicCandidate {
  double cost = kInfinity;
  double twist = 0.0;
  std::vector<std::pair<int, int>> cells;  // (a, b) traversal indices, unrolled
  bool b_reversed = false;
};

CyclicCandidate cyclic_candidate(const Polyline& a, const Polyline& b, bool reverse_b,
                                 double weight, const TwistOptions& options) {
  const int n = static_cast<int>(a.points.size());
  const int m = static_cast<int>(b.points.size());
  std::vector<Vec3> b_points = b.points;
  if (reverse_b) std::reverse(b_points.begin(), b_points.end());
  const auto a_tangents = unit_tangents(a.points, true);
  const auto b_tangents = unit_tangents(b_points, true);
  // The free start ranges over the columns, so the shorter polyline goes there: the divide
  // and conquer then costs O(n m log min(n, m)).
  const bool a_in_rows = n >= m;
  const CostGrid grid = a_in_rows ? CostGrid(a.points, a_tangents, b_points, b_tangents, weight)
                                  : CostGrid(b_points, b_tangents, a.points, a_tangents, weight);
  const CyclicPath best = best_cyclic_path(grid, options.max_each_start_work);

  CyclicCandidate candidate;
  candidate.cost = best.cost;
  candidate.b_reversed = reverse_b;
  const auto cells = path_cells(best.path);
  for (std::size_t k = 0; k + 1 < cells.size(); ++k) {
    candidate.twist += grid.twist(cells[k].first % grid.rows(), cells[k].second % grid.columns());
  }
  candidate.cells.reserve(cells.size());
  for (const auto& [row, column] : cells) {
    candidate.cells.emplace_back(a_in_rows ? row : column, a_in_rows ? column : row);
  }
  return candidate;
}

RuledStrip closed_strip(const Polyline& a, const Polyline& b, const TwistOptions& options) {
  RuledStrip strip = empty_strip(a, b);
  const int n = strip.a_count;
  const int m = strip.b_count;
  const double weight = length_weight(a, b, options);
  CyclicCandidate best = cyclic_candidate(a, b, options.b_direction < 0, weight, options);
  if (options.b_direction == 0 && options.try_reversed_b) {
    CyclicCandidate reversed = cyclic_candidate(a, b, true, weight, options);
    if (reversed.cost < best.cost) best = std::move(reversed);
  }
  strip.twist_cost = best.twist;
  const bool reversed = best.b_reversed;
  add_triangles(
      best.cells, n, [n, m, reversed](int j) { return n + (reversed ? m - 1 - j % m : j % m); },
      strip.mesh.triangles);
  return strip;
}

}  // namespace

RuledStrip twist_minimizing_strip(const Polyline& a, const Polyline& b,
                                  const TwistOptions& options) {
  check_polyline(a, "A");
  check_polyline(b, "B");
  if (!(options.ruling_length_weight >= 0.0) || !std::isfinite(options.ruling_length_weight)) {
    throw InvalidInputException("twist options: ruling_length_weight must be finite and >= 0");
  }
  if (a.is_point() || b.is_point()) return fan_strip(a, b);
  if (a.closed != b.closed) {
    throw InvalidInputException(std::string("cannot build a ruled strip between a ") +
                                (a.closed ? "closed" : "open") + " polyline A and " +
                                (b.closed ? "a closed" : "an open") + " polyline B");
  }
  return a.closed ? closed_strip(a, b, options) : open_strip(a, b, options);
}

}  // namespace papercraft
