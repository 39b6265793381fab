// The `energy` analysis: the balance T + V − (T₀ + V₀) = W_ext + W_walls + W_θ − D_impacts −
// D_friction closes to rounding in 2D (the θ-scheme's discrete energy identity), and its
// parts are the analytic ones: a disk dropped on a floor with e = 0 dissipates its fall
// in the impact, a block sliding to rest dissipates its kinetic energy by friction, a
// piston pushing a layer does work.
#include <cmath>

#include "analysis_run.hpp"

using namespace moreau_test;

namespace {

json base(double duration, double h = 1e-3) {
  json s = json::parse(R"({"format": "moreau-scene/1", "dimension": 2, "gravity": [0, -9.81],
    "materials": {"m": {"density": 1000}},
    "solver": {"type": "nlgs", "tolerance": 1e-10, "max_iterations": 2000},
    "analyses": [{"type": "energy"}]})");
  s["time"] = {{"step", h}, {"duration", duration}};
  s["output"] = {{"every", 50}};
  return s;
}

json floor_body() {
  return {{"name", "floor"}, {"fixed", true}, {"position", {0, -0.01}},
          {"contactors", {{{"shape", "segment"}, {"length", 10}, {"thickness", 0.02}, {"group", "floor"}}}}};
}

}  // namespace

TEST(Energy, InelasticImpactDissipatesTheFall) {
  const double r = 0.1, drop = 0.5;
  json s = base(1.0);
  s["laws"] = {{"plastic", {{"type", "coulomb"}, {"friction", 0.0}}}};
  s["interactions"] = {{{"groups", {"ball", "floor"}}, {"law", "plastic"}}};
  s["bodies"] = {floor_body(), {{"name", "ball"}, {"material", "m"}, {"position", {0, r + drop}},
                                {"contactors", {{{"shape", "disk"}, {"radius", r}, {"group", "ball"}}}}}};
  SceneRun run = run_json("energy_drop", s);
  ASSERT_FALSE(run.frames.empty());
  const double m = run.header("/bodies/mass")[1];
  const std::string fr = run.last();
  const double E0 = run.scalar(fr, "analyses/energy/initial");
  std::printf("drop: dissipated by the impact %.9g J/m, m g drop %.9g, balance error %.1e\n",
              run.scalar(fr, "analyses/energy/dissipated_impacts"), m * 9.81 * drop,
              run.scalar(fr, "analyses/energy/balance_error"));
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/dissipated_impacts"), m * 9.81 * drop, 1e-9 * m * 9.81 * drop);
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/dissipated_friction"), 0, 1e-12 * E0);
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/kinetic"), 0, 1e-12 * std::fabs(E0));
  for (const auto& f : run.frames) EXPECT_NEAR(run.scalar(f, "analyses/energy/balance_error"), 0, 1e-12 * std::fabs(E0)) << f;
}

TEST(Energy, SlidingBlockDissipatesByFriction) {
  const double v0 = 1.0, mu = 0.3;
  json s = base(0.6);
  s["laws"] = {{"rough", {{"type", "coulomb"}, {"friction", mu}}}};
  s["interactions"] = {{{"groups", {"block", "floor"}}, {"law", "rough"}}};
  s["bodies"] = {floor_body(), {{"name", "block"}, {"material", "m"}, {"position", {0, 0.05}}, {"velocity", {v0, 0}},
                                {"contactors", {{{"shape", "polygon"},
                                                 {"vertices", {{-0.1, -0.05}, {0.1, -0.05}, {0.1, 0.05}, {-0.1, 0.05}}},
                                                 {"group", "block"}}}}}};
  SceneRun run = run_json("energy_slide", s);
  ASSERT_FALSE(run.frames.empty());
  const double m = run.header("/bodies/mass")[1];
  const std::string fr = run.last();
  // It stops after v0²/(2 μ g) = 0.17 s: all of ½ m v0² went into friction.
  std::printf("sliding block: friction dissipated %.9g J/m, 1/2 m v0^2 = %.9g\n",
              run.scalar(fr, "analyses/energy/dissipated_friction"), 0.5 * m * v0 * v0);
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/dissipated_friction"), 0.5 * m * v0 * v0, 1e-8 * m * v0 * v0);
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/kinetic"), 0, 1e-12 * m * v0 * v0);
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/balance_error"), 0, 1e-12 * m * v0 * v0);
}

