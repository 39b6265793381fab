// The scene key `export_problems`: the local problems a run solved, written as FCLib files,
// are the problems the run solved. Checked against the run's own output (the impulses of
// the same step), by re-solving them with `moreau fclib solve`, and whichever way the
// solver saw W (read from the matrix, or exchanged through body velocities).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <filesystem>
#include <moreau/contact_error.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "h5_read.hpp"
#include "kernel/fclib/fclib.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

constexpr double kRunTolerance = 1e-10;

std::string solver(const std::string& exchange) {
  return R"({"type": "nlgs", "tolerance": 1e-10, "max_iterations": 100000, "exchange": ")" + exchange + R"("})";
}

/// Two disks, one on a floor and one leaning on it, touching from the start (so step 1 has
/// contacts): 2 contacts, 4 unknowns for 6 body unknowns, W positive definite.
std::string scene_2d(const std::string& solver_section, const std::string& export_section, double lift = 0) {
  return R"({
  "format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 1e-3, "duration": 0.02},
  "gravity": [0, -9.81],
  "materials": {"wood": {"density": 700}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, 0], "contactors": [{"shape": "segment", "length": 2, "thickness": 0.02, "group": "wall"}]},
    {"name": "a", "material": "wood", "position": [0, )" + std::to_string(0.110001 + lift) + R"(], "contactors": [{"shape": "disk", "radius": 0.1, "group": "grain"}]},
    {"name": "b", "material": "wood", "position": [0.05, )" + std::to_string(0.303651 + 2 * lift) + R"(], "contactors": [{"shape": "disk", "radius": 0.1, "group": "grain"}]}
  ],
  "interactions": [{"groups": ["grain", "wall"], "law": "rough"}, {"groups": ["grain", "grain"], "law": "rough"}],
  "detection": {"alert": 0.01},
  "solver": )" + solver_section + R"(,
  "export_problems": )" + export_section + R"(,
  "output": {"file": "out.h5", "every": 1}
})";
}

/// Two spheres on a plane, the second leaning on the first off-axis: 2 contacts, 6
/// unknowns for 12 body unknowns.
std::string scene_3d(const std::string& solver_section, const std::string& export_section) {
  return R"({
  "format": "moreau-scene/1", "dimension": 3,
  "time": {"step": 1e-3, "duration": 0.02},
  "gravity": [0, 0, -9.81],
  "materials": {"steel": {"density": 7800}},
  "laws": {"rough": {"type": "coulomb", "friction": 0.4}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "floor"}]},
    {"name": "a", "material": "steel", "position": [0, 0, 0.050001], "contactors": [{"shape": "sphere", "radius": 0.05, "group": "ball"}]},
    {"name": "b", "material": "steel", "position": [0.03, 0.02, 0.143275], "contactors": [{"shape": "sphere", "radius": 0.05, "group": "ball"}]}
  ],
  "interactions": [{"groups": ["ball", "floor"], "law": "rough"}, {"groups": ["ball", "ball"], "law": "rough"}],
  "detection": {"alert": 0.01},
  "solver": )" + solver_section + R"(,
  "export_problems": )" + export_section + R"(,
  "output": {"file": "out.h5", "every": 1}
})";
}

struct SceneRun {
  fs::path dir;
  Result result;
  std::string output() const { return (dir / "out.h5").string(); }
  std::string problem(long step) const {
    char name[48];
    std::snprintf(name, sizeof name, "scene-step%08ld.hdf5", step);
    return (dir / "problems" / name).string();
  }
};

SceneRun run_scene(const std::string& name, const std::string& text) {
  SceneRun r;
  r.dir = scratch_dir("export_" + name);
  write_file(r.dir, "scene.json", text);
  r.result = run_moreau({"run", "scene.json", "--quiet"}, r.dir);
  return r;
}

std::string frame(long step, const std::string& what) {
  char name[64];
  std::snprintf(name, sizeof name, "/frames/%08ld/contacts/%s", step, what.c_str());
  return name;
}

Eigen::VectorXd eigen(const std::vector<double>& v) { return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())); }

