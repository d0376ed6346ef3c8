// The merge node's joins and the width measure they spend most of their time in.
//
//   build/bench/merge_bench                      # Google Benchmark: the width measure
//   build/bench/merge_bench --strips DIR...      # the merge node's calls on real strips
//
// Benchmarks (one thread): BM_NarrowRaster/k times narrow_raster (core/piece_width.h) on a
// comb (a 100 x 20 plate with twelve 2 x 30 teeth, in mm, width 5), scaled by k, so its raster
// holds about k^2 x 21,000 cells; BM_NarrowRasterByDistanceTransform/k computes the same counts
// by two squared Euclidean distance transforms (the method narrow_raster used before it checked
// rows; tests/support/narrow_raster_reference.h). Both start from the piece's points; the
// reference's rasterizing is done once, outside the timing, so the ratio of the two understates
// the gain. The run aborts where the two counts differ.
//
// --strips DIR...: each DIR holds strips.json and report.json of a run whose merge stage was
// `merge.none` (so strips.json holds the strips as unfolded), e.g.
//   papercraft run MESH -c pre_merge.yaml --tolerance 2% --height 200 --out DIR
// with the default pipeline but `merge: {impl: merge.none, ...}`. Times, on one thread, what
// merge.congruent does with them: merge_congruent, then join_small_and_narrow_strips with
// min_area_mm2 100 and min_width_mm 5 at the run's print scale; prints per DIR the strips in and
// pieces out, the pieces narrower than 3 mm over more than 25% of their area, those under
// 1 cm^2, and the seconds; then the sums.

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/flat_boundary.h"
#include "core/piece_width.h"
#include "nodes/merge/congruent.h"
#include "support/flat_strips_json.h"
#include "support/narrow_raster_reference.h"

namespace {

using namespace papercraft;

constexpr double kWidth = 5.0;

// The comb scaled by k: a plate (0..100, 0..20) and teeth (2 wide, 30 long) every 8 mm above it.
void comb(double k, std::vector<Vec2>& points, std::vector<Triangle>& triangles) {
  points.clear();
  triangles.clear();
  auto rectangle = [&](double x0, double y0, double x1, double y1) {
    const int first = static_cast<int>(points.size());
    points.insert(points.end(),
                  {Vec2(x0, y0) * k, Vec2(x1, y0) * k, Vec2(x1, y1) * k, Vec2(x0, y1) * k});
    triangles.push_back({first, first + 1, first + 2});
    triangles.push_back({first, first + 2, first + 3});
  };
  rectangle(0, 0, 100, 20);
  for (int tooth = 0; tooth < 12; ++tooth) rectangle(4 + 8 * tooth, 20, 6 + 8 * tooth, 50);
}

void BM_NarrowRaster(benchmark::State& state) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  comb(static_cast<double>(state.range(0)), points, triangles);
  NarrowRaster raster;
  for (auto _ : state) {
    raster = narrow_raster(points, triangles, kWidth);
    benchmark::DoNotOptimize(raster);
  }
  state.counters["narrow_share"] = raster.fraction();
}
BENCHMARK(BM_NarrowRaster)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);

void BM_NarrowRasterByDistanceTransform(benchmark::State& state) {
  std::vector<Vec2> points;
  std::vector<Triangle> triangles;
  comb(static_cast<double>(state.range(0)), points, triangles);
  const NarrowRaster grid = narrow_raster(points, triangles, kWidth);
  // The same margin as narrow_raster's: one width around the piece.
  const testing::InsideCells cells = testing::inside_cells(
      points, triangles, grid, static_cast<int>(std::ceil(kWidth / grid.cell)));
  NarrowRaster raster;
  for (auto _ : state) {
    raster = testing::distance_transform_narrow_raster(cells, kWidth, grid);
    benchmark::DoNotOptimize(raster);
  }
  if (raster.inside != grid.inside || raster.narrow != grid.narrow) {
    std::fprintf(stderr, "merge_bench: the counts differ (%ld/%ld against %ld/%ld)\n",
                 raster.narrow, raster.inside, grid.narrow, grid.inside);
    std::abort();
  }
  state.counters["narrow_share"] = raster.fraction();
}
BENCHMARK(BM_NarrowRasterByDistanceTransform)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond);

int merge_strips(int argc, char** argv) {
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  int total_in = 0, total_out = 0, total_narrow = 0, total_small = 0;
  double total_seconds = 0.0;
  std::printf(
      "| run | strips | pieces | narrow | small | seconds |\n|---|---:|---:|---:|---:|---:|\n");
  for (int i = 0; i < argc; ++i) {
    const std::string dir = argv[i];
    auto run = testing::read_run_strips(dir, "merge_bench");
    if (!run) return 1;
    const double mm = run->mm_per_unit;
    std::vector<FlatStrip> strips = std::move(run->strips);
    const int in = static_cast<int>(strips.size());
    const auto start = std::chrono::steady_clock::now();
    strips = merge_congruent(std::move(strips));
    strips = join_small_and_narrow_strips(std::move(strips), 100.0 / (mm * mm), 5.0 / mm);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int narrow = 0, small = 0;
    for (const FlatStrip& strip : strips) {
      narrow += narrow_area_fraction(strip.vertices2d, strip.triangles, 3.0 / mm) > 0.25;
      small += flat_area(strip) * mm * mm < 100.0;
    }
    std::printf("| %s | %d | %zu | %d | %d | %.2f |\n", dir.c_str(), in, strips.size(), narrow,
                small, seconds);
    total_in += in, total_out += static_cast<int>(strips.size());
    total_narrow += narrow, total_small += small, total_seconds += seconds;
  }
  std::printf("| **total** | %d | %d | %d | %d | %.2f |\n", total_in, total_out, total_narrow,
              total_small, total_seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--strips") == 0) {
    try {
      return merge_strips(argc - 2, argv + 2);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "merge_bench: %s\n", e.what());
      return 1;
    }
  }
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
