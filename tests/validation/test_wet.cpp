// Capillary bridges (`wet`, LMGC90's IQS_WET_DS_CLB family; docs/laws.md): a drop (disk in
// 2D, sphere in 3D, radius 0.05, mass m, weight W) under a fixed grain of the same size,
// gravity pulling it away. A bridge carries a tension up to the adhesion F while the gap is
// within the rupture distance d:
//  - F > W, touching: the drop hangs still, the bridge carrying exactly W (tension: a
//    negative normal force);
//  - F < W, a wet packing (gap d/2 at the start, so the bridge exists from the first step):
//    the drop leaves with a = g − F/m while the bridge lasts, exactly (a constant
//    acceleration is integrated exactly by θ = 1/2); the bridge ruptures at the first step
//    whose gap at the detection configuration q⁻ + (1−θ)h v⁻ exceeds d, which the discrete
//    motion predicts exactly: d/2 + a h² [n²/2 + (1−θ) n] > d; from that step on a = g;
//  - gap 1.5 d at the start (within the alert distance, beyond d): no bridge, free fall.
// Tolerances: the solver runs to 1e-12 (DESIGN §1 error), so velocities and forces agree
// to 1e-9 of g h and W; the rupture step is exact.
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double g = 9.81, r = 0.05, h = 1e-3, d = 1e-3;

SceneRun drop(int dim, const std::string& name, double adhesion, double gap0, double duration) {
  std::ostringstream s;
  s.precision(17);
  auto vec = [&](double y) {
    std::ostringstream v;
    v.precision(17);
    v << (dim == 2 ? "[0, " : "[0, 0, ") << y << "]";
    return v.str();
  };
  const char* shape = dim == 2 ? "disk" : "sphere";
  s << R"({"format": "moreau-scene/1", "dimension": )" << dim << R"(, "time": {"step": )" << h << R"(, "duration": )"
    << duration << R"(}, "gravity": )" << vec(-g) << R"(, "materials": {"water_glass": {"density": 1000}},
  "laws": {"bridge": {"type": "wet", "adhesion": )" << adhesion << R"(, "rupture_distance": )" << d << R"(, "friction": 0.3}},
  "interactions": [{"groups": ["grain", "grain"], "law": "bridge"}], "detection": {"alert": 2e-3},
  "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 500}, "output": {"every": 1}, "bodies": [
    {"name": "fixed", "fixed": true, "position": )" << vec(0) << R"(, "contactors": [{"shape": ")" << shape
    << R"(", "radius": )" << r << R"(, "group": "grain"}]},
    {"name": "drop", "material": "water_glass", "position": )" << vec(-2 * r - gap0) << R"(, "contactors": [{"shape": ")"
    << shape << R"(", "radius": )" << r << R"(, "group": "grain"}]}]})";
  return run_scene(name + (dim == 2 ? "_2d" : "_3d"), s.str());
}

double mass(int dim) { return dim == 2 ? 1000 * M_PI * r * r : 1000 * 4.0 / 3 * M_PI * r * r * r; }

/// The drop's vertical velocity at the end of step f − 1 (frame f).
double vertical_velocity(const SceneRun& run, int dim, std::size_t f) { return run.at(run.frames[f], "velocity")[2 * dim - 1]; }

void hangs(int dim) {
  const double W = mass(dim) * g;
  SceneRun run = drop(dim, "wet_hangs", 1.5 * W, 0, 0.1);
  ASSERT_EQ(run.frames.size(), 101u);
  for (std::size_t f = 1; f < run.frames.size(); ++f) {
    const auto force = run.at(run.frames[f], "contacts/normal_force");
    ASSERT_EQ(force.size(), 1u);
    EXPECT_NEAR(force[0], -W, 1e-9 * W) << "frame " << f << ": the bridge carries the weight";
    EXPECT_NEAR(vertical_velocity(run, dim, f), 0, 1e-9 * g * h);
    EXPECT_EQ(run.at(run.frames[f], "contacts/bond")[0], 1.0);
    EXPECT_EQ(run.at(run.frames[f], "laws/broken")[0], 0.0);
  }
  const double y = run.at(run.frames.back(), "position")[2 * dim - 1];
  std::printf("%dD wet drop, F = 1.5 W: hangs (moved %.2e m in 0.1 s), bridge force %.12g N (W = %.12g N)\n", dim,
              std::abs(y + 2 * r), -run.at(run.frames.back(), "contacts/normal_force")[0], W);
  EXPECT_NEAR(y, -2 * r, 1e-12);
}

void pulled_off(int dim) {
  const double m = mass(dim), W = m * g, F = 0.5 * W, a = g - F / m, theta = 0.5;
  long predicted = 0;
  // Gap at the detection configuration of step n: d/2 + a [(nh)²/2 + (1−θ)h·nh].
  auto gap = [&](double n) { return d / 2 + a * h * h * (n * n / 2 + (1 - theta) * n); };
  while (gap(static_cast<double>(predicted)) <= d) ++predicted;
  SceneRun run = drop(dim, "wet_pulled_off", F, d / 2, 0.04);
  long ruptured = -1;
  for (std::size_t f = 1; f < run.frames.size(); ++f) {
    const long step = static_cast<long>(f) - 1;
    const double broken = run.at(run.frames[f], "laws/broken")[0];
    if (ruptured < 0 && broken == 1) ruptured = step;
    const double dv = vertical_velocity(run, dim, f) - vertical_velocity(run, dim, f - 1);
    const double expected = -(ruptured < 0 ? a : g) * h;
    EXPECT_NEAR(dv, expected, 1e-9 * g * h) << "step " << step << (ruptured < 0 ? " (bridged)" : " (ruptured)");
    EXPECT_EQ(run.at(run.frames[f], "laws/bonds")[0], ruptured < 0 ? 1.0 : 0.0) << "step " << step;
  }
  std::printf("%dD wet drop, F = W/2, starting d/2 apart: leaves at g - F/m = %.6g m/s2, bridge ruptures at step %ld "
              "(predicted %ld), then falls at g\n", dim, a, ruptured, predicted);
  EXPECT_EQ(ruptured, predicted);
}

void beyond_the_meniscus(int dim) {
  SceneRun run = drop(dim, "wet_beyond", 10 * mass(dim) * g, 1.5 * d, 0.01);
  for (std::size_t f = 1; f < run.frames.size(); ++f) {
    EXPECT_NEAR(vertical_velocity(run, dim, f) - vertical_velocity(run, dim, f - 1), -g * h, 1e-9 * g * h) << "frame " << f;
    EXPECT_EQ(run.at(run.frames[f], "laws/bonds")[0], 0.0);
  }
}

}  // namespace

TEST(Wet, DiskHangsFromABridgeStrongerThanItsWeight) { hangs(2); }
TEST(Wet, SphereHangsFromABridgeStrongerThanItsWeight) { hangs(3); }
TEST(Wet, DiskPulledOffLeavesAtGMinusFOverMUntilTheBridgeRupturesAtTheDistance) { pulled_off(2); }
TEST(Wet, SpherePulledOffLeavesAtGMinusFOverMUntilTheBridgeRupturesAtTheDistance) { pulled_off(3); }
TEST(Wet, NoBridgeBeyondTheRuptureDistance) {
  beyond_the_meniscus(2);
  beyond_the_meniscus(3);
}