/// The exported problem of `step` is the one the run solved at that step.
void check_against_the_run(const SceneRun& run, long step, int dim) {
  SCOPED_TRACE("step " + std::to_string(step) + " of " + run.dir.string());
  const std::string path = run.problem(step);
  ASSERT_TRUE(fs::exists(path));
  const moreau::fclib::Problem p = moreau::fclib::read(path);
  const moreau::LocalProblem& P = p.local;
  ASSERT_FALSE(p.global);
  EXPECT_EQ(P.dim, dim);
  const Eigen::Index nc = P.contacts(), n = dim * nc;
  ASSERT_GT(nc, 0);
  EXPECT_EQ(P.W.rows(), n);
  EXPECT_EQ(P.W.cols(), n);
  EXPECT_EQ(P.q.size(), n);
  EXPECT_EQ(read_doubles(path, "/fclib_local/spacedim"), std::vector<double>{static_cast<double>(dim)});

  // W = H M⁻¹ Hᵀ: symmetric positive semidefinite within rounding.
  const Eigen::MatrixXd W(P.W);
  const double scale = W.cwiseAbs().maxCoeff();
  EXPECT_LE((W - W.transpose()).cwiseAbs().maxCoeff(), 1e-13 * scale);
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (W + W.transpose())).eigenvalues();
  EXPECT_GE(eig.minCoeff(), -1e-12 * scale);

  // The run's impulses of that step (output frame `step`, local frame, normal first) are
  // the file's /solution/r, and they solve the exported problem at the run's tolerance.
  const Eigen::VectorXd impulses = eigen(read_doubles(run.output(), frame(step, "impulse")));
  ASSERT_EQ(impulses.size(), n);
  const Eigen::VectorXd stored = eigen(read_doubles(path, "/solution/r"));
  EXPECT_EQ(stored, impulses);
  const Eigen::VectorXd u = P.W * stored + P.q;
  EXPECT_LE(moreau::natural_map_error(P, stored, u), kRunTolerance * 1.01);
  EXPECT_LT((eigen(read_doubles(path, "/solution/u")) - u).norm(), 1e-14 * (1 + u.norm()));

  // The warm start is what the run started from: zero at the first step, else the previous
  // step's impulses (same contacts here, in the same order).
  ASSERT_TRUE(p.guess_r.has_value());
  if (step == 1) {
    EXPECT_EQ(p.guess_r->cwiseAbs().maxCoeff(), 0.0);
  } else if (read_doubles(run.output(), frame(step - 1, "bodies")) == read_doubles(run.output(), frame(step, "bodies"))) {
    EXPECT_EQ(*p.guess_r, eigen(read_doubles(run.output(), frame(step - 1, "impulse"))));
  }

  // Solved again from scratch by another code path (`moreau fclib solve`, nlgs over W, from
  // zero): W is positive definite here, so the solution is the run's, within tolerances.
  ASSERT_GT(eig.minCoeff(), 1e-6 * scale) << "the comparison of impulses needs a unique solution";
  const fs::path sol = run.dir / ("solution" + std::to_string(step) + ".hdf5");
  Result r = run_moreau({"fclib", "solve", path, "--solver", "nlgs", "--tol", "1e-13", "--max-iter", "100000",
                         "--solution", sol.string()}, run.dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto line = nlohmann::json::parse(r.out);
  EXPECT_TRUE(line["converged"].get<bool>()) << r.out;
  EXPECT_EQ(line["contacts"], nc);
  const Eigen::VectorXd again = eigen(read_doubles(sol.string(), "/solution/r"));
  // |Δr| ≲ (run tolerance) ‖q‖ / λ_min(W).
  EXPECT_LE((again - impulses).norm(), 10 * kRunTolerance * P.q.norm() / eig.minCoeff() + 1e-14) << again.transpose() << "\n"
                                                                                              << impulses.transpose();
}

}  // namespace

TEST(ExportProblems, TwoDimensionalProblemIsTheOneTheRunSolved) {
  const SceneRun run = run_scene("2d", scene_2d(solver("bodies"), R"({"steps": [20, 1]})"));
  ASSERT_EQ(run.result.code, 0) << run.result.err;
  EXPECT_NE(run.result.out.find("exported 2 FCLib problems to " + (run.dir / "problems").string() + " (steps 1, 20)"),
            std::string::npos) << run.result.out;
  check_against_the_run(run, 1, 2);
  check_against_the_run(run, 20, 2);
  // 2D problems are 2D FCLib problems: two unknowns per contact.
  EXPECT_EQ(moreau::fclib::read(run.problem(20)).local.W.rows(), 2 * 2);
}

TEST(ExportProblems, ThreeDimensionalProblemIsTheOneTheRunSolved) {
  const SceneRun run = run_scene("3d", scene_3d(solver("w"), R"({"steps": [1, 20]})"));
  ASSERT_EQ(run.result.code, 0) << run.result.err;
  check_against_the_run(run, 1, 3);
  check_against_the_run(run, 20, 3);
}

