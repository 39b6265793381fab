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

/// A block glued on a fixed one (2D: two points of area 0.1 m; 3D: four of 0.01 m²) by a
/// czm of G_Ic = G and G_IIc = `mode_II_energy`, moved by `drivers` for `duration`.
std::string glued_blocks(int dim, double duration, const std::string& drivers, double mode_II_energy) {
  const double area = dim == 2 ? 0.1 : 0.01;
  std::ostringstream s;
  s.precision(17);
  s << R"({"format": "moreau-scene/1", "dimension": )" << dim << R"(, "time": {"step": 1e-3, "duration": )" << duration << R"(},
  "gravity": )" << (dim == 2 ? "[0, 0]" : "[0, 0, 0]") << R"(, "materials": {"m": {"density": 1000}},
  "laws": {"glue": {"type": "czm", "normal_stiffness": 1e10, "tangential_stiffness": 1e10, "normal_strength": 1e6,
    "shear_strength": 1e6, "mode_I_energy": )" << G << R"(, "mode_II_energy": )" << mode_II_energy << R"(, "area": )" << area
    << R"(, "friction": 0.5}},
  "interactions": [{"groups": ["top", "bottom"], "law": "glue"}], "detection": {"alert": 1e-3},
  "drivers": [)" << drivers << R"(],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 500}, "output": {"every": 1}, "bodies": [)";
  if (dim == 2)
    s << R"({"name": "bottom", "fixed": true, "position": [0, -0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "bottom"}]},
      {"name": "top", "material": "m", "position": [0, 0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "top"}]}]})";
  else
    s << R"({"name": "bottom", "fixed": true, "position": [0, 0, -0.05], "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "bottom"}]},
      {"name": "top", "material": "m", "position": [0, 0, 0.05], "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "top"}]}]})";
  return s.str();
}

/// Runs a 2D (two points of area 0.1 m) or 3D (four of 0.01 m²) glued block moved along
/// `axis` (1: normal, 0: tangential) by the phases; checks the law and returns the work.
void check_mode(int dim, int axis, const std::vector<Phase>& phases) {
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
  SceneRun run = run_scene("czm_" + std::to_string(dim) + "d_mode_" + (axis == 1 ? "I" : "II"), glued_blocks(dim, t, drivers.str(), G));

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

/// Mixed mode (2D): the block pulled at 45° between the normal and the tangent, G_IIc = 2
/// G_Ic. With k_n = k_t and σ_max = τ_max the traction stays along the opening, the
/// normalised opening's direction is a_n² = a_t² = 1/2, and the linear rule gives
/// 1/λ_f = a_n²/λ_fn + a_t²/λ_ft (λ_fn = 2 G_Ic k/σ² = 4, λ_ft = 8: λ_f = 16/3): the
/// interface dissipates ½ σ δ_0 λ_f = 266.67 J/m², half in each mode, so that
/// G_I/G_Ic + G_II/G_IIc = 1. Work by trapezoids as above (two kinks: 1e-4 relative).
void check_mixed_mode() {
  const double area = 0.1, GII = 2 * G, c = std::sqrt(0.5);
  std::ostringstream drivers;
  drivers.precision(17);
  drivers << R"({"body": "top", "velocity": [)" << c * v << ", " << c * v << R"(], "angular_velocity": 0})";
  SceneRun run = run_scene("czm_2d_mixed_mode", glued_blocks(2, 0.6, drivers.str(), GII));
  const auto p0 = run.at(run.frames.front(), "position");
  double work_I = 0, work_II = 0, last[2] = {0, 0}, last_force[2] = {0, 0};
  bool broken = false;
  for (std::size_t f = 1; f < run.frames.size(); ++f) {
    const std::string& fr = run.frames[f];
    const auto p = run.at(fr, "position");
    const double delta[2] = {p[2] - p0[2], p[3] - p0[3]};  // tangential (x), normal (y)
    const auto frc = run.at(fr, "contacts/force");
    const auto bodies = run.at(fr, "contacts/bodies");
    double force[2] = {0, 0};  // opposing the motion, on the top block
    for (std::size_t k = 0; k < bodies.size() / 2; ++k)
      for (int i = 0; i < 2; ++i) force[i] -= (bodies[2 * k] == 1 ? 1 : -1) * frc[2 * k + i];
    work_II += 0.5 * (force[0] + last_force[0]) * (delta[0] - last[0]);
    work_I += 0.5 * (force[1] + last_force[1]) * (delta[1] - last[1]);
    for (int i = 0; i < 2; ++i) last[i] = delta[i], last_force[i] = force[i];
    const auto damage = run.at(fr, "contacts/damage");
    broken = !damage.empty() && damage[0] == 1;
  }
  const double d0 = strength / k, lf = 1 / (0.5 / (2 * G * k / (strength * strength)) + 0.5 / (2 * GII * k / (strength * strength)));
  const double expected = 0.5 * strength * d0 * lf * area * 2;  // two points
  const double rule = work_I / (G * area * 2) + work_II / (GII * area * 2);
  std::printf("2D mixed mode (45 deg, G_IIc = 2 G_Ic): work %.9g J (expected %.9g J, relative %.2e), mode I %.6g J, mode II "
              "%.6g J, G_I/G_Ic + G_II/G_IIc = %.9f; broken %d\n", work_I + work_II, expected,
              (work_I + work_II) / expected - 1, work_I, work_II, rule, broken);
  EXPECT_TRUE(broken);
  EXPECT_NEAR(work_I + work_II, expected, 1e-4 * expected);
  EXPECT_NEAR(rule, 1.0, 1e-4);
}

}  // namespace

// Load to δ = 2δ_0 (D = 2/3), unload to δ_0/2, reload to rupture at δ_f = 4δ_0 and beyond.
const std::vector<Phase> path = {{0.2, 1}, {0.15, -1}, {0.4, 1}};

TEST(CohesiveZone, ModeIFollowsTheLawDissipatesGcTimesAreaAndUnloadsAlongTheDamagedStiffness) { check_mode(2, 1, path); }
TEST(CohesiveZone, ModeIIFollowsTheLawDissipatesGcTimesAreaAndUnloadsAlongTheDamagedStiffness) { check_mode(2, 0, path); }
TEST(CohesiveZone, ModeIBetweenBoxesFollowsTheLaw) { check_mode(3, 1, path); }
TEST(CohesiveZone, MixedModeFollowsTheLinearEnergyRule) { check_mixed_mode(); }
TEST(CohesiveZone, ModeIIBetweenBoxesKeepsItsBondsAsTheFacesShear) { check_mode(3, 0, path); }
