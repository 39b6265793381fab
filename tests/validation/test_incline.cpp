// A disk (2D) or a sphere (3D) on an incline of angle α with friction μ: it rolls
// without slipping while tan α ≤ 3μ (disk) / 3.5μ (sphere), with a = (2/3) g sin α /
// (5/7) g sin α, and slips above, with a = g (sin α − μ cos α). The acceleration is
// measured from the velocity along the slope between two times once the contact is
// established; a constant acceleration is integrated exactly by θ = 0.5, so the
// tolerance is the solver's (1e-10 relative) plus rounding: 1e-6 relative.
#include <cmath>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

double measured_acceleration_2d(double alpha, double mu) {
  const double R = 0.1, g = 9.81;
  // Incline: a long segment rotated by -alpha through the origin; the disk touches it.
  const double nx = std::sin(alpha), ny = std::cos(alpha);  // incline normal (pointing up-left for -alpha)
  char scene[1800];
  std::snprintf(scene, sizeof scene, R"({
  "format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 1e-3, "duration": 0.5},
  "gravity": [0, -9.81],
  "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": %g}},
  "bodies": [
    {"name": "slope", "fixed": true, "position": [0, 0], "angle": %.17g, "contactors": [{"shape": "segment", "length": 20, "thickness": 0.02, "group": "slope"}]},
    {"name": "disk", "material": "m", "position": [%.17g, %.17g], "contactors": [{"shape": "disk", "radius": %g, "group": "disk"}]}
  ],
  "interactions": [{"groups": ["disk", "slope"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 200},
  "output": {"every": 100}
})", mu, -alpha, nx * (R + 0.01), ny * (R + 0.01), R);
  SceneRun run = run_scene("incline2d", scene);
  auto speed = [&](const std::string& f) {
    const auto v = run.at(f, "velocity");
    return v[2] * std::cos(alpha) - v[3] * std::sin(alpha);  // along the slope, downhill
  };
  // frames 0, 100, ..., 500 (t = 0.1 s apart)
  return (speed(run.frames[5]) - speed(run.frames[1])) / 0.4;
}

double measured_acceleration_3d(double alpha, double mu) {
  const double R = 0.1;
  const double nx = std::sin(alpha), nz = std::cos(alpha);  // plane normal tilted in x
  char scene[1800];
  std::snprintf(scene, sizeof scene, R"({
  "format": "moreau-scene/1", "dimension": 3,
  "time": {"step": 1e-3, "duration": 0.5},
  "gravity": [0, 0, -9.81],
  "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": %g}},
  "bodies": [
    {"name": "slope", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "normal": [%.17g, 0, %.17g], "group": "slope"}]},
    {"name": "ball", "material": "m", "position": [%.17g, 0, %.17g], "contactors": [{"shape": "sphere", "radius": %g, "group": "ball"}]}
  ],
  "interactions": [{"groups": ["ball", "slope"], "law": "rough"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 200},
  "output": {"every": 100}
})", mu, nx, nz, nx * R, nz * R, R);
  SceneRun run = run_scene("incline3d", scene);
  auto speed = [&](const std::string& f) {
    const auto v = run.at(f, "velocity");
    return v[3] * std::cos(alpha) - v[5] * std::sin(alpha);
  };
  return (speed(run.frames[5]) - speed(run.frames[1])) / 0.4;
}

}  // namespace

TEST(Incline, DiskRollsBelowThreeMuAndSlipsAbove) {
  const double g = 9.81, mu = 0.2;
  for (double tan_a : {0.3, 0.55, 0.65, 0.9}) {  // 3μ = 0.6
    const double a = std::atan(tan_a);
    const bool rolls = tan_a <= 3 * mu;
    const double expected = rolls ? 2.0 / 3.0 * g * std::sin(a) : g * (std::sin(a) - mu * std::cos(a));
    const double got = measured_acceleration_2d(a, mu);
    std::printf("disk, tan a = %.2f (3 mu = %.2f): a = %.6f, expected %.6f (%s)\n", tan_a, 3 * mu, got, expected,
                rolls ? "rolling" : "slipping");
    EXPECT_NEAR(got, expected, 1e-6 * g);
  }
}

TEST(Incline, SphereRollsBelowThreeAndAHalfMuAndSlipsAbove) {
  const double g = 9.81, mu = 0.2;
  for (double tan_a : {0.3, 0.65, 0.75, 1.0}) {  // 3.5μ = 0.7
    const double a = std::atan(tan_a);
    const bool rolls = tan_a <= 3.5 * mu;
    const double expected = rolls ? 5.0 / 7.0 * g * std::sin(a) : g * (std::sin(a) - mu * std::cos(a));
    const double got = measured_acceleration_3d(a, mu);
    std::printf("sphere, tan a = %.2f (3.5 mu = %.2f): a = %.6f, expected %.6f (%s)\n", tan_a, 3.5 * mu, got, expected,
                rolls ? "rolling" : "slipping");
    EXPECT_NEAR(got, expected, 1e-6 * g);
  }
}
