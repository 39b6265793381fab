// The `stress` analysis (de Saxcé et al. 2004; eq. 16–17 of Dumont, Fortin & Ouafik 2010):
//  - a static packing squeezed by two pistons without gravity: Σ = diag(−F_x/H, −F_y/W),
//    the applied loads over the faces, and the same from the wall forces the run reports;
//  - a packing settled under gravity: Σ = (1/V)(Σ_walls x_c ⊗ f_c + Σ_p m_p x_p ⊗ g), the
//    boundary tractions and the body force, to the solver's tolerance (what is left is
//    the inertia term of a packing at rest to that tolerance);
//  - symmetric to rounding, and unchanged by moving the origin of the moments;
//  - eq. 17 for a disk rolling down an incline from rest (its mean free path L the
//    distance rolled), frame by frame and on time average; and, for φ = 0, a bead
//    bouncing on a plane: the time average is −ρ g a in Σ_yy.
#include <cmath>

#include "analysis_run.hpp"

using namespace moreau_test;

namespace {

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

json segment(const std::string& name, double x, double y, double angle, double length, const std::string& group,
             bool fixed = true) {
  json b = {{"name", name}, {"position", {x, y}}, {"angle", angle},
            {"contactors", {{{"shape", "segment"}, {"length", length}, {"thickness", 0.004}, {"group", group}}}}};
  if (fixed) b["fixed"] = true;
  else b["mass"] = 1.0, b["inertia"] = 1.0;
  return b;
}

}  // namespace

TEST(Stress, SqueezedPackingIsTheAppliedLoad) {
  // 4 × 3 touching frictionless disks of radius R in a box [0, W] × [0, H]; the right wall
  // and the lid are pistons: one free component, pushed by a constant force. (With
  // friction, the floor and the lid could take part of the horizontal load: Σ is then
  // still the average of the boundary tractions, but no longer −F_x/H.)
  const double R = 0.01, W = 8 * R, H = 6 * R, Fx = 30.0, Fy = 50.0;
  json scene = json::parse(R"({"format": "moreau-scene/1", "dimension": 2,
    "time": {"step": 1e-3, "duration": 0.01}, "gravity": [0, 0],
    "materials": {"steel": {"density": 7800}}, "laws": {"smooth": {"type": "coulomb", "friction": 0.0}},
    "interactions": [{"groups": ["grain", "grain"], "law": "smooth"}, {"groups": ["grain", "wall"], "law": "smooth"}],
    "detection": {"alert": 1e-4},
    "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 50000},
    "output": {"every": 5}})");
  scene["bodies"] = {segment("floor", W / 2, -0.002, 0, W + 0.02, "wall"), segment("left", -0.002, H / 2, M_PI / 2, H + 0.02, "wall"),
                     segment("right", W + 0.002, H / 2, M_PI / 2, H + 0.02, "wall", false),
                     segment("lid", W / 2, H + 0.002, 0, W + 0.02, "wall", false)};
  scene["generators"] = {{{"type", "lattice"}, {"lattice", "square"}, {"counts", {4, 3}}, {"origin", {R, R}}, {"radius", R},
                          {"grain", {{"shape", "disk"}, {"group", "grain"}}}, {"body", {{"material", "steel"}}}}};
  scene["forces"] = {{{"type", "constant"}, {"body", "right"}, {"force", {-Fx, 0}}},
                     {{"type", "constant"}, {"body", "lid"}, {"force", {0, -Fy}}}};
  scene["drivers"] = {{{"body", "right"}, {"velocity", {nullptr, 0}}, {"angular_velocity", 0}},
                      {{"body", "lid"}, {"velocity", {0, nullptr}}, {"angular_velocity", 0}}};
  const json box = {{"min", {0, 0}}, {"max", {W, H}}};
  scene["analyses"] = {{{"type", "stress"}, {"region", box}},
                       {{"type", "stress"}, {"name", "far"}, {"region", box}, {"origin", {120.0, -75.0}}},
                       {{"type", "walls"}, {"bodies", {"right", "lid"}}}};
  SceneRun run = run_json("squeezed", scene);
  ASSERT_FALSE(run.frames.empty());
  const std::string fr = run.last();
  const auto S = run.at(fr, "analyses/stress/total");
  const auto far = run.at(fr, "analyses/far/total");
  const auto walls = run.at(fr, "analyses/walls/force");  // force of the grains on right, lid
  const double scale = max_abs(S);
  std::printf("Sigma = [[%.9g, %.9g], [%.9g, %.9g]] Pa; -Fx/H = %.9g, -Fy/W = %.9g\n", S[0], S[1], S[2], S[3], -Fx / H, -Fy / W);
  // Applied loads over the faces, and the tractions the walls feel, to the solver's tolerance.
  EXPECT_NEAR(S[0], -Fx / H, 1e-9 * scale);
  EXPECT_NEAR(S[3], -Fy / W, 1e-9 * scale);
  EXPECT_NEAR(S[0], -walls[0] / H, 1e-9 * scale);
  EXPECT_NEAR(S[3], -walls[3] / W, 1e-9 * scale);
  EXPECT_NEAR(S[1], 0, 1e-9 * scale);
  EXPECT_NEAR(S[1], S[2], 1e-13 * scale) << "symmetric to rounding";
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(far[k], S[k], 1e-11 * scale) << "origin moved by 140 m";
}

