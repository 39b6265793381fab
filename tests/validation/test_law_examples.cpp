// The contact laws' example scenes (configs/, docs/laws.md "Examples") do what the docs
// say, on short runs (the first steps, where it shows):
//  - mortar_wall_2d: on a table tilted 45° (tan 45° = 1 > μ = 0.6 of the joints) the
//    mortared wall stands, a few joints cracking; the same wall without mortar (dry joints
//    of the same μ, `make_law_scenes.py --dry wall`) slides apart;
//  - bonded_beam_2d: three-point bending damages the bottom row at mid-span first (the
//    most stretched fibre), nothing in the upper half;
//  - wet_pile_3d: the column of wet spheres stands; the dry one (`--dry pile`) slumps.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

std::string config(const std::string& name) {
  std::ifstream f(std::string(MOREAU_CONFIGS) + "/" + name);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  if (p == std::string::npos) throw std::logic_error("no " + from);
  return text.replace(p, from.size(), to);
}

SceneRun run_steps(const std::string& name, const std::string& scene, int steps) {
  const auto dir = scratch_dir(name);
  const auto path = write_file(dir, "scene.json", scene);
  Result r = run_moreau({"run", path.string(), "--out", "out.h5", "--steps", std::to_string(steps), "--quiet"}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  SceneRun run;
  run.file = (dir / "out.h5").string();
  run.frames = frame_names(run.file);
  return run;
}

/// The largest distance a moving body travelled between the first and last frames.
double largest_move(const SceneRun& run, int dim) {
  const auto a = run.at(run.frames.front(), "position"), b = run.at(run.frames.back(), "position");
  double most = 0;
  for (std::size_t i = 0; i + dim <= a.size(); i += dim) {
    double s = 0;
    for (int k = 0; k < dim; ++k) s += (b[i + k] - a[i + k]) * (b[i + k] - a[i + k]);
    most = std::max(most, std::sqrt(s));
  }
  return most;
}

}  // namespace

TEST(LawExamples, MortarWallStandsTiltedWhereTheDryWallSlidesApart) {
  const std::string wall = config("mortar_wall_2d.json");
  const std::string mortar =
      R"({"type": "cohesive", "tensile_strength": 10000.0, "cohesion": 20000.0, "friction": 0.6, "area": 0.04})";
  SceneRun bonded = run_steps("mortar_wall", wall, 300);
  SceneRun dry = run_steps("dry_wall", replaced(wall, mortar, R"({"type": "coulomb", "friction": 0.6})"), 300);
  const double broken = bonded.at(bonded.frames.back(), "laws/broken")[0], bonds = bonded.at(bonded.frames.back(), "laws/bonds")[0];
  std::printf("mortar wall tilted 45 deg, 0.3 s: largest move %.2e m, %g of %g bonds broken; dry wall: largest move %.3f m\n",
              largest_move(bonded, 2), broken, broken + bonds, largest_move(dry, 2));
  EXPECT_LT(largest_move(bonded, 2), 1e-6) << "the mortared wall stands";
  EXPECT_LT(broken, 0.05 * (broken + bonds)) << "a few joints crack";
  EXPECT_GT(largest_move(dry, 2), 0.01) << "the dry wall slides apart";
}

TEST(LawExamples, BondedBeamIsDamagedFirstAtTheBottomOfMidSpan) {
  SceneRun run = run_steps("bonded_beam", config("bonded_beam_2d.json"), 800);
  const std::string& last = run.frames.back();
  const auto damage = run.at(last, "contacts/damage"), point = run.at(last, "contacts/point");
  const auto bond = run.at(last, "contacts/bond");
  // Disks of radius r = 5 mm, rows √3 r apart: the beam's upper half is above 2 √3 r + r.
  const double r = 0.005, top_half = r + 2 * std::sqrt(3.0) * r;
  std::vector<std::size_t> order(damage.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return damage[a] > damage[b]; });
  // Five, not six: the converged answer (`nlgs` or `auto` at 1e-6) has the five most damaged
  // bonds in the bottom row (x = 0, ±0.020, ±0.040; D 0.84, 0.75, 0.54) and its sixth in the
  // second row (x = 0.005, y = 0.011, D 0.39); which one the default 1e-3 ranks sixth depends
  // on which member `auto` runs.
  ASSERT_GE(order.size(), 5u);
  std::printf("bonded beam, step 800: most damaged bonds (x, y, D):");
  for (std::size_t k = 0; k < 5; ++k) {
    const std::size_t c = order[k];
    std::printf(" (%.4f, %.4f, %.3f)", point[2 * c], point[2 * c + 1], damage[c]);
    EXPECT_GT(damage[c], 0.3);
    EXPECT_LT(std::abs(point[2 * c]), 12 * r) << "near mid-span";
    EXPECT_LT(point[2 * c + 1], r) << "in the bottom row (sagging below its centres)";
  }
  std::printf("\n");
  for (std::size_t c = 0; c < damage.size(); ++c) {
    if (point[2 * c + 1] > top_half) EXPECT_EQ(damage[c], 0) << "upper half, x = " << point[2 * c];
    EXPECT_NE(bond[c], 2) << "nothing broken yet";
  }
}

TEST(LawExamples, WetColumnStandsWhereTheDryOneSlumps) {
  const std::string pile = config("wet_pile_3d.json");
  SceneRun wet = run_steps("wet_pile", pile, 300);
  SceneRun dry = run_steps("dry_pile", replaced(pile, R"({"type": "wet", "adhesion": 0.015, "rupture_distance": 0.0005, "friction": 0.4})",
                                                R"({"type": "coulomb", "friction": 0.4})"), 300);
  auto top = [](const SceneRun& run) {
    const auto p = run.at(run.frames.back(), "position");
    double z = 0;
    for (std::size_t i = 2; i < p.size(); i += 3) z = std::max(z, p[i]);
    return z;
  };
  // 10 layers of spheres of radius 5 mm, 2 % apart: the top centre starts at 0.0968 m.
  std::printf("column of 10 layers, 0.15 s: wet top at %.4f m, dry top at %.4f m\n", top(wet), top(dry));
  EXPECT_GT(top(wet), 0.094) << "the wet column stands (its 2 % gaps closed)";
  EXPECT_LT(top(dry), 0.08) << "the dry column slumps";
}
