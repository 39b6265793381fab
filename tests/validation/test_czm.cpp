// Cohesive zone with damage (`czm`, the bilinear MAL_CZM type; docs/laws.md): a block
// glued on a fixed one, moved by imposed velocities, so the interface opening δ is the
// block's displacement (every velocity component imposed: W = 0 and the contact problem
// is the interface law alone).
//
// Pure mode I (opening) and pure mode II (shear), each loaded past the peak, unloaded,
// reloaded to rupture. Checked at every step against the law written out here:
//  - the force follows T = A k (1 − D) δ, D from the largest opening reached (bilinear:
//    D = λ_f (λ − 1) / (λ (λ_f − 1)), λ = δ/δ_0, λ_f = δ_f/δ_0), to 1e-9 of the peak:
//    the step is solved until damage and opening agree (the fixed point converges in two
//    solves here: δ does not depend on D) and the solver runs to 1e-12;
//  - damage never decreases; unloading follows the damaged stiffness (the same formula
//    with D frozen);
//  - the work of the interface force over the whole path, ∫ T dδ by trapezoids over the
//    steps, equals G_c × area once broken: exact on the linear pieces, off only on the
//    steps holding a kink (peak, rupture, turns), by at most k A Δδ² each: with Δδ = 1e-6 m
//    that is 2e-3 J against G_c A = 40 J, so 1e-4 relative.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double k = 1e10, strength = 1e6, G = 200;   // Pa/m, Pa, J/m²: δ_0 = 1e-4 m, δ_f = 4e-4 m
constexpr double v = 1e-3, h = 1e-3;                  // m/s, s: 1e-6 m a step

/// Traction per unit area of the bilinear law at opening δ ≥ 0 with largest opening κ.
double traction(double delta, double kappa) {
  const double d0 = strength / k, lf = 2 * G * k / (strength * strength);
  const double lambda = std::max(kappa, delta) / d0;
  double D = 0;
  if (lambda >= lf) D = 1;
  else if (lambda > 1) D = lf * (lambda - 1) / (lambda * (lf - 1));
  return k * (1 - D) * delta;
}

struct Phase {
  double duration, sign;
};

