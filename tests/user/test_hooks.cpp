// The example hooks of user/, run through `moreau run` as a user would.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "cli_runner.hpp"
#include "h5_read.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

/// A 2D ball thrown up from y = 1 at (2, 3) m/s, mass 2, with hooks.
std::string ball(const std::string& hooks, double duration = 1.0) {
  return R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 0.01, "duration": )" + std::to_string(duration) + R"(},
  "gravity": [0, -9.81],
  "bodies": [{"name": "ball", "position": [0, 1], "velocity": [2, 3], "angular_velocity": 4, "mass": 2, "inertia": 0.25}],
  "output": {"every": 10},
  "hooks": [)" + hooks + "]}";
}

std::vector<std::vector<double>> read_csv(const fs::path& p, std::string& header) {
  std::ifstream in(p);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST(Hooks, EnergyLogWritesTheEnergiesAsCsv) {
  const fs::path dir = scratch_dir("energy_log");
  const fs::path scene = write_file(dir, "scene.json", ball(R"({"type": "energy_log", "file": "e.csv", "every": 10})"));
  Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  auto rows = read_csv(dir / "e.csv", header);
  EXPECT_EQ(header, "time,kinetic_translational,kinetic_rotational,potential,total");
  ASSERT_EQ(rows.size(), 11u);  // t = 0, 0.1, ..., 1.0
  const double m = 2, g = 9.81, E0 = 0.5 * m * (4 + 9) + 0.5 * 0.25 * 16 + m * g * 1;
  for (const auto& row : rows) {
    const double t = row[0], vy = 3 - g * t, y = 1 + 3 * t - 0.5 * g * t * t;
    // θ = 0.5 is exact for constant gravity: energies match to rounding.
    EXPECT_NEAR(row[1], 0.5 * m * (4 + vy * vy), 1e-9) << t;
    EXPECT_NEAR(row[2], 0.5 * 0.25 * 16, 1e-12) << t;
    EXPECT_NEAR(row[3], m * g * y, 1e-9) << t;
    EXPECT_NEAR(row[4], E0, 1e-9) << t;
  }
}

TEST(Hooks, StopWhenEndsTheRunWithItsLastFrame) {
  const fs::path dir = scratch_dir("stop_when");
  const fs::path scene = write_file(
      dir, "scene.json",
      ball(R"({"type": "stop_when", "quantity": "position", "body": "ball", "component": 1, "below": 0.0})", 5.0));
  Result r = run_moreau({"run", scene.string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  // y(t) = 1 + 3t − g t²/2 crosses 0 at t* = (3 + √(9 + 2g))/g; the run stops at the
  // first step end past it.
  const double g = 9.81, t_star = (3 + std::sqrt(9 + 2 * g)) / g;
  const long step = static_cast<long>(std::ceil(t_star / 0.01));
  char frame[32];
  std::snprintf(frame, sizeof frame, "%08ld", step);
  const auto frames = frame_names((dir / "out.h5").string());
  EXPECT_EQ(frames.back(), frame);
  EXPECT_NE(r.err.find("stopped by a hook: stop_when: position[1] of body 0 = "), std::string::npos) << r.err;
  const auto y = read_doubles((dir / "out.h5").string(), "/frames/" + frames.back() + "/position");
  EXPECT_LT(y[1], 0.0);
  EXPECT_GT(y[1], -0.2);
}

TEST(Hooks, StopWhenOnKineticEnergy) {
  const fs::path dir = scratch_dir("stop_ke");
  const fs::path scene = write_file(
      dir, "scene.json", ball(R"({"type": "stop_when", "quantity": "kinetic_energy", "above": 100, "after": 0.5})", 5.0));
  Result r = run_moreau({"run", scene.string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("stop_when: kinetic energy = "), std::string::npos) << r.err;
}

TEST(Hooks, ShakeImposesASinusoidalVelocity) {
  const fs::path dir = scratch_dir("shake");
  const fs::path scene = write_file(dir, "scene.json", R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 0.001, "duration": 0.2}, "gravity": [0, -9.81],
  "bodies": [{"name": "plate", "position": [0, 0], "mass": 1, "inertia": 1, "velocity": [0, 0.0942477796076938]}],
  "output": {"every": 50},
  "hooks": [{"type": "shake", "body": "plate", "component": 1, "amplitude": 0.001, "frequency": 15}]})");
  Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const double A = 0.001, w = 2 * std::numbers::pi * 15, h = 0.001, T = 0.2;
  const auto p = read_doubles((dir / "out.h5").string(), "/frames/00000200/position");
  // Gravity does not act on the imposed component; x is the trapezoidal integral of the
  // imposed v, whose error is at most T h² max|v''| / 12 = T h² A ω³ / 12.
  EXPECT_NEAR(p[1], A * std::sin(w * T), T * h * h * A * w * w * w / 12);
  EXPECT_EQ(p[0], 0.0);
}

TEST(Hooks, ChangingTheStateAfterSolveIsRefused) {
  const fs::path dir = scratch_dir("steer_late");
  const fs::path scene = write_file(
      dir, "scene.json",
      std::string(R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.01, "duration": 0.1},
  "plugin_paths": [")") + MOREAU_TEST_PLUGINS + R"(/steer_late"],
  "bodies": [{"name": "b", "position": [0, 0], "mass": 1, "inertia": 1}],
  "hooks": [{"type": "steer_late"}]})");
  Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("a hook may change the state only before the solve stage (it ran before update_dofs)"),
            std::string::npos) << r.err;
}
