// Static frictionless stacks, forces read from the output file (contacts/force = impulse/h)
// and compared with statics. The solver runs to 1e-10, the stack is at rest: forces match
// to 1e-6 of the weight.
#include <cmath>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

/// Sum of the force vectors of the contacts between bodies a and b (either order, the
/// sign making it the force on a).
std::vector<double> force_on(const SceneRun& run, const std::string& frame, int a, int b, int dim) {
  const auto bodies = run.at(frame, "contacts/bodies");
  const auto force = run.at(frame, "contacts/force");
  std::vector<double> f(dim, 0.0);
  for (std::size_t c = 0; c < bodies.size() / 2; ++c) {
    const int x = static_cast<int>(bodies[2 * c]), y = static_cast<int>(bodies[2 * c + 1]);
    const double s = (x == a && y == b) ? 1.0 : (x == b && y == a) ? -1.0 : 0.0;
    for (int k = 0; k < dim; ++k) f[k] += s * force[c * dim + k];
  }
  return f;
}

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

}  // namespace

TEST(Stacks, ThreeEqualDisksInABox) {
  // Bottom disks rest against the walls with a small gap between them; statics for the
  // actual geometry: sin φ = (w/2 − R)/(2R), top–bottom F = W/(2 cos φ), wall F sin φ,
  // floor 1.5 W.
  const double R = 0.1, w = 4 * R + 0.002, g = 9.81, rho = 1000;
  const double m = rho * M_PI * R * R, W = m * g;
  char scene[2600];
  const double xb = w / 2 - R, sphi = xb / (2 * R), cphi = std::sqrt(1 - sphi * sphi);
  std::snprintf(scene, sizeof scene, R"({
  "format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 1e-3, "duration": 1.0},
  "gravity": [0, -9.81],
  "materials": {"m": {"density": %g}},
  "laws": {"smooth": {"type": "coulomb", "friction": 0.0}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, -0.01], "contactors": [{"shape": "segment", "length": 1, "thickness": 0.02, "group": "wall"}]},
    {"name": "left", "fixed": true, "position": [%.17g, 0.5], "angle": 1.5707963267948966, "contactors": [{"shape": "segment", "length": 1, "thickness": 0.02, "group": "wall"}]},
    {"name": "right", "fixed": true, "position": [%.17g, 0.5], "angle": 1.5707963267948966, "contactors": [{"shape": "segment", "length": 1, "thickness": 0.02, "group": "wall"}]},
    {"name": "b1", "material": "m", "position": [%.17g, %.17g], "contactors": [{"shape": "disk", "radius": %g, "group": "disk"}]},
    {"name": "b2", "material": "m", "position": [%.17g, %.17g], "contactors": [{"shape": "disk", "radius": %g, "group": "disk"}]},
    {"name": "top", "material": "m", "position": [0, %.17g], "contactors": [{"shape": "disk", "radius": %g, "group": "disk"}]}
  ],
  "interactions": [{"groups": ["disk", "disk"], "law": "smooth"}, {"groups": ["disk", "wall"], "law": "smooth"}],
  "solver": {"type": "nlgs", "tolerance": 1e-10, "max_iterations": 5000},
  "output": {"every": 100}
})", rho, -w / 2 - 0.01, w / 2 + 0.01, -xb, R, R, xb, R, R, R + 2 * R * cphi, R);
  SceneRun run = run_scene("three_disks", scene);
  const std::string last = run.frames.back();
  const double F = W / (2 * cphi);
  const auto tb1 = force_on(run, last, 5, 3, 2), tb2 = force_on(run, last, 5, 4, 2);
  const auto w1 = force_on(run, last, 3, 1, 2), w2 = force_on(run, last, 4, 2, 2);
  const auto f1 = force_on(run, last, 3, 0, 2), f2 = force_on(run, last, 4, 0, 2);
  std::printf("W = %.6f N: top-bottom %.6f %.6f (W/(2cos phi) = %.6f), walls %.6f %.6f (%.6f), floor %.6f %.6f (%.6f)\n", W,
              norm(tb1), norm(tb2), F, norm(w1), norm(w2), F * sphi, norm(f1), norm(f2), 1.5 * W);
  const double tol = 1e-6 * W;
  EXPECT_NEAR(norm(tb1), F, tol);
  EXPECT_NEAR(norm(tb2), F, tol);
  EXPECT_NEAR(norm(w1), F * sphi, tol);
  EXPECT_NEAR(norm(w2), F * sphi, tol);
  EXPECT_NEAR(norm(f1), 1.5 * W, tol);
  EXPECT_NEAR(norm(f2), 1.5 * W, tol);
  // With w → 4R these are W/√3, W/(2√3), 1.5 W.
  EXPECT_NEAR(F, W / std::sqrt(3.0), 2e-3 * W);
}

TEST(Stacks, SphereOnThreeTouchingSpheres) {
  // The three bottom spheres are fixed and touch; each contact carries W/√6.
  const double R = 0.05, rho = 1000, g = 9.81;
  const double W = rho * 4.0 / 3.0 * M_PI * R * R * R * g;
  const double c = 2 * R / std::sqrt(3.0), z = R + 2 * R * std::sqrt(2.0 / 3.0);
  char scene[2400];
  std::snprintf(scene, sizeof scene, R"({
  "format": "moreau-scene/1", "dimension": 3,
  "time": {"step": 1e-3, "duration": 0.3},
  "gravity": [0, 0, -9.81],
  "materials": {"m": {"density": %g}},
  "laws": {"smooth": {"type": "coulomb", "friction": 0.0}},
  "bodies": [
    {"name": "a", "fixed": true, "position": [%.17g, 0, %g], "contactors": [{"shape": "sphere", "radius": %g, "group": "s"}]},
    {"name": "b", "fixed": true, "position": [%.17g, %.17g, %g], "contactors": [{"shape": "sphere", "radius": %g, "group": "s"}]},
    {"name": "c", "fixed": true, "position": [%.17g, %.17g, %g], "contactors": [{"shape": "sphere", "radius": %g, "group": "s"}]},
    {"name": "top", "material": "m", "position": [0, 0, %.17g], "contactors": [{"shape": "sphere", "radius": %g, "group": "s"}]}
  ],
  "interactions": [{"groups": ["s", "s"], "law": "smooth"}],
  "solver": {"type": "nlgs", "tolerance": 1e-10, "max_iterations": 5000},
  "output": {"every": 100}
})", rho, c, R, R, -c / 2, c * std::sqrt(3.0) / 2, R, R, -c / 2, -c * std::sqrt(3.0) / 2, R, R, z, R);
  SceneRun run = run_scene("four_spheres", scene);
  const std::string last = run.frames.back();
  for (int b = 0; b < 3; ++b) {
    const double f = norm(force_on(run, last, 3, b, 3));
    std::printf("contact top-%d: %.8f N, W/sqrt(6) = %.8f N\n", b, f, W / std::sqrt(6.0));
    EXPECT_NEAR(f, W / std::sqrt(6.0), 1e-6 * W);
  }
}
