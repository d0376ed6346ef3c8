// narrow_measure (core/piece_width.h), the 3D width check the refinement runs on every piece a
// cut would make, on one 100 x 20 plate (a 5 mm disc, spacing 5/8) meshed three ways: in
// near-square cells (the reference), and in needles 20 long and 0.25 or 0.05 wide, as CAD
// meshes have them. The needles should cost about what the squares do (the `samples` counter
// says how many points were measured): a needle sampled k x k with k set by its long side
// took 32 x 32 points for an area of 5 or 1.
//
//   build/bench/narrow_measure_bench

#include <benchmark/benchmark.h>

#include <cmath>

#include "core/piece_width.h"

namespace {

// The plate, 100 x 20, in cells of cell_x x cell_y, each two triangles.
papercraft::TriangleMesh plate(double cell_x, double cell_y) {
  papercraft::TriangleMesh mesh;
  const int nx = static_cast<int>(std::lround(100.0 / cell_x));
  const int ny = static_cast<int>(std::lround(20.0 / cell_y));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.vertices.push_back({100.0 * i / nx, 20.0 * j / ny, 0.0});
  auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

void measure(benchmark::State& state, const papercraft::TriangleMesh& mesh) {
  std::size_t samples = 0;
  for (auto _ : state) {
    const papercraft::NarrowMeasure m = papercraft::narrow_measure(mesh, 5.0);
    samples = m.samples;
    benchmark::DoNotOptimize(m.largest_region);
  }
  state.counters["samples"] = static_cast<double>(samples);
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

void Squares(benchmark::State& state) {
  measure(state, plate(1.0, 1.0));
}
BENCHMARK(Squares)->Unit(benchmark::kMillisecond);

void Needles(benchmark::State& state) {
  measure(state, plate(state.range(0) / 100.0, 20.0));
}
BENCHMARK(Needles)->Arg(25)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