TEST(Energy, BalanceClosesInAPourWithAPiston) {
  // Grains poured with restitution and friction, then pushed by a driven piston: every
  // term at work; θ = 0.6 adds the scheme's own work. The balance is an identity of the
  // scheme, true for any impulses: a loose solver tolerance does not change it.
  json s = base(0.5, 5e-4);
  s["time"]["theta"] = 0.6;
  s["solver"] = {{"type", "nlgs"}, {"tolerance", 1e-6}, {"max_iterations", 500}};  // the identity holds for any impulses
  s["laws"] = {{"bouncy", {{"type", "coulomb"}, {"friction", 0.4}, {"restitution", 0.5}}}};
  s["interactions"] = {{{"groups", {"grain", "grain"}}, {"law", "bouncy"}}, {{"groups", {"grain", "wall"}}, {"law", "bouncy"}}};
  auto wall = [](const std::string& name, double x, double y, double angle, double len, bool fixed) {
    json b = {{"name", name}, {"position", {x, y}}, {"angle", angle},
              {"contactors", {{{"shape", "segment"}, {"length", len}, {"thickness", 0.004}, {"group", "wall"}}}}};
    if (fixed) b["fixed"] = true;
    else b["mass"] = 1.0, b["inertia"] = 1.0;
    return b;
  };
  s["bodies"] = {wall("floor", 0.03, -0.002, 0, 0.08, true), wall("left", -0.002, 0.05, M_PI / 2, 0.1, true),
                 wall("piston", 0.062, 0.05, M_PI / 2, 0.1, false)};
  s["drivers"] = {{{"body", "piston"}, {"velocity", {0, 0}}, {"angular_velocity", 0}, {"end", 0.3}},
                  {{"body", "piston"}, {"velocity", {-0.05, 0}}, {"angular_velocity", 0}, {"start", 0.3}}};
  s["forces"] = {{{"type", "constant"}, {"body", "grain_3"}, {"force", {0.01, 0}}}};
  s["generators"] = {{{"type", "deposit"}, {"count", 50}, {"seed", 2}, {"radius", 0.003},
                      {"container", {{"box", {{"min", {0, 0}}, {"max", {0.06, 0.08}}}}}},
                      {"grain", {{"shape", "disk"}, {"group", "grain"}}}, {"body", {{"material", "m"}}}}};
  SceneRun run = run_json("energy_pour", s);
  ASSERT_FALSE(run.frames.empty());
  const std::string fr = run.last();
  const double E0 = std::fabs(run.scalar(fr, "analyses/energy/initial"));
  double worst = 0;
  for (const auto& f : run.frames) worst = std::max(worst, std::fabs(run.scalar(f, "analyses/energy/balance_error")));
  std::printf("pour: impacts %.4g, friction %.4g, walls %.4g, forces %.4g, theta %.4g J/m; worst balance error %.1e of |E0|\n",
              run.scalar(fr, "analyses/energy/dissipated_impacts"), run.scalar(fr, "analyses/energy/dissipated_friction"),
              run.scalar(fr, "analyses/energy/work_boundary"), run.scalar(fr, "analyses/energy/work_external"),
              run.scalar(fr, "analyses/energy/work_theta"), worst / E0);
  EXPECT_LT(worst, 1e-11 * E0);
  EXPECT_GT(run.scalar(fr, "analyses/energy/dissipated_impacts"), 0);
  EXPECT_GT(run.scalar(fr, "analyses/energy/dissipated_friction"), 0);
  EXPECT_GT(run.scalar(fr, "analyses/energy/work_boundary"), 0) << "the piston pushes";
  EXPECT_NE(run.scalar(fr, "analyses/energy/work_external"), 0);
  // W_θ = Σ_steps h (½ − θ) m g·(v⁺ − v⁻) telescopes to h (½ − θ) Σ_grains m g·(v − v₀), v₀ = 0.
  const auto m = run.header("/bodies/mass");
  const auto v = run.at(fr, "velocity");
  double closed = 0;
  for (std::size_t b = 3; b < m.size(); ++b) closed += 5e-4 * (0.5 - 0.6) * m[b] * -9.81 * v[2 * b + 1];
  EXPECT_NEAR(run.scalar(fr, "analyses/energy/work_theta"), closed, 1e-12 * E0);
}
