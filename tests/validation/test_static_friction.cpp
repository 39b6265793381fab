// Static and dynamic friction (`coulomb` with static_friction, LMGC90's IQS_DS_CLB;
// docs/laws.md): μ_s for a contact that was not sliding at the end of the previous step,
// μ_d for one that was. A block of weight W on a floor, pushed sideways by a constant
// force F with μ_d W < F < μ_s W:
//  - at rest, it stays put (static friction holds F);
//  - set sliding by a short imposed velocity, it keeps sliding once released, with
//    a = (F − μ_d W)/m: a constant acceleration, integrated exactly by θ = 1/2, the solver
//    at 1e-12, so 1e-6 g (as test_blocks.cpp); at rest, displacements below 1e-12 m.
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double g = 9.81;

void pushed_block(int dim) {
  const double mu_d = 0.3, mu_s = 0.5, m = dim == 2 ? 20.0 : 4.0, F = 0.4 * m * g;
  std::ostringstream s;
  s.precision(17);
  auto vec = [&](double x, double y) {
    std::ostringstream v;
    v.precision(17);
    v << "[" << x << ", " << (dim == 2 ? "" : "0, ") << y << "]";
    return v.str();
  };
  s << R"({"format": "moreau-scene/1", "dimension": )" << dim << R"(, "time": {"step": 1e-3, "duration": 0.8},
  "gravity": )" << vec(0, -g) << R"(, "materials": {"m": {"density": 1000}},
  "laws": {"rough": {"type": "coulomb", "friction": )" << mu_d << R"(, "static_friction": )" << mu_s << R"(}},
  "interactions": [{"groups": ["block", "floor"], "law": "rough"}],
  "forces": [{"type": "constant", "body": "block", "force": )" << vec(F, 0) << R"(}],
  "drivers": [{"body": "block", "velocity": )" << (dim == 2 ? "[0.2, null]" : "[0.2, 0, null]") << R"(, "start": 0.3, "end": 0.31}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 500}, "output": {"every": 50}, "bodies": [)";
  if (dim == 2)
    s << R"({"name": "floor", "fixed": true, "position": [0, -0.1], "contactors": [{"shape": "polygon", "vertices": [[-10, -0.1], [10, -0.1], [10, 0.1], [-10, 0.1]], "group": "floor"}]},
      {"name": "block", "material": "m", "position": [0, 0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "block"}]}]})";
  else
    s << R"({"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "normal": [0, 0, 1], "group": "floor"}]},
      {"name": "block", "material": "m", "position": [0, 0, 0.05], "contactors": [{"shape": "box", "size": [0.2, 0.2, 0.1], "group": "block"}]}]})";
  SceneRun run = run_scene(dim == 2 ? "pushed_block_2d" : "pushed_block_3d", s.str());
  // Frames every 50 steps: 5 is t = 0.25 s (before the kick at 0.3 s), 8 .. 16 after it.
  double rest = 0;
  for (int f = 0; f <= 5; ++f) rest = std::max(rest, std::fabs(run.at(run.frames[f], "position")[dim]));
  auto vx = [&](int f) { return run.at(run.frames[f], "velocity")[dim]; };
  const double a = (vx(16) - vx(8)) / 0.4, expected = (F - mu_d * m * g) / m;
  std::printf("%dD pushed block (F = 0.4 W, mu_d = %.1f, mu_s = %.1f): largest displacement at rest %.3e m; sliding "
              "after the kick: a = %.9f, expected %.9f; v at 0.8 s %.4f m/s\n", dim, mu_d, mu_s, rest, a, expected, vx(16));
  EXPECT_LT(rest, 1e-12);
  EXPECT_NEAR(a, expected, 1e-6 * g);
  EXPECT_GT(vx(16), 0.2);
}

}  // namespace

TEST(StaticFriction, PushedPolygonStaysUntilSetSlidingThenKeepsSliding) { pushed_block(2); }
TEST(StaticFriction, PushedBoxStaysUntilSetSlidingThenKeepsSliding) { pushed_block(3); }
