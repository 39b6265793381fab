// The time-stepper's stopping test (docs/solvers.md, "Stopping test") and honest
// reporting of the solves of a run (issue 15 points 5 and 7, issue 11's mass ratios).
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "run_scene.hpp"

using namespace moreau_test;

namespace {

/// The attribute `name` of /frames/FRAME/solver.
double solver_attr(const std::string& file, const std::string& frame, const char* name) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t a = H5Aopen_by_name(f, ("/frames/" + frame + "/solver").c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  double v = NAN;
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
  }
  H5Fclose(f);
  return v;
}

/// A 2D deposit: `n` disks (radius 5 mm ± 10 %, a fixed pseudo-random pattern) dropped in
/// a box, the given alert distance and solver block.
std::string deposit(int n, double alert, const std::string& solver, double heavy_ratio = 1, int steps = 400) {
  std::ostringstream s;
  const double r = 0.005, pitch = 2.2 * r;
  const int cols = 8;
  const double width = cols * pitch;
  s.precision(17);
  s << R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 5e-4, "duration": )" << steps * 5e-4 << R"(},
  "gravity": [0, -9.81],
  "materials": {"grain": {"density": 2600}, "heavy": {"density": )" << 2600 * heavy_ratio << R"(}},
  "laws": {"gg": {"type": "coulomb", "friction": 0.3}},
  "detection": {"alert": )" << alert << R"(},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, -0.005], "contactors": [{"shape": "segment", "length": 0.2, "thickness": 0.01, "group": "wall"}]},
    {"name": "left", "fixed": true, "position": [)" << -width / 2 - 0.005 << R"(, 0.1], "angle": 1.5707963267948966, "contactors": [{"shape": "segment", "length": 0.2, "thickness": 0.01, "group": "wall"}]},
    {"name": "right", "fixed": true, "position": [)" << width / 2 + 0.005 << R"(, 0.1], "angle": 1.5707963267948966, "contactors": [{"shape": "segment", "length": 0.2, "thickness": 0.01, "group": "wall"}]})";
  for (int k = 0; k < n; ++k) {
    const double jitter = std::sin(12.9898 * (k + 1)) * 0.1 * r;  // deterministic pattern
    const double radius = r * (1 + 0.1 * std::sin(78.233 * (k + 1)));
    s << ",\n    {\"name\": \"d" << k << "\", \"material\": \"" << (heavy_ratio != 1 && k % 10 == 0 ? "heavy" : "grain")
      << "\", \"position\": [" << -width / 2 + (k % cols + 0.5) * pitch + jitter << ", " << 1.1 * r + (k / cols) * pitch
      << "], \"contactors\": [{\"shape\": \"disk\", \"radius\": " << radius << ", \"group\": \"grain\"}]}";
  }
  s << R"(],
  "interactions": [{"groups": ["grain", "grain"], "law": "gg"}, {"groups": ["grain", "wall"], "law": "gg"}],
  "solver": )" << solver << R"(,
  "output": {"file": "out.h5", "every": 20, "display": "points"}
})";
  return s.str();
}

struct Summary {
  std::vector<double> iterations, worst_overlap;
  std::size_t contacts = 0;
};

Summary summarise(const SceneRun& run) {
  Summary s;
  for (const auto& fr : run.frames) {
    s.iterations.push_back(solver_attr(run.file, fr, "iterations"));
    const auto gap = run.at(fr, "contacts/gap");
    s.contacts = std::max(s.contacts, gap.size());
    double worst = 0;
    for (double g : gap) worst = std::min(worst, g);
    s.worst_overlap.push_back(-worst);
  }
  return s;
}

}  // namespace

TEST(Stopping, TheAlertDistanceLeavesOverlapsAndIterationsUnchanged) {
  // With ‖q‖ as the denominator, the open contacts of a larger alert (q_n = g/h each)
  // loosened the test on the closed ones. The time-stepper's denominator runs over the
  // approaching contacts only: a 4x larger alert adds open contacts, not a looser test.
  // NLGS sweeps the closed contacts in the same order either way: same iterations, same
  // overlaps. (`auto` counts its members' work relative to the problem's size, which the
  // open contacts change, so its choices may differ; its stopping test is the same.)
  const char* solver = R"({"type": "nlgs", "tolerance": 1e-4, "max_iterations": 5000})";
  const Summary small = summarise(run_scene("alert_small", deposit(40, 0.001, solver)));
  const Summary large = summarise(run_scene("alert_large", deposit(40, 0.004, solver)));
  ASSERT_EQ(small.iterations.size(), large.iterations.size());
  EXPECT_GT(large.contacts, small.contacts + 10) << "the larger alert lists more (open) contacts";
  for (std::size_t k = 0; k < small.iterations.size(); ++k) {
    EXPECT_EQ(small.iterations[k], large.iterations[k]) << "frame " << k;
    EXPECT_NEAR(small.worst_overlap[k], large.worst_overlap[k], 1e-6 * small.worst_overlap[k] + 1e-12) << "frame " << k;
  }
}

