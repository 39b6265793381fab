// Elastic repulsion (`elastic`, LMGC90's ELASTIC_REPELL_CLB; docs/laws.md): a disk of mass
// m thrown at v0 onto a fixed slab whose contact has stiffness k, no gravity. A linear
// spring: the contact lasts half a period, T = π √(m/k), and (undamped) the disk leaves
// at v0. The law puts the force on the overlap at the end of each step,
// r_n/h = k max(0, −(g + θh u_n)), g the gap at the detection configuration
// q⁻ + (1−θ)h v⁻, which for θ = 1/2 is the scheme
//     v⁺ (1 + θh²k/m) = v⁻ − (hk/m) g,      q⁺ = g + θh v⁺,
// a slightly dissipative one: the force k x(t + θh) ≈ k x + kθh ẋ is the spring plus a
// damper c = kθh, damping ratio ζ = θωh/2, so the disk leaves at v0 exp(−πζ) (ω = √(k/m)).
// Checked:
//  - every step in contact follows that recurrence (to 1e-9 of v0: the solver's tolerance);
//  - the contact lasts T to within 2h (the first and last steps of contact are partial);
//  - the rebound speed is v0 exp(−πθωh/2) (0.97563 v0 for ωh = π/100) to (ωh)², the next
//    order of the expansion.
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double r = 0.05, v0 = 1.0, h = 1e-4, theta = 0.5, T = 0.01;

}  // namespace

TEST(Elastic, DiskBouncesOffASpringForHalfAPeriod) {
  const double m = 1000 * M_PI * r * r, k = m * (M_PI / T) * (M_PI / T), gap0 = 2e-4;
  std::ostringstream s;
  s.precision(17);
  s << R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": )" << h << R"(, "duration": 0.02}, "gravity": [0, 0],
  "materials": {"m": {"density": 1000}}, "laws": {"spring": {"type": "elastic", "stiffness": )" << k << R"(}},
  "interactions": [{"groups": ["disk", "slab"], "law": "spring"}], "detection": {"alert": 5e-3},
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 100}, "output": {"every": 1}, "bodies": [
    {"name": "slab", "fixed": true, "position": [0, -0.1], "contactors": [{"shape": "polygon", "vertices": [[-1, -0.1], [1, -0.1], [1, 0.1], [-1, 0.1]], "group": "slab"}]},
    {"name": "disk", "material": "m", "position": [0, )" << r + gap0 << R"(], "velocity": [0, )" << -v0
    << R"(], "contactors": [{"shape": "disk", "radius": )" << r << R"(, "group": "disk"}]}]})";
  SceneRun run = run_scene("elastic_bounce", s.str());
  auto height = [&](std::size_t f) { return run.at(run.frames[f], "position")[3] - r; };  // the disk's gap to the slab
  auto speed = [&](std::size_t f) { return run.at(run.frames[f], "velocity")[3]; };
  long first = -1, last = -1;
  for (std::size_t f = 1; f < run.frames.size(); ++f) {
    const auto force = run.at(run.frames[f], "contacts/normal_force");
    const bool pushing = !force.empty() && force[0] > 0;
    if (!pushing) continue;
    if (first < 0) first = static_cast<long>(f) - 1;
    last = static_cast<long>(f) - 1;
    // The step from frame f − 1: the recurrence from its start.
    const double v_begin = speed(f - 1), g = height(f - 1) + (1 - theta) * h * v_begin;
    const double v_end = (v_begin - h * k / m * g) / (1 + theta * h * h * k / m);
    EXPECT_NEAR(speed(f), v_end, 1e-9 * v0) << "step " << f - 1;
    EXPECT_NEAR(height(f), g + theta * h * v_end, 1e-9 * v0 * h) << "step " << f - 1;
  }
  ASSERT_GE(first, 0) << "the disk never touched";
  const double duration = static_cast<double>(last - first + 1) * h, rebound = speed(run.frames.size() - 1) / v0;
  const double omega_h = M_PI / T * h;
  const double expected = std::exp(-M_PI * theta * omega_h / 2);
  std::printf("elastic bounce: contact for %.5f s (pi sqrt(m/k) = %.5f s, h = %g), rebound %.6f v0 (exp(-pi theta omega h / 2) = "
              "%.6f)\n", duration, T, h, rebound, expected);
  EXPECT_NEAR(duration, T, 2 * h);
  EXPECT_NEAR(rebound, expected, omega_h * omega_h);
}