TEST(ExportProblems, SameProblemWhetherTheSolverReadsWOrExchangesThroughBodies) {
  // At step 1 both runs start from the same configuration, so their problems agree to
  // rounding; later steps follow two solvers' answers, which agree to the tolerance.
  for (int dim : {2, 3}) {
    SCOPED_TRACE("dimension " + std::to_string(dim));
    auto scene = [&](const std::string& exchange) {
      const std::string exp = R"({"steps": [1, 20]})";
      return dim == 2 ? scene_2d(solver(exchange), exp) : scene_3d(solver(exchange), exp);
    };
    const SceneRun by_w = run_scene("w" + std::to_string(dim), scene("w"));
    const SceneRun by_bodies = run_scene("bodies" + std::to_string(dim), scene("bodies"));
    ASSERT_EQ(by_w.result.code, 0) << by_w.result.err;
    ASSERT_EQ(by_bodies.result.code, 0) << by_bodies.result.err;
    for (auto [step, tol] : {std::pair{1L, 1e-14}, std::pair{20L, 1e-7}}) {
      const auto a = moreau::fclib::read(by_w.problem(step)).local, b = moreau::fclib::read(by_bodies.problem(step)).local;
      ASSERT_EQ(a.contacts(), b.contacts());
      const Eigen::MatrixXd Wa(a.W), Wb(b.W);
      EXPECT_LE((Wa - Wb).cwiseAbs().maxCoeff(), tol * Wa.cwiseAbs().maxCoeff()) << "step " << step;
      EXPECT_LE((a.q - b.q).cwiseAbs().maxCoeff(), tol * a.q.cwiseAbs().maxCoeff()) << "step " << step;
      EXPECT_EQ(a.mu, b.mu);
    }
  }
}

TEST(ExportProblems, EveryNthStepBesideTheOutputFileAtomically) {
  const fs::path dir = scratch_dir("export_every");
  write_file(dir, "scene.json", scene_2d(solver("bodies"), R"({"every": 10, "directory": "lcp"})"));
  Result r = run_moreau({"run", "scene.json", "--quiet", "--out", "sub/run.h5"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  // Relative to the output file's folder (--out moved it), not the working folder.
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "sub" / "lcp")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"scene-step00000010.hdf5", "scene-step00000020.hdf5"}));  // no temporaries left
  EXPECT_FALSE(fs::exists(dir / "lcp"));
}

