// twist_minimizing_strip between two closed loops of n vertices each: the cyclic divide and
// conquer should grow as n^2 log n: the fitted coefficient's RMS stays small.
//
//   build/bench/twist_dp_bench --benchmark_filter=Closed

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "engine/ruled/twist_dp.h"

namespace {

papercraft::Polyline wavy_loop(std::mt19937& rng, int count, double z) {
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  papercraft::Polyline loop;
  loop.closed = true;
  for (int k = 0; k < count; ++k) {
    const double t = 2.0 * M_PI * k / count;
    const double r = 1.0 + 0.3 * std::sin(3.0 * t) + noise(rng);
    loop.points.emplace_back(r * std::cos(t), r * std::sin(t),
                             z + 0.2 * std::sin(2.0 * t) + noise(rng));
  }
  return loop;
}

void ClosedStrip(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937 rng(1);
  const papercraft::Polyline a = wavy_loop(rng, n, 0.0);
  const papercraft::Polyline b = wavy_loop(rng, n, 1.0);
  papercraft::TwistOptions options;
  options.try_reversed_b = false;
  for (auto _ : state) {
    benchmark::DoNotOptimize(papercraft::twist_minimizing_strip(a, b, options));
  }
  state.SetComplexityN(n);
}
BENCHMARK(ClosedStrip)
    ->RangeMultiplier(2)
    ->Range(128, 2048)
    ->Unit(benchmark::kMillisecond)
    ->Complexity([](benchmark::IterationCount n) {
      return static_cast<double>(n) * static_cast<double>(n) * std::log2(static_cast<double>(n));
    });

void OpenStrip(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937 rng(2);
  papercraft::Polyline a = wavy_loop(rng, n, 0.0);
  papercraft::Polyline b = wavy_loop(rng, n, 1.0);
  a.closed = b.closed = false;
  for (auto _ : state) benchmark::DoNotOptimize(papercraft::twist_minimizing_strip(a, b));
}
BENCHMARK(OpenStrip)->RangeMultiplier(4)->Range(128, 2048)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
