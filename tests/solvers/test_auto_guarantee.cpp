// The guarantee of `auto` (docs/solvers.md "Guarantee") on the reduced corpus: the shared
// FCLib files and a few problems exported from scenes by scripts/corpus.py (kept in
// tests/data/corpus, cold and warm-started). At each tolerance, whatever a member reaches
// from the same start, auto reaches. Time ratios are a benchmark's business
// (scripts/work_precision.py --corpus), not a unit test's: this checks the reaching.
#include <filesystem>

#include "solver_cases.hpp"

using namespace solver_cases;

namespace {

struct Case {
  std::string file;
  bool warm;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  for (const char* f : {"fclib-local_problem_test.hdf5", "faf-Capsules-i97-269.hdf5", "faf-Box_Stacks-i0035-31-0.hdf5",
                        "spheres-in-a-box-98-i10000-256-10.hdf5", "CubeH8.hdf5"})
    c.push_back({shared(f), false});
  std::vector<std::string> exported;
  for (const auto& e : std::filesystem::directory_iterator(std::string(MOREAU_SOURCE_DIR) + "/tests/data/corpus"))
    exported.push_back(e.path().string());
  std::sort(exported.begin(), exported.end());
  for (const auto& f : exported) {
    c.push_back({f, false});
    c.push_back({f, true});
  }
  return c;
}

}  // namespace

TEST(AutoGuarantee, ReachesEveryToleranceAMemberReaches) {
  int solved_by_some = 0, solved_by_auto = 0;
  for (const Case& c : cases()) {
    const auto prob = moreau::fclib::read(c.file);
    const moreau::LocalProblem& P = prob.local;
    const Eigen::VectorXd start = c.warm && prob.guess_r ? *prob.guess_r : Eigen::VectorXd::Zero(P.dim * P.contacts());
    for (double tol : {1e-4, 1e-8}) {
      std::string reached_by;
      for (const char* member : {"nlgs", "newton", "admm", "apgd"}) {
        Eigen::VectorXd r = start, u;
        const auto rep = make(member, {{"tolerance", tol}, {"max_iterations", std::string(member) == "newton" ? 200 : 20000}})
                             ->solve(P, r, u);
        if (rep.converged) {
          reached_by = member;
          break;
        }
      }
      Eigen::VectorXd r = start, u;
      const auto rep = make("auto", {{"tolerance", tol}})->solve(P, r, u);
      expect_honest(P, r, u, rep, tol, "auto");
      const std::string what = std::filesystem::path(c.file).filename().string() + (c.warm ? " (warm)" : "") +
                               " at " + std::to_string(tol);
      if (!reached_by.empty()) {
        ++solved_by_some;
        EXPECT_TRUE(rep.converged) << what << ": " << reached_by << " reaches it, auto stops at " << rep.error;
      }
      if (rep.converged) ++solved_by_auto;
    }
  }
  EXPECT_GE(solved_by_auto, solved_by_some);
  std::printf("reduced corpus: %d problem-tolerance pairs solved by some member, %d by auto\n", solved_by_some, solved_by_auto);
}
