// The grid broad phase on N spheres of equal radius at a fixed volume fraction (0.3) in a
// cube, N = 10³ … 10⁶: time per contactor should stay flat (linear total cost). Twice:
// contactors numbered in space (as scenes built layer by layer are) and in random order
// (every access a cache miss once the arrays outgrow the cache).
//
//   build/bin/moreau_bench_broadphase --benchmark_counters_tabular=true
//
// BM_GridSilo: grains between long walls, with the walls in the cell-size choice (the
// behaviour before) and kept out of it (the default), in one run.
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

/// A 2D silo: N touching disks of radius 4 mm (boxes grown by 1 mm) in a bin of square
/// section, between two walls as tall as the bin is wide and a floor (segments 1 cm thick).
moreau::BroadPhaseInput silo(std::size_t n) {
  const double r = 0.004 + 0.0005, pitch = 0.008;  // touching grains
  const auto columns = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double width = columns * pitch, height = (n + columns - 1) / columns * pitch;
  moreau::BroadPhaseInput in;
  in.dim = 2;
  in.groups = 2;
  in.interacts = {1, 1, 1, 0};  // grains with grains and walls
  auto add = [&](double x0, double y0, double x1, double y1, int group) {
    in.lo.insert(in.lo.end(), {x0, y0, 0});
    in.hi.insert(in.hi.end(), {x1, y1, 0});
    in.body.push_back(static_cast<int>(in.body.size()));
    in.group.push_back(group);
  };
  add(-0.01, 0, 0, height, 1);                   // left wall
  add(width, 0, width + 0.01, height, 1);        // right wall
  add(-0.01, -0.01, width + 0.01, 0, 1);         // floor
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (i % columns + 0.5) * pitch, y = (i / columns + 0.5) * pitch;
    add(x - r, y - r, x + r, y + r, 0);
  }
  return in;
}

/// Long walls in the grid: `large_ratio` 10⁹ is the cell choice before walls were kept out
/// of it (the largest box: the walls), the default 4 keeps them out (the largest grain).
void BM_GridSilo(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const bool walls_in_cells = state.range(1) != 0;
  const moreau::BroadPhaseInput in = silo(n);
  auto grid = moreau_test::create<moreau::BroadPhase>("grid", {{"large_ratio", walls_in_cells ? 1e9 : 4.0}},
                                                      moreau::BuildContext{});
  std::vector<std::pair<int, int>> pairs;
  grid->pairs(in, pairs);
  for (auto _ : state) {
    grid->pairs(in, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.SetLabel(walls_in_cells ? "walls set the cell (before)" : "walls kept out of the cell");
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.counters["ns_per_contactor"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_GridSilo)->ArgsProduct({{600, 2400, 10000}, {1, 0}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
