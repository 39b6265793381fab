// The grid broad phase on N spheres of equal radius at a fixed volume fraction (0.3) in a
// cube, N = 10³ … 10⁶: time per contactor should stay flat (linear total cost).
//
//   build/bin/moreau_bench_broadphase --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <moreau/broadphase.hpp>
#include <random>

#include "sim.hpp"

namespace {

moreau::BroadPhaseInput spheres(std::size_t n) {
  const double r = 0.5, fraction = 0.3;
  const double side = std::cbrt(n * 4.0 / 3.0 * M_PI * r * r * r / fraction);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, side);
  moreau::BroadPhaseInput in;
  in.dim = 3;
  in.groups = 1;
  in.interacts = {1};
  in.lo.resize(3 * n);
  in.hi.resize(3 * n);
  in.body.resize(n);
  in.group.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    in.body[i] = static_cast<int>(i);
    for (int k = 0; k < 3; ++k) {
      const double c = u(rng);
      in.lo[3 * i + k] = c - r;
      in.hi[3 * i + k] = c + r;
    }
  }
  return in;
}

void BM_GridBroadPhase(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const moreau::BroadPhaseInput in = spheres(n);
  auto grid = moreau_test::create<moreau::BroadPhase>("grid", {{"cell", 0.0}}, moreau::BuildContext{});
  std::vector<std::pair<int, int>> pairs;
  for (auto _ : state) {
    grid->pairs(in, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["ns_per_contactor"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs_per_contactor"] = static_cast<double>(pairs.size()) / n;
  state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
}
BENCHMARK(BM_GridBroadPhase)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->Complexity();

}  // namespace

BENCHMARK_MAIN();
