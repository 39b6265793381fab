// The grid broad phase on N spheres of equal radius at a fixed volume fraction (0.3) in a
// cube, N = 10³ … 10⁶: time per contactor should stay flat (linear total cost). Twice:
// contactors numbered in space (as scenes built layer by layer are) and in random order
// (every access a cache miss once the arrays outgrow the cache).
//
//   build/bin/moreau_bench_broadphase --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <moreau/broadphase.hpp>
#include <random>

#include "sim.hpp"

namespace {

/// `ordered`: contactors numbered in space (z-slab, then y-row, then x), as a scene built
/// layer by layer numbers them; otherwise in random order, the worst case for caches.
moreau::BroadPhaseInput spheres(std::size_t n, bool ordered) {
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
  std::vector<std::array<double, 3>> centre(n);
  for (auto& c : centre)
    for (int k = 0; k < 3; ++k) c[k] = u(rng);
  if (ordered) {
    const auto key = [&](const std::array<double, 3>& c) {
      return std::array<long, 3>{std::lround(std::floor(c[2] / (2 * r))), std::lround(std::floor(c[1] / (2 * r))),
                                 std::lround(std::floor(c[0] / (2 * r)))};
    };
    std::sort(centre.begin(), centre.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  }
  for (std::size_t i = 0; i < n; ++i) {
    in.body[i] = static_cast<int>(i);
    for (int k = 0; k < 3; ++k) {
      in.lo[3 * i + k] = centre[i][k] - r;
      in.hi[3 * i + k] = centre[i][k] + r;
    }
  }
  return in;
}

void run(benchmark::State& state, bool ordered) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const moreau::BroadPhaseInput in = spheres(n, ordered);
  auto grid = moreau_test::create<moreau::BroadPhase>("grid", {{"cell", 0.0}}, moreau::BuildContext{});
  std::vector<std::pair<int, int>> pairs;
  grid->pairs(in, pairs);  // warm-up: at 10⁶ the timed loop runs once, and first-touch page faults are not the algorithm
  for (auto _ : state) {
    grid->pairs(in, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["ns_per_contactor"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs_per_contactor"] = static_cast<double>(pairs.size()) / n;
  state.SetComplexityN(static_cast<benchmark::IterationCount>(n));
}
void BM_GridBroadPhase(benchmark::State& state) { run(state, false); }
void BM_GridBroadPhaseOrdered(benchmark::State& state) { run(state, true); }
BENCHMARK(BM_GridBroadPhaseOrdered)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_GridBroadPhase)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond)->Complexity();

}  // namespace

BENCHMARK_MAIN();
