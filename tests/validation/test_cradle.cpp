// Newton's cradle: 5 equal steel spheres in a row, 1 mm apart, e = 1, no friction, no
// gravity; the first moves at 1 m/s. The gaps make the impacts sequential (each closes in
// 10 steps of 1e-4 s), so each is a two-ball elastic collision of equal masses, which
// exchanges the velocities exactly: the last ball leaves at 1 m/s and the others stop.
// Tolerance: the solver's (1e-12) and rounding, 1e-9 m/s.
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

TEST(Cradle, LastBallLeavesAtTheFirstBallsSpeedAndTheOthersStop) {
  std::ostringstream s;
  s.precision(17);
  s << R"({"format": "moreau-scene/1", "dimension": 3, "time": {"step": 1e-4, "duration": 0.1},
  "gravity": [0, 0, 0], "materials": {"steel": {"density": 7800}},
  "laws": {"elastic": {"type": "coulomb", "friction": 0, "restitution": 1}},
  "interactions": [{"groups": ["ball", "ball"], "law": "elastic"}],
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 1000}, "output": {"every": 100}, "bodies": [)";
  for (int i = 0; i < 5; ++i)
    s << (i ? ", " : "") << R"({"name": "b)" << i << R"(", "material": "steel", "position": [)" << i * 0.051
      << R"(, 0, 0])" << (i == 0 ? R"(, "velocity": [1, 0, 0])" : "")
      << R"(, "contactors": [{"shape": "sphere", "radius": 0.025, "group": "ball"}]})";
  s << "]}";
  SceneRun run = run_scene("cradle", s.str());
  const auto v = run.at(run.frames.back(), "velocity");
  for (int i = 0; i < 5; ++i) {
    std::printf("ball %d: v = (%.3e, %.3e, %.3e)\n", i, v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    EXPECT_NEAR(v[3 * i], i == 4 ? 1.0 : 0.0, 1e-9) << "ball " << i;
    EXPECT_NEAR(v[3 * i + 1], 0.0, 1e-12);
    EXPECT_NEAR(v[3 * i + 2], 0.0, 1e-12);
  }
}