TEST(Stress, SettledPackingIsBoundaryTractionsAndWeight) {
  json scene = json::parse(R"({"format": "moreau-scene/1", "dimension": 2,
    "time": {"step": 1e-3, "duration": 0.5}, "gravity": [0, -9.81],
    "materials": {"glass": {"density": 2500}}, "laws": {"rough": {"type": "coulomb", "friction": 0.4}},
    "interactions": [{"groups": ["grain", "grain"], "law": "rough"}, {"groups": ["grain", "wall"], "law": "rough"}],
    "solver": {"type": "nlgs", "tolerance": 1e-8, "max_iterations": 5000},
    "output": {"every": 500}})");
  const double W = 0.04;
  scene["bodies"] = {segment("floor", W / 2, -0.002, 0, W + 0.02, "wall"), segment("left", -0.002, 0.05, M_PI / 2, 0.1, "wall"),
                     segment("right", W + 0.002, 0.05, M_PI / 2, 0.1, "wall")};
  scene["generators"] = {{{"type", "deposit"}, {"count", 60}, {"seed", 5},
                          {"size", {{"distribution", "uniform"}, {"min", 0.0018}, {"max", 0.0025}}},
                          {"container", {{"box", {{"min", {0, 0}}, {"max", {W, 0.06}}}}}},
                          {"grain", {{"shape", "disk"}, {"group", "grain"}}}, {"body", {{"material", "glass"}}}}};
  scene["analyses"] = {{{"type", "stress"}, {"volume", 1.0}, {"origin", {0.0, 0.0}}}};
  SceneRun run = run_json("settled", scene);
  ASSERT_FALSE(run.frames.empty());
  const std::string fr = run.last();
  const auto S = run.at(fr, "analyses/stress/total");  // with V = 1: Σ·V
  const auto inertia = run.at(fr, "analyses/stress/inertia");
  // The boundary tractions and the weight, from the frame's contacts and bodies.
  const auto B = run.at(fr, "contacts/bodies");
  const auto P = run.at(fr, "contacts/point");
  const auto F = run.at(fr, "contacts/force");
  const auto x = run.at(fr, "position");
  const auto m = run.header("/bodies/mass");
  std::vector<double> T(4, 0.0);
  for (std::size_t c = 0; c < B.size() / 2; ++c) {
    const int a = static_cast<int>(B[2 * c]), b = static_cast<int>(B[2 * c + 1]);
    const bool wa = a < 3, wb = b < 3;  // the three walls come first
    if (wa == wb) continue;
    const double sign = wb ? 1.0 : -1.0;  // the force on the grain
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) T[2 * i + j] += sign * P[2 * c + i] * F[2 * c + j];
  }
  for (std::size_t b = 3; b < m.size(); ++b)
    for (int i = 0; i < 2; ++i) T[2 * i + 1] += m[b] * x[2 * b + i] * -9.81;
  const double scale = max_abs(S);
  double diff = 0;
  for (int k = 0; k < 4; ++k) diff = std::max(diff, std::fabs(S[k] - T[k]));
  std::printf("settled packing: |Sigma V - (walls + weight)| = %.2e of |Sigma V| (inertia term %.2e)\n", diff / scale,
              max_abs(inertia) / scale);
  EXPECT_LT(diff, 1e-6 * scale);
  EXPECT_NEAR(S[1], S[2], 1e-12 * scale);
}

