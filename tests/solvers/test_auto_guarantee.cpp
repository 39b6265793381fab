// The guarantee of `auto` (docs/solvers.md "Guarantee") on the reduced corpus: the shared
// FCLib files and a few problems exported from scenes by scripts/corpus.py (kept in
// tests/data/corpus, cold and warm-started), at tolerances 1e-4 and 1e-8:
// - whatever a member reaches from the same start, auto reaches;
// - auto's counted work (SolverReport::work, plugins/solver/work.hpp) is at most k times
//   the least counted work of a member that reaches the tolerance alone from that start.
// Counted work is deterministic (sizes and iteration counts only), so this is a test of the
// rule, not of the machine; how well it predicts CPU time is measured by
// moreau_bench_portfolio (docs/solvers.md "Corpus and guarantee").
#include <filesystem>

#include "solver_cases.hpp"

using namespace solver_cases;

namespace {

/// The k that auto achieves (docs/solvers.md "Guarantee"; scripts/guarantee_study.py reads
/// its default --k here). By construction (the floor, plugins/solver/auto/floor.hpp) auto's
/// work is at most K·(L + s) + one slice + rule 2b's Newton steps, L the least work of a
/// member alone, s one of its iterations, K that member's: with a factorisation 4.5 for
/// NLGS and APGD, 8 for Newton and ADMM; without, 4. Measured (branch i15-k4 on main
/// b144f6a): on the whole reduced corpus (scripts/guarantee_study.py, 258 pairs) the worst
/// is 3.88 at 1e-4 (fclib-local_problem_test) and 4.69 at 1e-8 (dense disks, μ 0.3, step
/// 600, cold: Newton alone in 1.4·10⁷); that problem is in tests/data/corpus too (the other
/// files there are older exports than the corpus's), so on this test's 50 pairs the worst
/// is the same 4.69. The 1.3 % above 4.69 allow for another compiler's rounding moving an
/// iteration count. Fails with 4.65.
constexpr double stated_k = 4.75;

/// auto's members, each run alone with auto's caps (max_iterations 20000; Newton:
/// newton_max_iterations 200, `newton`'s own default, each step a factorisation).
constexpr const char* members[] = {"nlgs", "apgd", "newton", "admm"};

struct Case {
  std::string file;
  bool warm;
};

struct Outcome {
  std::string what;            ///< problem (warm) at tolerance
  std::string least_by;        ///< the member with the least work that reaches it ("": none)
  double least_work = 0;       ///< its work
  double next_work = 0;        ///< the least work of another member that reaches it (0: none)
  double auto_work = 0;
  bool auto_converged = false;
  double auto_error = 0;
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

/// Every member and auto on every case and tolerance, once for both tests (the members'
/// runs are most of this file's time).
const std::vector<Outcome>& outcomes() {
  static const std::vector<Outcome> all = [] {
    std::vector<Outcome> out;
    for (const Case& c : cases()) {
      const auto prob = moreau::fclib::read(c.file);
      const moreau::LocalProblem& P = prob.local;
      const Eigen::VectorXd start = c.warm && prob.guess_r ? *prob.guess_r : Eigen::VectorXd::Zero(P.dim * P.contacts());
      for (double tol : {1e-4, 1e-8}) {
        Outcome o;
        char buf[32];
        std::snprintf(buf, sizeof buf, " at %g", tol);
        o.what = std::filesystem::path(c.file).filename().string() + (c.warm ? " (warm)" : "") + buf;
        for (const char* member : members) {
          Eigen::VectorXd r = start, u;
          const auto rep = make(member, {{"tolerance", tol}, {"max_iterations", std::string(member) == "newton" ? 200 : 20000}})
                               ->solve(P, r, u);
          EXPECT_GT(rep.work, 0) << member << " counts no work on " << o.what;
          if (!rep.converged) continue;
          if (o.least_by.empty() || rep.work < o.least_work) {
            o.next_work = o.least_work;
            o.least_by = member;
            o.least_work = rep.work;
          } else if (o.next_work == 0 || rep.work < o.next_work) {
            o.next_work = rep.work;
          }
        }
        Eigen::VectorXd r = start, u;
        const auto rep = make("auto", {{"tolerance", tol}})->solve(P, r, u);
        expect_honest(P, r, u, rep, tol, "auto");
        o.auto_work = rep.work;
        o.auto_converged = rep.converged;
        o.auto_error = rep.error;
        out.push_back(o);
      }
    }
    return out;
  }();
  return all;
}

}  // namespace

TEST(AutoGuarantee, ReachesEveryToleranceAMemberReaches) {
  int solved_by_some = 0, solved_by_auto = 0;
  for (const Outcome& o : outcomes()) {
    if (!o.least_by.empty()) {
      ++solved_by_some;
      EXPECT_TRUE(o.auto_converged) << o.what << ": " << o.least_by << " reaches it, auto stops at " << o.auto_error;
    }
    if (o.auto_converged) ++solved_by_auto;
  }
  EXPECT_GE(solved_by_auto, solved_by_some);
  std::printf("reduced corpus: %d problem-tolerance pairs solved by some member, %d by auto\n", solved_by_some, solved_by_auto);
}

TEST(AutoGuarantee, WorkWithinKTimesTheLeastWorkOfAMember) {
  double worst = 0;
  std::string worst_what;
  std::vector<double> ratios;
  double worst_dominant = 0;  // where one member clearly dominates: under half the next one's work
  int dominant = 0, dominant_within_1 = 0, dominant_within_1_5 = 0;
  for (const Outcome& o : outcomes()) {
    if (o.least_by.empty()) continue;
    ASSERT_GT(o.least_work, 0) << o.what;
    const double ratio = o.auto_work / o.least_work;
    ratios.push_back(ratio);
    if (o.next_work == 0 || o.least_work <= 0.5 * o.next_work) {
      ++dominant;
      worst_dominant = std::max(worst_dominant, ratio);
      dominant_within_1 += ratio <= 1;
      dominant_within_1_5 += ratio <= 1.5;
    }
    std::printf("  %-60s least %-6s %10.4g  auto %10.4g  ratio %5.2f\n", o.what.c_str(), o.least_by.c_str(), o.least_work,
                o.auto_work, ratio);
    EXPECT_LE(ratio, stated_k) << o.what << ": auto's counted work " << o.auto_work << " is " << ratio << "× "
                               << o.least_by << "'s " << o.least_work << " (stated k " << stated_k << ")";
    if (ratio > worst) {
      worst = ratio;
      worst_what = o.what;
    }
  }
  ASSERT_FALSE(ratios.empty());
  std::sort(ratios.begin(), ratios.end());
  const auto within = [&](double k) { return std::count_if(ratios.begin(), ratios.end(), [k](double x) { return x <= k; }); };
  std::printf("counted work, auto / least member: median %.2f, worst %.2f (%s); within 1: %ld, 1.5: %ld, 2: %ld of %zu\n",
              ratios[ratios.size() / 2], worst, worst_what.c_str(), within(1.0), within(1.5), within(2.0), ratios.size());
  std::printf("where one member clearly dominates (under half the next member's work; %d pairs): worst %.2f, within 1: %d, 1.5: %d\n",
              dominant, worst_dominant, dominant_within_1, dominant_within_1_5);
}
