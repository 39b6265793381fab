// Blocks: a 2D polygon and a 3D box on an incline (stick for tan α ≤ μ, else slide with
// a = g (sin α − μ cos α)), a box resting on a plane (4 contacts carrying the weight, no
// drift), and columns of boxes and disks that stand.
//
// Tolerances. A constant acceleration is integrated exactly by θ = 0.5 and the solver runs
// to 1e-12, so accelerations are compared at 1e-6 g and force sums at 1e-6 W (rounding and
// the solver tolerance only). Drift: a resting body must not move at all beyond rounding,
// 1e-6 m over 10⁴ steps is the issue's bound.
#include <cmath>
#include <sstream>

#include "incline_scene.hpp"
#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double g = 9.81;

/// Downhill acceleration of a block resting on an incline of angle alpha.
double block_acceleration(int dim, double alpha, double mu) {
  std::ostringstream law;
  law.precision(17);
  law << R"({"type": "coulomb", "friction": )" << mu << "}";
  const SceneRun run = run_block_on_incline(dim == 2 ? "block_incline_2d" : "block_incline_3d", dim, alpha, law.str());
  return (downhill_speed(run, run.frames[5], dim, alpha) - downhill_speed(run, run.frames[1], dim, alpha)) / 0.4;
}

void sweep_incline(int dim) {
  const double mu = 0.3;
  for (double tan_a : {0.15, 0.28, 0.32, 0.6}) {
    const double a = std::atan(tan_a);
    const bool sticks = tan_a <= mu;
    const double expected = sticks ? 0.0 : g * (std::sin(a) - mu * std::cos(a));
    const double got = block_acceleration(dim, a, mu);
    std::printf("%dD block, tan a = %.2f (mu = %.2f): a = %.9f, expected %.9f (%s)\n", dim, tan_a, mu, got, expected,
                sticks ? "sticking" : "sliding");
    EXPECT_NEAR(got, expected, 1e-6 * g) << "tan a = " << tan_a;
  }
}

}  // namespace

TEST(Blocks, PolygonOnInclineSticksBelowMuAndSlidesAbove) { sweep_incline(2); }
TEST(Blocks, BoxOnInclineSticksBelowMuAndSlidesAbove) { sweep_incline(3); }

TEST(Blocks, BoxRestingOnAPlaneHasFourContactsCarryingItsWeightAndDoesNotDrift) {
  // 0.4 × 0.3 × 0.2 box, density 1000: W = 24 kg · g. 10⁴ steps.
  SceneRun run = run_scene("box_on_plane", R"({"format": "moreau-scene/1", "dimension": 3,
  "time": {"step": 1e-3, "duration": 10}, "gravity": [0, 0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.5}},
  "interactions": [{"groups": ["box", "floor"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 1000}, "output": {"every": 1000},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "normal": [0, 0, 1], "group": "floor"}]},
             {"name": "box", "material": "m", "position": [0.3, -0.2, 0.1], "orientation": [0.9238795325112867, 0, 0, 0.3826834323650898],
              "contactors": [{"shape": "box", "size": [0.4, 0.3, 0.2], "group": "box"}]}]})");
  const double W = 24 * g;
  const auto x0 = run.at(run.frames.front(), "position");
  double worst = 0;
  for (const auto& f : run.frames) {
    if (f == run.frames.front()) continue;
    const auto force = run.at(f, "contacts/force");
    ASSERT_EQ(force.size(), 4u * 3) << "frame " << f << ": a box face on a plane has 4 contacts";
    double fz = 0;
    for (int c = 0; c < 4; ++c) fz += force[3 * c + 2];
    EXPECT_NEAR(fz, W, 1e-6 * W) << "frame " << f;
    const auto x = run.at(f, "position");
    for (int k = 3; k < 6; ++k) worst = std::max(worst, std::fabs(x[k] - x0[k]));
  }
  std::printf("box on plane: drift after 1e4 steps %.3e m\n", worst);
  EXPECT_LT(worst, 1e-6);
}

namespace {

double final_kinetic_energy(const SceneRun& run, int dim, double mass, double inertia) {
  const auto& f = run.frames.back();
  const auto v = run.at(f, "velocity");
  const auto w = run.at(f, "angular_velocity");
  double e = 0;
  for (double x : v) e += 0.5 * mass * x * x;
  for (double x : w) e += 0.5 * inertia * x * x;  // fixed floor bodies have zero velocity
  (void)dim;
  return e;
}

}  // namespace

TEST(Blocks, ColumnOfTenBoxesStands) {
  std::ostringstream s;
  s << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 1e-3, "duration": 10},
  "gravity": [0, 0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.5}},
  "interactions": [{"groups": ["box", "floor"], "law": "rough"}, {"groups": ["box", "box"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-8, "max_iterations": 2000}, "output": {"every": 1000},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "normal": [0, 0, 1], "group": "floor"}]})";
  for (int i = 0; i < 10; ++i)
    s << R"(, {"name": "b)" << i << R"(", "material": "m", "position": [0, 0, )" << 0.05 + 0.1 * i
      << R"(], "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "box"}]})";
  s << "]}";
  SceneRun run = run_scene("column_boxes", s.str());
  // m = 4 kg each; the largest principal inertia bounds the rotational energy.
  const double ke = final_kinetic_energy(run, 3, 4.0, 4.0 * (0.04 + 0.04) / 12);
  const auto x = run.at(run.frames.back(), "position");
  double drift = 0;
  for (int i = 0; i < 10; ++i) drift = std::max({drift, std::fabs(x[3 * (i + 1)]), std::fabs(x[3 * (i + 1) + 1]),
                                                  std::fabs(x[3 * (i + 1) + 2] - (0.05 + 0.1 * i))});
  std::printf("10 boxes: kinetic energy at 10 s %.3e J, largest displacement %.3e m\n", ke, drift);
  EXPECT_LT(ke, 1e-8);
  EXPECT_LT(drift, 1e-4);
}

TEST(Blocks, ColumnOfTwentyDisksStands) {
  std::ostringstream s;
  s << R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 1e-3, "duration": 10},
  "gravity": [0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.5}},
  "interactions": [{"groups": ["disk", "floor"], "law": "rough"}, {"groups": ["disk", "disk"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-8, "max_iterations": 5000}, "output": {"every": 1000},
  "bodies": [{"name": "floor", "fixed": true, "position": [0, 0], "contactors": [{"shape": "polygon", "vertices": [[-1, -0.1], [1, -0.1], [1, 0], [-1, 0]], "group": "floor"}]})";
  for (int i = 0; i < 20; ++i)
    s << R"(, {"name": "d)" << i << R"(", "material": "m", "position": [0, )" << 0.05 + 0.1 * i
      << R"(], "contactors": [{"shape": "disk", "radius": 0.05, "group": "disk"}]})";
  s << "]}";
  SceneRun run = run_scene("column_disks", s.str());
  const double m = 1000 * M_PI * 0.05 * 0.05;
  const double ke = final_kinetic_energy(run, 2, m, m * 0.05 * 0.05 / 2);
  std::printf("20 disks: kinetic energy at 10 s %.3e J\n", ke);
  EXPECT_LT(ke, 1e-8);
}
