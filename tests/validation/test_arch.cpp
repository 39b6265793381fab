// A semicircular masonry arch of 36 voussoirs (radial joints, dry: Coulomb μ = 0.8, no
// sliding) under self-weight, on fixed abutments (scripts/masonry_arch.py builds the same).
//
// Limit analysis (no tension, no sliding, infinite compressive strength: Heyman, "The
// safety of masonry arches", Int. J. Mech. Sci. 11, 1969) gives the least thickness of a
// semicircular arch with radial joints as t/R = 0.1075 (R: centreline radius), the
// solution of Milankovitch (1907) revisited by Makris & Alexakis ("The effect of
// stereotomy on the shape of the thrust-line and the minimum thickness of semicircular
// masonry arches", Arch. Appl. Mech. 83, 2013); Heyman's approximation is 0.106. At that
// thickness the thrust line touches the extrados at the crown and the springings and the
// intrados at about 54.5° from the crown: the collapse mechanism hinges there.
//
// Checked: 5 % above (t/R = 0.1129) the arch stands (no voussoir moves more than 1e-9 m
// in 1.5 s: it is statically admissible, so the contact forces hold it exactly); 5 %
// below (0.1021) it collapses, hinging at the springings, at the crown and at the joints
// 55° from it (the joint of the 36 nearest 54.5°), the relative rotations alternating in
// sign as the hinges alternate between extrados and intrados. The margin of 5 % covers
// the discreteness of 36 joints: the threshold moreau finds is t/R in [0.10742, 0.10744]
// (`python3 scripts/masonry_arch.py threshold --voussoirs 36 --resolution 2e-5`,
// docs/laws.md), 0.06 % below the continuous arch's.
#include <cmath>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

constexpr int N = 36;
constexpr double milankovitch = 0.1075;

SceneRun arch(const std::string& name, double t_over_r, double duration) {
  const double R = 1, t = t_over_r * R, ri = R - t / 2, ro = R + t / 2;
  std::ostringstream s;
  s.precision(17);
  s << R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 5e-4, "duration": )" << duration << R"(},
  "gravity": [0, -9.81], "materials": {"stone": {"density": 2500}},
  "laws": {"dry_joint": {"type": "coulomb", "friction": 0.8}},
  "interactions": [{"groups": ["stone", "stone"], "law": "dry_joint"}, {"groups": ["stone", "ground"], "law": "dry_joint"}],
  "detection": {"alert": 1e-3}, "solver": {"type": "auto", "tolerance": 1e-8}, "output": {"every": 100}, "bodies": [)";
  for (int side : {-1, 1})
    s << R"({"name": "abutment)" << side << R"(", "fixed": true, "position": [)" << side * R << R"(, -0.1],
      "contactors": [{"shape": "polygon", "vertices": [[)" << -t << ", -0.1], [" << t << ", -0.1], [" << t << ", 0.1], [" << -t
      << R"(, 0.1]], "group": "ground"}]}, )";
  for (int i = 0; i < N; ++i) {
    const double a0 = M_PI * i / N, a1 = M_PI * (i + 1) / N, am = 0.5 * (a0 + a1);
    const double cx = R * std::cos(am), cy = R * std::sin(am);
    const double corner[4][2] = {{ri, a0}, {ro, a0}, {ro, a1}, {ri, a1}};
    s << (i ? ", " : "") << R"({"name": "v)" << i << R"(", "material": "stone", "position": [)" << cx << ", " << cy
      << R"(], "contactors": [{"shape": "polygon", "group": "stone", "vertices": [)";
    for (int k = 0; k < 4; ++k)
      s << (k ? ", " : "") << "[" << corner[k][0] * std::cos(corner[k][1]) - cx << ", " << corner[k][0] * std::sin(corner[k][1]) - cy
        << "]";
    s << "]}]}";
  }
  s << "]}";
  return run_scene(name, s.str());
}

}  // namespace

TEST(MasonryArch, StandsFivePercentAboveTheLimitAnalysisThickness) {
  SceneRun run = arch("arch_stands", 1.05 * milankovitch, 1.5);
  const auto x0 = run.at(run.frames.front(), "position"), x1 = run.at(run.frames.back(), "position");
  double moved = 0;
  for (std::size_t i = 0; i < x0.size(); ++i) moved = std::max(moved, std::fabs(x1[i] - x0[i]));
  std::printf("t/R = %.4f: largest voussoir displacement after 1.5 s %.3e m\n", 1.05 * milankovitch, moved);
  EXPECT_LT(moved, 1e-9);
}

TEST(MasonryArch, CollapsesFivePercentBelowItWithHingesAtCrownHaunchesAndSpringings) {
  SceneRun run = arch("arch_collapses", 0.95 * milankovitch, 0.5);
  const auto x0 = run.at(run.frames.front(), "position"), x1 = run.at(run.frames.back(), "position");
  double moved = 0;
  for (std::size_t i = 0; i < x0.size(); ++i) moved = std::max(moved, std::fabs(x1[i] - x0[i]));
  // Joint j lies between voussoirs j − 1 and j (the abutments, bodies 0 and 1, do not turn).
  const auto angle = run.at(run.frames.back(), "angle");
  std::vector<double> rel(N + 1);
  double top = 0;
  for (int j = 0; j <= N; ++j) {
    const double before = j == 0 ? 0 : angle[2 + j - 1], after = j == N ? 0 : angle[2 + j];
    rel[j] = after - before;
    top = std::max(top, std::fabs(rel[j]));
  }
  std::vector<int> hinges;
  for (int j = 0; j <= N; ++j)
    if (std::fabs(rel[j]) > 0.2 * top) hinges.push_back(j);
  std::printf("t/R = %.4f: largest displacement after 0.5 s %.3f m; hinges at joints", 0.95 * milankovitch, moved);
  for (int j : hinges) std::printf(" %d (%.0f deg from the crown, rotation %+.3f)", j, std::fabs(90 - 180.0 * j / N), rel[j]);
  std::printf("\n");
  EXPECT_GT(moved, 0.01);
  // Springings, haunches at 55° (joints 7 and 29), crown (joint 18).
  const std::vector<int> expected = {0, 7, 18, 29, 36};
  EXPECT_EQ(hinges, expected);
  for (std::size_t k = 1; k < hinges.size(); ++k)
    EXPECT_LT(rel[hinges[k]] * rel[hinges[k - 1]], 0) << "hinges alternate between extrados and intrados";
}