TEST(Stress, RollingDiskMatchesEquation17) {
  // Eq. 17 is the mean stress of a disk (radius a, density ρ) rolling without slipping down
  // a plane inclined at φ, from rest, L being the distance rolled:
  //   Σ = ρ g a {[[0, sin φ/6], [sin φ/6, −cos φ]] + (L/a) sin φ/3 · 1}   (slope axes: down, normal).
  // The centrifugal part uses ω at mid-step, so L is taken at mid-step too; the rest is exact.
  const double phi = 0.5, a = 0.1, rho = 700, g = 9.81, t = 0.02, h = 1e-3;
  const double n[2] = {std::sin(phi), std::cos(phi)};
  json scene = json::parse(R"({"format": "moreau-scene/1", "dimension": 2,
    "time": {"step": 1e-3, "duration": 1.0}, "gravity": [0, -9.81],
    "materials": {"wood": {"density": 700}}, "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
    "interactions": [{"groups": ["wheel", "slope"], "law": "rough"}],
    "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 100},
    "output": {"every": 50}})");
  scene["bodies"] = {segment("slope", 0, 0, -phi, 20, "slope"),
                     {{"name", "wheel"}, {"material", "wood"}, {"position", {n[0] * (t / 2 + a), n[1] * (t / 2 + a)}},
                      {"contactors", {{{"shape", "disk"}, {"radius", a}, {"group", "wheel"}}}}}};
  scene["bodies"][0]["contactors"][0]["thickness"] = t;
  scene["analyses"] = {{{"type", "stress"}, {"volume", M_PI * a * a}, {"average", true}}};
  SceneRun run = run_json("rolling", scene);
  ASSERT_FALSE(run.frames.empty());
  const double e1[2] = {std::cos(phi), -std::sin(phi)}, e2[2] = {std::sin(phi), std::cos(phi)};
  auto slope_axes = [&](const std::vector<double>& S, double out[4]) {
    const double* q[2] = {e1, e2};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        double s = 0;
        for (int k = 0; k < 2; ++k)
          for (int l = 0; l < 2; ++l) s += q[i][k] * S[2 * k + l] * q[j][l];
        out[2 * i + j] = s;
      }
  };
  auto eq17 = [&](double L, double out[4]) {
    const double c = rho * g * a;
    out[0] = c * (L / a) * std::sin(phi) / 3;
    out[1] = out[2] = c * std::sin(phi) / 6;
    out[3] = c * (-std::cos(phi) + (L / a) * std::sin(phi) / 3);
  };
  const auto x0 = run.at(run.frames.front(), "position");
  double worst = 0, mean_L = 0, prev_L = 0;
  std::vector<double> mean(4, 0.0);
  for (std::size_t k = 1; k < run.frames.size(); ++k) {
    const std::string& fr = run.frames[k];
    const auto x = run.at(fr, "position"), v = run.at(fr, "velocity");
    const double L = (x[2] - x0[2]) * e1[0] + (x[3] - x0[3]) * e1[1];
    const double speed = v[2] * e1[0] + v[3] * e1[1];
    double got[4], want[4];
    slope_axes(run.at(fr, "analyses/stress/total"), got);
    eq17(L - speed * h / 2, want);  // mid-step
    for (int i = 0; i < 4; ++i) worst = std::max(worst, std::fabs(got[i] - want[i]) / (rho * g * a));
    // The average over the frame's window: L at mid-window, the stress averaged over steps.
    double avg[4];
    slope_axes(run.at(fr, "analyses/stress/average/total"), avg);
    for (int i = 0; i < 4; ++i) mean[i] += avg[i] / static_cast<double>(run.frames.size() - 1);
    // L = α t²/2 (α = 2/3 g sin φ): its mean over a window Δ is the trapezoid less αΔ²/12.
    const double alpha = 2.0 / 3.0 * g * std::sin(phi), dt = 50 * h;
    mean_L += (0.5 * (L + prev_L) - alpha * dt * dt / 12) / static_cast<double>(run.frames.size() - 1);
    prev_L = L;
  }
  double want[4];
  eq17(mean_L, want);
  double worst_mean = 0;
  for (int i = 0; i < 4; ++i) worst_mean = std::max(worst_mean, std::fabs(mean[i] - want[i]) / (rho * g * a));
  std::printf("rolling disk: frames within %.2e rho g a of eq. 17 (L up to %.2f a); time average within %.2e\n", worst,
              prev_L / a, worst_mean);
  // Per frame: O(h²) from the mid-step; on average: the mean of L over a window of 50 steps.
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worst_mean, 1e-3);
}