TEST(Stopping, AMissIsSaidAtOnceAndInTheSummary) {
  // nlgs capped at 2 sweeps cannot reach 1e-8 on a pile: a warning at the first miss (its
  // step, the error in scientific notation, the bodies of the worst contact) and the count
  // and worst error at the end, even with --quiet.
  const auto dir = scratch_dir("miss_report");
  const auto path = write_file(dir, "scene.json", deposit(30, 0.001, R"({"type": "nlgs", "tolerance": 1e-8, "max_iterations": 2})", 1, 200));
  Result r = run_moreau({"run", path.string(), "--out", "out.h5", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: step "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("above its tolerance 1.00e-08 after 2 iterations; largest residual at the contact of \""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("steps ended above the tolerance 1.00e-08 (first at step "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("worst error "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("0.000000"), std::string::npos) << "errors in scientific notation: " << r.err;
  // "on_failure": "stop": the run ends at the first miss, the error in scientific notation.
  const auto stop = write_file(dir, "stop.json", deposit(30, 0.001, R"({"type": "nlgs", "tolerance": 1e-8, "max_iterations": 2, "on_failure": "stop"})", 1, 200));
  Result s = run_moreau({"run", stop.string(), "--out", "stop.h5", "--quiet"}, dir);
  EXPECT_EQ(s.code, 1);
  EXPECT_NE(s.err.find("did not converge at step "), std::string::npos) << s.err;
  EXPECT_NE(s.err.find("e-"), std::string::npos) << s.err;
}

TEST(Stopping, MassRatioOfAMillionIsSolvedOrSaidLoudly) {
  // Issue 11: every tenth grain 10⁶ times denser. `auto` (NLGS, Newton, ADMM: the last two
  // scale each contact by its block of W, insensitive to mass ratios) reaches the tolerance
  // at nearly every step; a step it does not reach is counted in the summary with its error
  // and the bodies of the worst contact, and no light grain sinks into the floor.
  const auto dir = scratch_dir("mass_ratio");
  const auto path = write_file(dir, "scene.json", deposit(40, 0.001, R"({"type": "auto", "tolerance": 1e-4})", 1e6, 400));
  Result r = run_moreau({"run", path.string(), "--out", "out.h5"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const bool all = r.err.find("all converged to 1.00e-04") != std::string::npos;
  const auto miss = r.err.find("warning: contact solves: ");
  EXPECT_TRUE(all || miss != std::string::npos) << r.err;
  if (!all) {
    const long missed = std::stol(r.err.substr(miss + 25));
    // Measured: 10 of 400 (17 before auto's cost model; impacts of the heavy grains, where
    // Newton and ADMM stall near 5e-3 too); the bound guards against a regression, the
    // count is in docs/solvers.md.
    EXPECT_LE(missed, 15) << "steps above the tolerance out of 400: " << r.err;
    EXPECT_NE(r.err.find("largest residual at the contact of \"d"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("warning: step "), std::string::npos) << "the first miss is said at once: " << r.err;
    // Which steps and bodies failed (issue 11): the summary lists each missed step (up to
    // 20) with its error and the two bodies of its worst contact.
    const auto list = r.err.find("missed steps (error, contact with the largest residual):");
    ASSERT_NE(list, std::string::npos) << r.err;
    long listed = 0;
    for (auto p = r.err.find("\n    step ", list); p != std::string::npos; p = r.err.find("\n    step ", p + 1)) {
      ++listed;
      EXPECT_NE(r.err.substr(p, r.err.find('\n', p + 1) - p).find(", \"d"), std::string::npos) << "bodies named: " << r.err;
    }
    EXPECT_EQ(listed, std::min<long>(missed, 20)) << r.err;
  }
  const auto frames = frame_names((dir / "out.h5").string());
  const auto pos = read_doubles((dir / "out.h5").string(), "/frames/" + frames.back() + "/position");
  for (std::size_t b = 3; b < pos.size() / 2; ++b) EXPECT_GT(pos[2 * b + 1], 0.004) << "grain " << b - 3 << " sank into the floor";
  std::printf("%s\n", r.err.substr(r.err.find("contact solves")).c_str());
}

TEST(Stopping, AContactApproachingByARoundingResidueDoesNotStallTheSolve) {
  // configs/disks_in_box_2d.json with apgd's normal/tangent scaling at 1e-3: at step 56 the
  // only approaching contact approached by q_n = -1.4e-17 (‖q‖ = 16); divided by that, the
  // rounding of W r + q read as error 0.32 and the run missed steps 56 and 88. The
  // denominator's floor, √ε ‖q‖ (kernel/contact/stopping_scale.hpp), keeps the rounding
  // below 1e-8 in the error: no step misses.
  std::ifstream f(std::string(MOREAU_CONFIGS) + "/disks_in_box_2d.json");
  std::string scene{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  const auto at = scene.find("\"output\":");
  ASSERT_NE(at, std::string::npos);
  scene.insert(at, R"("solver": {"type": "apgd", "tolerance": 1e-3, "scaling": "normal_tangent"}, )");
  const auto dir = scratch_dir("rounding_residue");
  const auto path = write_file(dir, "scene.json", scene);
  Result r = run_moreau({"run", path.string(), "--out", "out.h5", "--steps", "100", "--quiet"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("above the tolerance"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("above its tolerance"), std::string::npos) << r.err;
}