TEST(ExportProblems, StepsWithoutEnoughContactsWriteNothingAndSaySo) {
  // Lifted 0.2 m: the disks fall freely for the first steps.
  const SceneRun run = run_scene("none", scene_2d(solver("bodies"), R"({"steps": [1, 2], "min_contacts": 1})", 0.2));
  ASSERT_EQ(run.result.code, 0) << run.result.err;
  EXPECT_NE(run.result.out.find("exported 0 FCLib problems"), std::string::npos) << run.result.out;
  EXPECT_NE(run.result.out.find("nothing written for steps 1, 2 (fewer than 1 contact)"), std::string::npos) << run.result.out;
  EXPECT_TRUE(fs::is_empty(run.dir / "problems"));
  // min_contacts: 3 is more than this scene ever has.
  const SceneRun few = run_scene("few", scene_2d(solver("bodies"), R"({"steps": [5], "min_contacts": 3})"));
  ASSERT_EQ(few.result.code, 0) << few.result.err;
  EXPECT_NE(few.result.out.find("nothing written for step 5 (fewer than 3 contacts)"), std::string::npos) << few.result.out;
  // A run shorter than the scene says which steps it did not reach.
  const fs::path dir = scratch_dir("export_short");
  write_file(dir, "scene.json", scene_2d(solver("bodies"), R"({"steps": [5, 15]})"));
  Result r = run_moreau({"run", "scene.json", "--quiet", "--steps", "10"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("(steps 5); step 15 not run"), std::string::npos) << r.out;
}

TEST(ExportProblems, BadKeysExitTwoNamingThePointer) {
  struct Case {
    std::string section, pointer, message;
  };
  const std::vector<Case> cases{
      {R"({"steps": [10, -3]})", "at /export_problems/steps/1: ", "steps are counted from 1"},
      {R"({"steps": [0]})", "at /export_problems/steps/0: ", "steps are counted from 1"},
      {R"({"steps": [2.5]})", "at /export_problems/steps/0: ", "expected a step number"},
      {R"({"steps": [21]})", "at /export_problems/steps/0: ", "after the scene's last step 20"},
      {R"({"steps": []})", "at /export_problems/steps: ", "at least one step"},
      {R"({"steps": [1], "every": 5})", "at /export_problems: ", "either \"steps\" or \"every\", not both"},
      {R"({"directory": "p"})", "at /export_problems: ", "missing \"steps\""},
      {R"({"every": 0})", "at /export_problems/every: ", "out of range"},
      {R"({"every": 100})", "at /export_problems/every: ", "exports nothing"},
      {R"({"steps": [1], "min_contacts": 0})", "at /export_problems/min_contacts: ", "out of range"},
      {R"({"steps": [1], "directry": "p"})", "at /export_problems/directry: ", "did you mean \"directory\""},
      {R"("problems")", "at /export_problems: ", "expected an object"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.section);
    const fs::path dir = scratch_dir("export_bad");
    write_file(dir, "scene.json", scene_2d(solver("bodies"), c.section));
    for (const char* command : {"check", "run"}) {
      Result r = run_moreau({command, "scene.json"}, dir);
      EXPECT_EQ(r.code, 2) << command;
      EXPECT_NE(r.err.find("scene.json: " + c.pointer), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "out.h5"));  // bad input leaves no output
    EXPECT_FALSE(fs::exists(dir / "problems"));
  }
  // A scene without interactions has no problems to export.
  const fs::path dir = scratch_dir("export_no_contacts");
  write_file(dir, "scene.json", R"({"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.01, "duration": 0.1},
    "bodies": [{"name": "b", "mass": 1, "inertia": 1}], "export_problems": {"every": 1}})");
  Result r = run_moreau({"check", "scene.json"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /export_problems: the scene has no interactions"), std::string::npos) << r.err;
  // A folder that cannot be made (a file has its name) is bad input too, found before the run.
  const fs::path dir2 = scratch_dir("export_blocked");
  write_file(dir2, "scene.json", scene_2d(solver("bodies"), R"({"steps": [1], "directory": "taken"})"));
  write_file(dir2, "taken", "a file");
  r = run_moreau({"run", "scene.json", "--quiet"}, dir2);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("at /export_problems/directory: cannot create the folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir2 / "out.h5"));
}

TEST(ExportProblems, TheReaderTakesTheGuessButNeverTheSolution) {
  // A solver given an exported file must not start from the run's answer.
  moreau::LocalProblem p;
  p.dim = 2;
  p.W = Eigen::SparseMatrix<double, Eigen::RowMajor>(2, 2);
  p.W.insert(0, 0) = 2;
  p.W.insert(1, 1) = 3;
  p.q = Eigen::Vector2d(-1, 0.2);
  p.mu = Eigen::VectorXd::Constant(1, 0.5);
  const Eigen::VectorXd answer = Eigen::Vector2d(0.5, -0.2 / 3), guess = Eigen::Vector2d(0.1, 0);
  const fs::path dir = scratch_dir("export_reader");
  const std::string only_solution = (dir / "a.hdf5").string(), both = (dir / "b.hdf5").string();
  moreau::fclib::write_local(only_solution, p, {"t", "d", ""}, nullptr, &answer);
  moreau::fclib::write_local(both, p, {"t", "d", ""}, &guess, &answer);
  EXPECT_FALSE(moreau::fclib::read(only_solution).guess_r.has_value());
  const auto b = moreau::fclib::read(both);
  ASSERT_TRUE(b.guess_r.has_value());
  EXPECT_EQ(*b.guess_r, guess);
  EXPECT_TRUE(Eigen::MatrixXd(b.local.W).isApprox(Eigen::MatrixXd(p.W)));
  EXPECT_EQ(b.local.q, p.q);
  EXPECT_LT(eigen(read_doubles(both, "/solution/u")).norm(), 1e-15);  // u = W r + q, recomputed by the writer
  EXPECT_FALSE(fs::exists(both + ".part"));
}

TEST(ExportProblems, TheExampleSceneExportsItsSteps) {
  // configs/export_problems_2d.json, as tests/configs runs it (its first 200 steps).
  const fs::path dir = scratch_dir("export_config");
  Result r = run_moreau({"run", std::string(MOREAU_SOURCE_DIR) + "/configs/export_problems_2d.json", "--quiet", "--steps",
                         "200", "--out", (dir / "out.h5").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("(steps 100, 200); step 300 not run"), std::string::npos) << r.out;
  for (long step : {100, 200}) {
    char name[64];
    std::snprintf(name, sizeof name, "export_problems_2d-step%08ld.hdf5", step);
    const std::string path = (dir / "problems" / name).string();
    const auto p = moreau::fclib::read(path);
    EXPECT_EQ(p.local.dim, 2);
    EXPECT_GE(p.local.contacts(), 9);  // the pyramid's 9 contacts, then the side walls'
    Result s = run_moreau({"fclib", "solve", path, "--tol", "1e-8"}, dir);
    ASSERT_EQ(s.code, 0) << s.err;
    EXPECT_TRUE(nlohmann::json::parse(s.out)["converged"].get<bool>()) << s.out;
  }
}