TEST(Stress, BouncingBeadAveragesToEquation17) {
  // φ = 0: Σ = ρ g a [[0, 0], [0, −1]] on time average. Over a finite window T the contact
  // impulses are m g T plus the change of momentum, which the expectation includes; the
  // rest is the lever of the impulses, applied at the detection configuration a gap (up to
  // v h) away: O(v h / a).
  const double a = 0.05, rho = 7800, g = 9.81, h = 2e-4, T = 10.0;
  json scene = json::parse(R"({"format": "moreau-scene/1", "dimension": 2,
    "time": {"step": 2e-4, "duration": 10.0}, "gravity": [0, -9.81],
    "materials": {"steel": {"density": 7800}}, "laws": {"elastic": {"type": "coulomb", "friction": 0.3, "restitution": 1.0}},
    "interactions": [{"groups": ["bead", "floor"], "law": "elastic"}],
    "solver": {"type": "nlgs", "tolerance": 1e-12, "max_iterations": 100},
    "output": {"every": 50000}})");
  scene["bodies"] = {segment("floor", 0, -0.002, 0, 4, "floor"),
                     {{"name", "bead"}, {"material", "steel"}, {"position", {0, a + 0.2}},
                      {"contactors", {{{"shape", "disk"}, {"radius", a}, {"group", "bead"}}}}}};
  scene["analyses"] = {{{"type", "stress"}, {"volume", M_PI * a * a}, {"average", true}}};
  SceneRun run = run_json("bouncing", scene);
  ASSERT_FALSE(run.frames.empty());
  const auto S = run.at(run.last(), "analyses/stress/average/total");
  const double v = run.at(run.last(), "velocity")[3];
  const double m = run.header("/bodies/mass")[1];
  const double expected = -(a / (M_PI * a * a)) * (m * g * T + m * v) / T;  // v(0) = 0
  const double vmax = std::sqrt(2 * g * 0.2);
  std::printf("bouncing bead: <Sigma_yy> = %.6f rho g a (momentum-corrected eq. 17: %.6f), <Sigma_xy> = %.1e\n",
              S[3] / (rho * g * a), expected / (rho * g * a), S[1] / (rho * g * a));
  EXPECT_NEAR(S[3], expected, vmax * h / a * rho * g * a);
  EXPECT_NEAR(S[3], -rho * g * a, (2 * vmax / (g * T) + vmax * h / a) * rho * g * a);
  EXPECT_NEAR(S[0], 0, 1e-9 * rho * g * a);
  EXPECT_NEAR(S[1], 0, 1e-9 * rho * g * a);
  EXPECT_NEAR(S[2], 0, 1e-9 * rho * g * a);
}
