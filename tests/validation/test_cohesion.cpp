// Cohesive bonds (`cohesive`, LMGC90's IQS_MOHR_DS_CLB; docs/laws.md).
//
// 1. A bonded block on an incline: n contact points of area A, cohesion C, friction μ.
//    The intact bonds carry ‖T‖ ≤ n C A + μ N, so the block holds up to the angle with
//    W (sin α − μ cos α) = n C A, beyond tan α = μ; above it the bonds break at the first
//    step and the block slides with a = g (sin α − μ cos α). Accelerations as in
//    test_blocks.cpp: a constant acceleration is integrated exactly by θ = 1/2 and the
//    solver runs to 1e-12, so 1e-6 g covers rounding; the angles tested sit at least 2 %
//    in tan α from the threshold, far more than the solver tolerance moves it.
// 2. A hanging chain of bonded disks (2D) and spheres (3D), the top one fixed, the bottom
//    one pulled down by a force growing at a constant rate ρ. The bonds are rigid, so the
//    chain is static while they hold and bond k carries F(t) + (weights below it) exactly:
//    the top bond carries the most and breaks first, at the first step whose load
//    F(t⁻ + θh) + n m g reaches the tensile strength σ_t A. Checked: the step (exact), the
//    bond (the top one, the others intact), the tension it carried just before (its
//    statics, to 1e-9 of the strength: solver tolerance 1e-12).
#include <cmath>
#include <sstream>

#include "incline_scene.hpp"
#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double g = 9.81;

struct InclineResult {
  double acceleration;
  double intact_bonds;
};

/// A block bonded to an incline (2D: polygon on a slab, 2 points; 3D: box on a plane, 4).
InclineResult bonded_block(int dim, double alpha, double mu, double cohesion, double area) {
  std::ostringstream law;
  law.precision(17);
  law << R"({"type": "cohesive", "friction": )" << mu << R"(, "cohesion": )" << cohesion << R"(, "tensile_strength": )"
      << 0.9 * cohesion / mu << R"(, "area": )" << area << "}";
  const SceneRun run = run_block_on_incline(dim == 2 ? "bonded_incline_2d" : "bonded_incline_3d", dim, alpha, law.str());
  return {(downhill_speed(run, run.frames[5], dim, alpha) - downhill_speed(run, run.frames[1], dim, alpha)) / 0.4,
          run.at(run.frames.back(), "laws/bonds")[0]};
}

void sweep_bonded_incline(int dim) {
  // Block 0.2 × 0.1 (× 0.2 in 3D), density 1000: W = 20 g (2D, per metre) or 4 g (3D).
  const double mu = 0.3, cohesion = 100, area = dim == 2 ? 0.1 : 0.01;
  const int points = dim == 2 ? 2 : 4;
  const double W = (dim == 2 ? 20.0 : 4.0) * g, hold = points * cohesion * area / W;
  // Threshold: sin α − μ cos α = hold.
  const double phi = std::atan(mu), alpha_c = phi + std::asin(hold / std::sqrt(1 + mu * mu));
  std::printf("%dD bonded block: mu = %.2f, n C A / W = %.5f, predicted threshold tan a = %.5f\n", dim, mu, hold,
              std::tan(alpha_c));
  for (double f : {0.5, 0.9, 0.98, 1.02, 1.3}) {
    const double tan_a = f * std::tan(alpha_c), a = std::atan(tan_a);
    const bool holds = f < 1;
    const double expected = holds ? 0.0 : g * (std::sin(a) - mu * std::cos(a));
    const InclineResult got = bonded_block(dim, a, mu, cohesion, area);
    std::printf("  tan a = %.4f (%.2f of the threshold): a = %.9f, expected %.9f; intact bonds %g\n", tan_a, f,
                got.acceleration, expected, got.intact_bonds);
    EXPECT_NEAR(got.acceleration, expected, 1e-6 * g) << "tan a = " << tan_a;
    EXPECT_EQ(got.intact_bonds, holds ? points : 0) << "tan a = " << tan_a;
  }
}

