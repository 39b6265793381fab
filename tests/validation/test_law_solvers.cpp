// Every solver takes every law unchanged (docs/laws.md): the laws reach the solver as a
// standard Coulomb problem (cohesion moves q by W c, compliance adds to W's diagonal, and
// to BodyFactor::diagonal for the solvers working through body velocities). One 2D scene
// holds three independent systems, run with each solver:
//  - a block on `elastic` supports (k per point), placed at its static overlap W/(2k): it
//    stays there, each point carrying W/2 (analytic);
//  - a block `cohesive`-bonded on an incline at 0.9 of its threshold angle: it holds;
//  - a block hanging from a ceiling by a `czm` interface, bonded unstretched: it swings on
//    the interface's springs (no closed form over 300 steps: compared between solvers).
// Tolerances: every solver runs to 1e-10 (the DESIGN §1 error); velocities then differ by
// about 1e-10 of ‖q‖ (~g h, 1e-2 m/s) a step, positions by h times that summed over 300
// steps: below 1e-12 m. Compared at 1e-9 m (statics: 1e-9 of the weight).
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr double g = 9.81;

std::string scene(const std::string& solver) {
  const double k = 1e6, W = 20 * g, overlap = W / (2 * k);
  const double mu = 0.3, hold = 2 * 100 * 0.1 / W, alpha = std::atan(0.9 * std::tan(std::atan(mu) + std::asin(hold / std::sqrt(1 + mu * mu))));
  const double nx = std::sin(alpha), nz = std::cos(alpha);
  std::ostringstream s;
  s.precision(17);
  s << R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 1e-3, "duration": 0.3},
  "gravity": [0, -9.81], "materials": {"m": {"density": 1000}},
  "laws": {"soft": {"type": "elastic", "stiffness": )" << k << R"(, "friction": 0.5},
           "glued": {"type": "cohesive", "friction": 0.3, "cohesion": 100, "tensile_strength": 300, "area": 0.1},
           "zone": {"type": "czm", "normal_stiffness": 1e7, "tangential_stiffness": 1e7, "normal_strength": 1e4,
                    "shear_strength": 1e4, "mode_I_energy": 100, "mode_II_energy": 100, "area": 0.1}},
  "interactions": [{"groups": ["a", "floor"], "law": "soft"}, {"groups": ["b", "slope"], "law": "glued"},
                   {"groups": ["c", "ceiling"], "law": "zone"}], "detection": {"alert": 0.02},
  "solver": )" << solver << R"(, "output": {"every": 100}, "bodies": [
    {"name": "floor", "fixed": true, "position": [0, -0.1], "contactors": [{"shape": "polygon", "vertices": [[-0.5, -0.1], [0.5, -0.1], [0.5, 0.1], [-0.5, 0.1]], "group": "floor"}]},
    {"name": "a", "material": "m", "position": [0, )" << 0.05 - overlap << R"(], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "a"}]},
    {"name": "slope", "fixed": true, "position": [)" << 2 - 0.1 * nx << ", " << -0.1 * nz << R"(], "angle": )" << -alpha
    << R"(, "contactors": [{"shape": "polygon", "vertices": [[-1, -0.1], [1, -0.1], [1, 0.1], [-1, 0.1]], "group": "slope"}]},
    {"name": "b", "material": "m", "position": [)" << 2 + 0.05 * nx << ", " << 0.05 * nz << R"(], "angle": )" << -alpha
    << R"(, "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "b"}]},
    {"name": "ceiling", "fixed": true, "position": [4, 0.1], "contactors": [{"shape": "polygon", "vertices": [[-0.5, -0.1], [0.5, -0.1], [0.5, 0.1], [-0.5, 0.1]], "group": "ceiling"}]},
    {"name": "c", "material": "m", "position": [4, -0.05], "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "c"}]}]})";
  return s.str();
}

}  // namespace

TEST(LawSolvers, EverySolverTakesCohesionComplianceAndDamageUnchanged) {
  const double W = 20 * g;
  const std::vector<std::pair<std::string, std::string>> solvers = {
      {"nlgs_bodies", R"({"type": "nlgs", "exchange": "bodies", "tolerance": 1e-10, "max_iterations": 20000})"},
      {"nlgs_w", R"({"type": "nlgs", "exchange": "w", "tolerance": 1e-10, "max_iterations": 20000})"},
      {"auto", R"({"type": "auto", "tolerance": 1e-10})"},
      {"apgd", R"({"type": "apgd", "tolerance": 1e-10, "max_iterations": 100000})"},
      {"psor", R"({"type": "psor", "tolerance": 1e-10, "max_iterations": 100000})"},
      {"admm", R"({"type": "admm", "tolerance": 1e-10})"},
      {"newton", R"({"type": "newton", "tolerance": 1e-10})"},
      {"prox", R"({"type": "prox", "tolerance": 1e-10})"}};
  std::vector<double> reference;
  for (const auto& [name, json] : solvers) {
    SceneRun run = run_scene("law_solvers_" + name, scene(json));
    const auto& last = run.frames.back();
    const auto x = run.at(last, "position");
    const auto x0 = run.at(run.frames.front(), "position");
    const auto force = run.at(last, "contacts/normal_force");
    const auto bond = run.at(last, "contacts/bond");
    const auto bodies = run.at(last, "contacts/bodies");
    double a_force = 0, a_moved = 0, b_moved = 0;
    int glued = 0;
    for (std::size_t c = 0; c < force.size(); ++c) {
      const int body = static_cast<int>(std::max(bodies[2 * c], bodies[2 * c + 1]));
      if (body == 1) a_force += force[c];
      if (body == 3 && bond[c] == 1) ++glued;
    }
    for (int k = 0; k < 2; ++k) {
      a_moved = std::max(a_moved, std::fabs(x[2 + k] - x0[2 + k]));
      b_moved = std::max(b_moved, std::fabs(x[6 + k] - x0[6 + k]));
    }
    std::printf("%-12s elastic block: moved %.2e m, support force %.12g N (W = %.12g); bonded block: moved %.2e m, %d bonds; "
                "czm block at y = %.12f\n", name.c_str(), a_moved, a_force, W, b_moved, glued, x[11]);
    EXPECT_LT(a_moved, 1e-9) << name;
    EXPECT_NEAR(a_force, W, 1e-9 * W) << name;
    EXPECT_LT(b_moved, 1e-9) << name;
    EXPECT_EQ(glued, 2) << name;
    if (reference.empty()) reference = x;
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], reference[i], 1e-9) << name << ", position " << i;
  }
}
