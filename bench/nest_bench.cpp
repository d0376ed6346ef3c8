// The layout's nesting (nodes/layout/nesting.h) on many pieces: nest_shapes with the layout's
// defaults (24 rotations, three orders, repacks, no neighbours) on N star-shaped pieces of
// 100 to 6,000 mm^2 (log-uniform, fixed seed) on an A4 page's printable area, one thread.
// Counters: pages, and the placements' checksum (the sum of page * 1000 + offset), which a
// change meant only to speed the fill up must leave as it is.
//
//   build/bench/nest_bench                       # N = 100, 400
//   build/bench/nest_bench --benchmark_filter=/400
//
// --strips DIR...: each DIR a finished run's folder (strips.json, report.json); times, on one
// thread, layout_pages (the layout node's whole work: nesting, the tries with long strips split,
// tabs and labels) on its flat strips at the run's print scale, and prints per DIR the strips,
// pages, seconds and a checksum of where every piece, label and number went, then the sums.
//   build/bench/nest_bench --strips OUT/cycloidal OUT/elephant

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "nodes/layout/nesting.h"
#include "nodes/layout/pages.h"
#include "support/flat_strips_json.h"

namespace {

using papercraft::Vec2;
using papercraft::layout_internal::NestShape;

// A star-shaped piece round the origin: a fan of triangles to 5..14 rim points at radii
// varying by up to half, scaled to `area` mm^2.
NestShape star(std::mt19937& rng, double area) {
  std::uniform_int_distribution<int> corners(5, 14);
  std::uniform_real_distribution<double> radius(0.5, 1.0), stretch(1.0, 4.0);
  const int n = corners(rng);
  const double along = stretch(rng);  // long pieces, as strips are
  std::vector<Vec2> rim;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * M_PI * k / n, r = radius(rng);
    rim.emplace_back(along * r * std::cos(t), r * std::sin(t));
  }
  double a = 0.0;
  for (int k = 0; k < n; ++k) {
    const Vec2 &p = rim[k], &q = rim[(k + 1) % n];
    a += 0.5 * (p.x() * q.y() - p.y() * q.x());
  }
  const double scale = std::sqrt(area / a);
  NestShape shape;
  for (int k = 0; k < n; ++k)
    shape.convex.push_back({Vec2::Zero(), rim[k] * scale, rim[(k + 1) % n] * scale});
  return shape;
}

void Nest(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> log_area(std::log(100.0), std::log(6000.0));
  std::vector<NestShape> shapes;
  for (int i = 0; i < state.range(0); ++i) shapes.push_back(star(rng, std::exp(log_area(rng))));
  const Vec2 area(190.0, 277.0);
  const papercraft::layout_internal::NestOptions options;
  int pages = 0;
  double checksum = 0.0;
  for (auto _ : state) {
    const auto placements = papercraft::layout_internal::nest_shapes(shapes, area, options, &pages);
    checksum = 0.0;
    for (const auto& p : placements) checksum += p.page * 1000.0 + p.offset.x() + p.offset.y();
    benchmark::DoNotOptimize(checksum);
  }
  state.counters["pages"] = pages;
  state.counters["checksum"] = checksum;
}
BENCHMARK(Nest)->Arg(100)->Arg(400)->Unit(benchmark::kSecond)->Iterations(1);

int layout_runs(int argc, char** argv) {
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  int total_pieces = 0, total_pages = 0;
  double total_seconds = 0.0;
  std::printf("| run | strips | pages | seconds | checksum |\n|---|---:|---:|---:|---:|\n");
  for (int i = 0; i < argc; ++i) {
    const std::string dir = argv[i];
    const auto run = papercraft::testing::read_run_strips(dir, "nest_bench");
    if (!run) return 1;
    const std::vector<papercraft::FlatStrip>& strips = run->strips;
    papercraft::LayoutOptions options;
    options.scale = run->mm_per_unit;
    const auto start = std::chrono::steady_clock::now();
    const papercraft::PatternLayout layout = papercraft::layout_pages(strips, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int pages = static_cast<int>(layout.pages.size());
    // Where everything went: a change meant only to speed the layout up leaves it as it is.
    double checksum = 0.0;
    for (std::size_t p = 0; p < layout.pages.size(); ++p)
      for (const auto& piece : layout.pages[p].pieces) {
        for (const papercraft::Vec2& v : piece.vertices) checksum += (p + 1) * (v.x() + 2 * v.y());
        for (const auto& label : piece.labels)
          checksum += (p + 1) * (label.position.x() + 2 * label.position.y() + label.size_mm);
        checksum += (p + 1) * (piece.number.position.x() + 2 * piece.number.position.y());
      }
    std::printf("| %s | %zu | %d | %.2f | %.6e |\n", dir.c_str(), strips.size(), pages, seconds,
                checksum);
    total_pieces += static_cast<int>(strips.size()), total_pages += pages;
    total_seconds += seconds;
  }
  std::printf("| **total** | %d | %d | %.2f | |\n", total_pieces, total_pages, total_seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--strips") == 0) return layout_runs(argc - 2, argv + 2);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