/// A chain of n + 1 bonded disks / spheres of radius 0.05 hanging from the fixed top one;
/// the bottom one pulled down by rate·t. Returns the output.
SceneRun pulled_chain(int dim, int n, double rate, double sigma_t, double area) {
  std::ostringstream s;
  s.precision(17);
  const char* shape = dim == 2 ? "disk" : "sphere";
  auto vec = [&](double y) {
    std::ostringstream v;
    v.precision(17);
    v << (dim == 2 ? "[0, " : "[0, 0, ") << y << "]";
    return v.str();
  };
  s << R"({"format": "moreau-scene/1", "dimension": )" << dim << R"(, "time": {"step": 1e-3, "duration": 0.3},
  "gravity": )" << vec(-g) << R"(, "materials": {"m": {"density": 1000}},
  "laws": {"glued": {"type": "cohesive", "friction": 0.5, "cohesion": )" << sigma_t * 0.5 << R"(, "tensile_strength": )"
    << sigma_t << R"(, "area": )" << area << R"(}},
  "interactions": [{"groups": ["bead", "bead"], "law": "glued"}],
  "forces": [{"type": "constant", "body": "b)" << n << R"(", "rate": )" << vec(-rate) << R"(}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 2000}, "output": {"every": 1}, "bodies": [)";
  for (int i = 0; i <= n; ++i) {
    if (i) s << ", ";
    s << R"({"name": "b)" << i << R"(", )" << (i == 0 ? R"("fixed": true, )" : R"("material": "m", )") << R"("position": )"
      << vec(-0.1 * i) << R"(, "contactors": [{"shape": ")" << shape << R"(", "radius": 0.05, "group": "bead"}]})";
  }
  s << "]}";
  return run_scene(dim == 2 ? "pulled_chain_2d" : "pulled_chain_3d", s.str());
}

void check_chain(int dim) {
  const int n = 5;
  // Strength 1000 N (2D, per metre) / 100 N (3D), reached after about 200 steps.
  const double rate = dim == 2 ? 3000 : 400, sigma_t = dim == 2 ? 1e5 : 1e6, area = dim == 2 ? 0.01 : 1e-4;
  const double m = dim == 2 ? 1000 * M_PI * 0.05 * 0.05 : 1000 * 4.0 / 3 * M_PI * 0.05 * 0.05 * 0.05;
  const double strength = sigma_t * area, h = 1e-3, theta = 0.5;
  // Load on the top bond during step k: F(t_k + θh) + n m g.
  auto load = [&](long k) { return rate * (static_cast<double>(k) + theta) * h + n * m * g; };
  long predicted = 0;
  while (load(predicted) < strength) ++predicted;
  SceneRun run = pulled_chain(dim, n, rate, sigma_t, area);
  // Frame k + 1 holds the end of step k.
  long broke = -1;
  for (std::size_t f = 1; f < run.frames.size() && broke < 0; ++f) {
    const auto bond = run.at(run.frames[f], "contacts/bond");
    const auto bodies = run.at(run.frames[f], "contacts/bodies");
    const auto force = run.at(run.frames[f], "contacts/normal_force");
    const long step = static_cast<long>(f) - 1;
    ASSERT_EQ(bond.size(), static_cast<std::size_t>(n));
    for (std::size_t c = 0; c < bond.size(); ++c) {
      if (bond[c] != 2) continue;
      broke = step;
      EXPECT_EQ(std::min(bodies[2 * c], bodies[2 * c + 1]), 0) << "the top bond breaks first (step " << step << ")";
      EXPECT_EQ(run.at(run.frames[f], "laws/broken")[0], 1.0);
      EXPECT_EQ(run.at(run.frames[f], "laws/bonds")[0], n - 1.0);
    }
    if (broke >= 0) break;
    for (std::size_t c = 0; c < bond.size(); ++c) {
      const int upper = static_cast<int>(std::min(bodies[2 * c], bodies[2 * c + 1]));
      // Intact: static tension = the load below it (normal force negative: tension).
      const double below = rate * (static_cast<double>(step) + theta) * h + (n - upper) * m * g;
      EXPECT_NEAR(-force[c], below, 1e-9 * strength) << "step " << step << ", bond below body " << upper;
    }
  }
  std::printf("%dD chain: strength %.6g N, bond at the top breaks at step %ld (predicted %ld: load %.6g N then, %.6g N "
              "the step before)\n", dim, strength, broke, predicted, load(predicted), load(predicted - 1));
  EXPECT_EQ(broke, predicted);
}

}  // namespace

TEST(Cohesion, BondedPolygonHoldsOnAnInclineUpToTheCohesionAngleThenSlides) { sweep_bonded_incline(2); }
TEST(Cohesion, BondedBoxHoldsOnAnInclineUpToTheCohesionAngleThenSlides) { sweep_bonded_incline(3); }
TEST(Cohesion, ChainOfBondedDisksPulledAtAConstantRateBreaksAtTheTopAtTheTensileStrength) { check_chain(2); }
TEST(Cohesion, ChainOfBondedSpheresPulledAtAConstantRateBreaksAtTheTopAtTheTensileStrength) { check_chain(3); }