/// Runs a 2D (two points of area 0.1 m) or 3D (four of 0.01 m²) glued block moved along
/// `axis` (1: normal, 0: tangential) by the phases; checks the law and returns the work.
void check_mode(int dim, int axis, const std::vector<Phase>& phases) {
  std::ostringstream s;
  s.precision(17);
  const double area = dim == 2 ? 0.1 : 0.01;
  const int points = dim == 2 ? 2 : 4;
  const int up = dim - 1;  // the normal axis (y in 2D, z in 3D)
  const int moved = axis == 1 ? up : 0;
  double t = 0;
  std::ostringstream drivers;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    std::ostringstream vel;
    vel.precision(17);
    vel << "[";
    for (int c = 0; c < dim; ++c) vel << (c ? ", " : "") << (c == moved ? phases[i].sign * v : 0.0);
    vel << "]";
    drivers << (i ? ", " : "") << R"({"body": "top", "velocity": )" << vel.str() << R"(, "angular_velocity": )"
            << (dim == 2 ? "0" : "[0, 0, 0]") << R"(, "start": )" << t << R"(, "end": )" << t + phases[i].duration << "}";
    t += phases[i].duration;
  }
  s << R"({"format": "moreau-scene/1", "dimension": )" << dim << R"(, "time": {"step": 1e-3, "duration": )" << t << R"(},
  "gravity": )" << (dim == 2 ? "[0, 0]" : "[0, 0, 0]") << R"(, "materials": {"m": {"density": 1000}},
  "laws": {"glue": {"type": "czm", "normal_stiffness": 1e10, "tangential_stiffness": 1e10, "normal_strength": 1e6,
    "shear_strength": 1e6, "mode_I_energy": 200, "mode_II_energy": 200, "area": )" << area << R"(, "friction": 0.5}},
  "interactions": [{"groups": ["top", "bottom"], "law": "glue"}], "detection": {"alert": 1e-3},
  "drivers": [)" << drivers.str() << R"(],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 500}, "output": {"every": 1}, "bodies": [)";
  if (dim == 2)
    s << R"({"name": "bottom", "fixed": true, "position": [0, -0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "bottom"}]},
      {"name": "top", "material": "m", "position": [0, 0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "top"}]}]})";
  else
    s << R"({"name": "bottom", "fixed": true, "position": [0, 0, -0.05], "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "bottom"}]},
      {"name": "top", "material": "m", "position": [0, 0, 0.05], "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "top"}]}]})";
  SceneRun run = run_scene("czm_" + std::to_string(dim) + "d_mode_" + (axis == 1 ? "I" : "II"), s.str());

  const double x0 = run.at(run.frames.front(), "position")[dim + moved];
  const double peak = strength * area * points;
  double kappa = 0, work = 0, last_delta = 0, last_force = 0, worst = 0;
  std::vector<double> last_damage(points, 0.0);
  bool broken = false;
  for (std::size_t f = 1; f < run.frames.size(); ++f) {
    const std::string& fr = run.frames[f];
    const double delta = run.at(fr, "position")[dim + moved] - x0;
    const auto damage = run.at(fr, "contacts/damage");
    const auto impulse = run.at(fr, "contacts/impulse");
    ASSERT_EQ(damage.size(), static_cast<std::size_t>(points)) << "frame " << fr;
    // The force on the top block along the motion, opposing it: −Σ r/h along the axis.
    double force = 0;
    if (axis == 1) {
      for (int c = 0; c < points; ++c) force -= impulse[dim * c] / h;  // tension: r_n < 0
    } else {
      const auto frc = run.at(fr, "contacts/force");
      const auto bodies = run.at(fr, "contacts/bodies");
      for (int c = 0; c < points; ++c) force -= (bodies[2 * c] == 1 ? 1 : -1) * frc[dim * c];  // x component, on the top block
    }
    kappa = std::max(kappa, delta);
    const double expected = points * area * traction(delta, kappa);
    worst = std::max(worst, std::fabs(force - expected));
    EXPECT_NEAR(force, expected, 1e-9 * peak) << "frame " << fr << ", opening " << delta;
    for (int c = 0; c < points; ++c) {
      EXPECT_GE(damage[c], last_damage[c]) << "frame " << fr << ": damage decreased";
      last_damage[c] = damage[c];
    }
    work += 0.5 * (force + last_force) * (delta - last_delta);
    last_delta = delta;
    last_force = force;
    broken = damage[0] == 1;
  }
  const double expected_work = G * area * points;
  std::printf("%dD mode %s: worst |T - law| = %.3e N (peak %.3g N); work of the interface %.9g J, G_c x area %.9g J "
              "(relative %.2e); broken %d\n", dim, axis == 1 ? "I" : "II", worst, peak, work, expected_work,
              work / expected_work - 1, broken);
  EXPECT_TRUE(broken);
  EXPECT_NEAR(work, expected_work, 1e-4 * expected_work);
}

}  // namespace

// Load to δ = 2δ_0 (D = 2/3), unload to δ_0/2, reload to rupture at δ_f = 4δ_0 and beyond.
const std::vector<Phase> path = {{0.2, 1}, {0.15, -1}, {0.4, 1}};

TEST(CohesiveZone, ModeIFollowsTheLawDissipatesGcTimesAreaAndUnloadsAlongTheDamagedStiffness) { check_mode(2, 1, path); }
TEST(CohesiveZone, ModeIIFollowsTheLawDissipatesGcTimesAreaAndUnloadsAlongTheDamagedStiffness) { check_mode(2, 0, path); }
TEST(CohesiveZone, ModeIBetweenBoxesFollowsTheLaw) { check_mode(3, 1, path); }
