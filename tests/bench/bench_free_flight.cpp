// One contact-free step (free_velocity + update_dofs + the depth swap) of 10⁶ free-flying
// 3D bodies. Reports ns per body per step, and, as the memory-traffic reference, the
// time to stream the same number of bytes (read and write) through memory.
//
//   build/bin/moreau_bench_free_flight --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cstring>
#include <random>

#include "sim.hpp"

using namespace moreau_test;
namespace R = moreau::rigid;

namespace {

constexpr std::size_t kBodies = 1'000'000;

/// Bytes one step reads and writes per body (3D, no external forces, no contacts):
/// free_velocity reads v, ω, q, 1/m, I (6) and writes v_free, ω_free; update_dofs reads
/// v_free, ω_free, x, v, ω, q, 1/m and writes x, v, ω, q.
constexpr double kBytesAnisotropic = 8.0 * ((3 + 3 + 4 + 1 + 6) + (3 + 3) + (3 + 3 + 3 + 3 + 3 + 4 + 1) + (3 + 3 + 3 + 4));
constexpr double kBytesIsotropic = kBytesAnisotropic - 8.0 * 4;  // free_velocity does not read q

std::unique_ptr<Sim> make(bool isotropic) {
  auto s = std::make_unique<Sim>(3, 1e-4, 0.5, std::vector<double>{0, 0, -9.81});
  std::vector<moreau::BodyLayout> bodies(kBodies);
  for (std::size_t i = 0; i < kBodies; ++i) bodies[i] = moreau::BodyLayout{"b" + std::to_string(i), 0, 1, 0};
  s->state.add_bodies(bodies);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  auto fill = [&](const char* f, auto gen) {
    for (moreau::Depth d : {moreau::Depth::begin, moreau::Depth::end}) {
      auto& fld = s->field(f);
      for (std::size_t i = 0; i < kBodies * fld.components(); ++i) fld.data(d)[i] = gen(i % fld.components());
    }
  };
  fill(R::position, [&](int) { return 100 * u(rng); });
  fill(R::velocity, [&](int) { return u(rng); });
  fill(R::angular_velocity, [&](int) { return 3 * u(rng); });
  fill(R::orientation, [&](int k) { return k == 0 ? 1.0 : 0.0; });
  fill(R::mass, [](int) { return 1.0; });
  fill(R::inverse_mass, [](int) { return 1.0; });
  const double I[6] = {isotropic ? 2.0 : 1.0, 2.0, isotropic ? 2.0 : 3.0, 0, 0, 0};
  fill(R::inertia, [&](int k) { return I[k]; });
  fill(R::inverse_inertia, [&](int k) { return k < 3 ? 1 / I[k] : 0.0; });
  s->prepare();
  return s;
}

void step(benchmark::State& bs, bool isotropic, double bytes) {
  auto sim = make(isotropic);
  for (auto _ : bs) sim->step();
  const double n = static_cast<double>(bs.iterations()) * kBodies;
  bs.counters["ns_per_body"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bs.counters["bytes_per_body"] = bytes;
  bs.counters["GB_per_s"] = benchmark::Counter(n * bytes * 1e-9, benchmark::Counter::kIsRate);
}

void BM_StepAnisotropic(benchmark::State& bs) { step(bs, false, kBytesAnisotropic); }
void BM_StepIsotropic(benchmark::State& bs) { step(bs, true, kBytesIsotropic); }

/// Memory-traffic reference: read and write the same bytes as an anisotropic step, as a
/// streaming triad over arrays of the same total size.
void BM_StreamReference(benchmark::State& bs) {
  const std::size_t doubles = static_cast<std::size_t>(kBytesAnisotropic / 8) * kBodies;
  const std::size_t half = doubles / 2;
  std::vector<double> a(half, 1.0), b(half, 2.0);
  for (auto _ : bs) {
    for (std::size_t i = 0; i < half; ++i) b[i] = a[i] * 1.0000001 + b[i] * 0.5;  // reads a, b; writes b
    benchmark::DoNotOptimize(b.data());
    benchmark::ClobberMemory();
  }
  const double n = static_cast<double>(bs.iterations()) * kBodies;
  bs.counters["ns_per_body"] = benchmark::Counter(n * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bs.counters["bytes_per_body"] = 8.0 * 3 * half / kBodies;  // 2 reads + 1 write per element
  bs.counters["GB_per_s"] = benchmark::Counter(n * 8.0 * 3 * half / kBodies * 1e-9, benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_StepAnisotropic)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StepIsotropic)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_StreamReference)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_MAIN();
