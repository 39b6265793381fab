// `apgd` on the shared solver checks (solver_cases.hpp): hand-made problems with known
// answers, redundant contacts, mass ratios, q = 0, μ ≥ 1, non-convergence said honestly,
// warm starts; then the shared FCLib problems.
#include "apgd_core.hpp"
#include "factored_problem.hpp"
#include "solver_cases.hpp"

#include <algorithm>
#include <limits>

using namespace solver_cases;

TEST(Apgd, OpenContactHasNoImpulse) { open_contact("apgd"); }
TEST(Apgd, StickingAndSlidingIn2D) { stick_and_slide_2d("apgd"); }
TEST(Apgd, StickingAndSlidingIn3D) { stick_and_slide_3d("apgd"); }
TEST(Apgd, FrictionlessAndLargeFriction) { frictionless_and_large_friction("apgd"); }
TEST(Apgd, TwoCoupledContacts) { two_coupled_contacts("apgd"); }
TEST(Apgd, RedundantContactsStayFiniteAndHonest) { redundant_contacts("apgd"); }
TEST(Apgd, ZeroQ) { zero_q("apgd"); }
TEST(Apgd, MassRatio1e4AgreesWithNlgs) { mass_ratio("apgd", 1e-8); }
TEST(Apgd, RandomProblemsWithLargeFriction) { random_problems("apgd", 1e-8, 6, 4, 1.0); }
TEST(Apgd, NotConvergedIsReportedAsSuch) { not_converged("apgd"); }
TEST(Apgd, WarmStartAndEdgeCases) { warm_start("apgd"); }

TEST(Apgd, SharedFclibProblems) {
  for (const char* f : {"fclib-local_problem_test.hdf5", "faf-Capsules-i97-269.hdf5", "faf-Box_Stacks-i0035-31-0.hdf5",
                        "spheres-in-a-box-98-i10000-256-10.hdf5", "CubeH8.hdf5"})
    fclib_case("apgd", f, 1e-8, 100000);
}

namespace {
/// A cohesive-zone (`czm`) problem: a 3-row, 10-disk beam bonded by czm (66 bonds, μ = 2:
/// the law's cone that never binds, docs/laws.md), loaded in three-point bending, exported
/// at step 20 (`moreau run tests/data/apgd/bonded_beam_small_2d.json --out DIR/out.h5`,
/// nlgs at 1e-8 as the scene solver; configs/bonded_beam_2d.json cut to |x| < 0.05 m).
/// Every bond's answer is strictly inside its cone, so u = 0 there: a linear system with
/// W + diag(κ), κ the bonds' compliance, about 40 steps of an accelerated gradient. With
/// the De Saxcé shift μ‖u_T‖ at every contact the step was expansive (μ = 2): APGD stayed
/// at error 8e-3 (cold) and 2.4e-3 (warm) after 10⁴ steps; measured now: 127 steps cold,
/// 119 warm to 1e-8 (scalar scaling). 400 leaves room for either scaling.
void bonded_beam_czm(const std::string& name) {
  const auto prob = moreau::fclib::read(std::string(MOREAU_SOURCE_DIR) + "/tests/data/apgd/bonded_beam_small_2d-step00000020.hdf5");
  const auto& P = prob.local;
  ASSERT_EQ(P.contacts(), 66);
  ASSERT_TRUE(prob.guess_r.has_value());
  for (bool warm : {false, true})
    for (double tol : {1e-3, 1e-8}) {
      auto s = make(name, {{"tolerance", tol}, {"max_iterations", 400}});
      Eigen::VectorXd r = warm ? *prob.guess_r : Eigen::VectorXd::Zero(2 * P.contacts()), u;
      const SolverReport rep = s->solve(P, r, u);
      const std::string what = name + (warm ? " warm" : " cold") + " at " + std::to_string(tol);
      expect_honest(P, r, u, rep, tol, what);
      EXPECT_TRUE(rep.converged) << what << ": error " << rep.error << " after " << rep.iterations << " iterations";
    }
}
}  // namespace

TEST(Apgd, CohesiveZoneBondsInsideTheirConesConverge) { bonded_beam_czm("apgd"); }
TEST(ApgdNormalTangent, CohesiveZoneBondsInsideTheirConesConverge) { bonded_beam_czm("apgd:scaling=normal_tangent"); }

namespace {
/// N steps in one call against N/2 + N/2 with the state kept and `resume` set (`auto` runs
/// APGD in slices): the iterate, the extrapolated point, the Lipschitz estimate and the
/// momentum after both must be the same to the bit, whether the second call reuses the
/// packed products (`same_problem`) or packs them again. The tolerance is never reached,
/// so both run exactly N steps. (The answer r each call returns is its own best iterate:
/// the second call's best is over its own steps, which is why it is not compared here.)
void expect_resumed_run_is_one_run(const moreau::LocalProblem& P, moreau::apgd::Scaling scaling, const std::string& what) {
  constexpr long N = 40;
  moreau::apgd::Options o;
  o.tolerance = 1e-300;
  o.scaling = scaling;
  o.max_iterations = N;
  moreau::apgd::State one;
  o.state = &one;
  Eigen::VectorXd r1 = Eigen::VectorXd::Zero(P.q.size()), u1;
  EXPECT_EQ(moreau::apgd::solve(P, o, r1, u1).iterations, N) << what;
  for (bool same_problem : {false, true}) {
    moreau::apgd::State two;
    o.state = &two;
    o.max_iterations = N / 2;
    o.resume = o.same_problem = false;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(P.q.size()), u;
    long iterations = moreau::apgd::solve(P, o, r, u).iterations;
    o.resume = true;
    o.same_problem = same_problem;
    iterations += moreau::apgd::solve(P, o, r, u).iterations;
    const std::string w = what + (same_problem ? ", products kept" : ", products packed again");
    EXPECT_EQ(iterations, N) << w;
    EXPECT_EQ((two.x - one.x).norm(), 0.0) << w;
    EXPECT_EQ((two.y - one.y).norm(), 0.0) << w;
    EXPECT_EQ(two.L, one.L) << w;
    EXPECT_EQ(two.theta, one.theta) << w;
  }
}

/// N steps in one call against slices of 1–4 steps (`auto`'s floor cut the dense disks'
/// warm run into ~3600 slices of ~3 steps), as `auto` calls them outside a time step: error
/// from the iteration, no u (recompute_error = velocities = false). Resuming computes
/// nothing: the slices' counted work is the one call's (its start counted once in both),
/// and their best error is its. A slice ending on an earlier best iterate than its last is
/// the case that cost a product and an error evaluation before (the error at x is now kept
/// in the state): the problems here have such slices. With u wanted (a time step) each such
/// slice pays the product for it, counted. Returns the number of such slices.
int expect_sliced_run_counts_one_runs_work(const moreau::LocalProblem& P, moreau::apgd::Scaling scaling, const std::string& what) {
  constexpr long N = 60;
  moreau::apgd::Options o;
  o.tolerance = 1e-300;
  o.scaling = scaling;
  o.recompute_error = o.velocities = false;
  o.max_iterations = N;
  moreau::apgd::State one;
  o.state = &one;
  double work1 = 0;
  o.work = &work1;
  Eigen::VectorXd r1 = Eigen::VectorXd::Zero(P.q.size()), u1;
  const moreau::SolverReport rep1 = moreau::apgd::solve(P, o, r1, u1);
  EXPECT_EQ(rep1.iterations, N) << what;
  int earlier_best = 0;
  for (bool velocities : {false, true}) {
    moreau::apgd::State two;
    o.state = &two;
    o.velocities = velocities;
    double work = 0, best = std::numeric_limits<double>::infinity();
    o.work = &work;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(P.q.size()), u;
    long done = 0;
    earlier_best = 0;
    for (int slice = 0; done < N; ++slice) {
      o.max_iterations = std::min<long>(1 + slice % 4, N - done);
      o.resume = o.same_problem = slice > 0;
      const moreau::SolverReport rep = moreau::apgd::solve(P, o, r, u);
      done += rep.iterations;
      best = std::min(best, rep.error);
      if ((r - two.x).norm() > 0) ++earlier_best;
      r = two.x;  // as auto's own run: the next slice goes on from the state, r ignored
    }
    const std::string w = what + (velocities ? ", u wanted" : "");
    EXPECT_EQ((two.x - one.x).norm(), 0.0) << w;
    if (velocities)  // a slice ending on an earlier best recomputes its error with a fresh product: to rounding
      EXPECT_NEAR(best, rep1.error, 1e-12) << w;
    else
      EXPECT_EQ(best, rep1.error) << w;
    if (velocities && earlier_best > 0)
      EXPECT_GT(work, work1 * (1 + 1e-12)) << w << ": " << earlier_best << " products for u not counted";
    else
      EXPECT_NEAR(work, work1, 1e-12 * work1) << w << " (" << earlier_best << " slices ended on an earlier best)";
  }
  return earlier_best;
}
}  // namespace

TEST(Apgd, SlicedRunCountsTheUninterruptedRunsWork) {
  for (auto scaling : {moreau::apgd::Scaling::contact, moreau::apgd::Scaling::normal_tangent}) {
    const std::string sc = scaling == moreau::apgd::Scaling::contact ? "contact" : "normal_tangent";
    int earlier_best = 0;
    for (int d : {2, 3}) {
      auto P = factored_problem(d, 10, 2, 16, 51u + static_cast<unsigned>(d));
      earlier_best += expect_sliced_run_counts_one_runs_work(P, scaling, "with W, dim " + std::to_string(d) + ", " + sc);
      P.W.resize(0, 0);  // through the factor (packed once)
      earlier_best += expect_sliced_run_counts_one_runs_work(P, scaling, "through the factor, dim " + std::to_string(d) + ", " + sc);
    }
    const auto beam = moreau::fclib::read(std::string(MOREAU_SOURCE_DIR) + "/tests/data/apgd/bonded_beam_small_2d-step00000020.hdf5");
    earlier_best += expect_sliced_run_counts_one_runs_work(beam.local, scaling, "czm beam, " + sc);
    EXPECT_GT(earlier_best, 0) << sc << ": no slice ended on an earlier best iterate (the case tested)";
  }
}

TEST(Apgd, ResumedRunIsTheUninterruptedRun) {
  for (auto scaling : {moreau::apgd::Scaling::contact, moreau::apgd::Scaling::normal_tangent}) {
    const std::string sc = scaling == moreau::apgd::Scaling::contact ? "contact" : "normal_tangent";
    for (int d : {2, 3}) {
      auto P = factored_problem(d, 10, 2, 16, 51u + static_cast<unsigned>(d));
      expect_resumed_run_is_one_run(P, scaling, "with W, dim " + std::to_string(d) + ", " + sc);
      P.W.resize(0, 0);  // through the factor (packed)
      expect_resumed_run_is_one_run(P, scaling, "through the factor, dim " + std::to_string(d) + ", " + sc);
    }
    // The czm beam: bonds inside their cones (no shift) beside contacts on the boundary.
    const auto beam = moreau::fclib::read(std::string(MOREAU_SOURCE_DIR) + "/tests/data/apgd/bonded_beam_small_2d-step00000020.hdf5");
    expect_resumed_run_is_one_run(beam.local, scaling, "czm beam, " + sc);
  }
}

// The same checks with the step scaled per direction (`scaling: normal_tangent`: the
// normal and the tangential diagonal entries of W apart, the cone projected in that metric).
namespace {
const std::string normal_tangent = "apgd:scaling=normal_tangent";
}
TEST(ApgdNormalTangent, OpenContactHasNoImpulse) { open_contact(normal_tangent); }
TEST(ApgdNormalTangent, StickingAndSlidingIn2D) { stick_and_slide_2d(normal_tangent); }
TEST(ApgdNormalTangent, StickingAndSlidingIn3D) { stick_and_slide_3d(normal_tangent); }
TEST(ApgdNormalTangent, FrictionlessAndLargeFriction) { frictionless_and_large_friction(normal_tangent); }
TEST(ApgdNormalTangent, TwoCoupledContacts) { two_coupled_contacts(normal_tangent); }
TEST(ApgdNormalTangent, RedundantContactsStayFiniteAndHonest) { redundant_contacts(normal_tangent); }
TEST(ApgdNormalTangent, MassRatio1e4AgreesWithNlgs) { mass_ratio(normal_tangent, 1e-8); }
TEST(ApgdNormalTangent, RandomProblemsWithLargeFriction) { random_problems(normal_tangent, 1e-8, 6, 4, 1.0); }
TEST(ApgdNormalTangent, NotConvergedIsReportedAsSuch) { not_converged(normal_tangent); }
TEST(ApgdNormalTangent, WarmStartAndEdgeCases) { warm_start(normal_tangent); }

TEST(ApgdNormalTangent, StickingAndSlidingWithTangentialEntriesLargerThanTheNormal) {
  // One contact, W = diag(w_n, w_t, w_t) with w_t = 3.5 w_n (a sphere on the ground: its
  // rotation adds to the tangential entries): the scaling differs per direction, so the
  // cone must be projected in D's metric for the fixed point to be the Coulomb solution.
  // r_n = −q_n / w_n; sticking r_T = −q_T / w_t when ‖q_T‖ ≤ μ r_n w_t, else sliding
  // r_T = −μ r_n q_T / ‖q_T‖.
  const std::vector<double> W3 = {1, 0, 0, 0, 3.5, 0, 0, 0, 3.5};
  auto stick = solve(normal_tangent, problem(3, W3, {-1, 0.2, -0.1}, {0.3}));
  EXPECT_NEAR(stick[0], 1, 1e-8);
  EXPECT_NEAR(stick[1], -0.2 / 3.5, 1e-8);
  EXPECT_NEAR(stick[2], 0.1 / 3.5, 1e-8);
  auto slide = solve(normal_tangent, problem(3, W3, {-1, 3, -4}, {0.3}));
  EXPECT_NEAR(slide[0], 1, 1e-8);
  EXPECT_NEAR(slide[1], -0.18, 1e-8);
  EXPECT_NEAR(slide[2], 0.24, 1e-8);
  // 2D, w_t = 3 w_n, r_n = 2: sticks while |q_t| ≤ 0.3 · 2 · 3 = 1.8.
  const std::vector<double> W2 = {1, 0, 0, 3};
  auto stick2 = solve(normal_tangent, problem(2, W2, {-2, 1.5}, {0.3}));
  EXPECT_NEAR(stick2[0], 2, 1e-8);
  EXPECT_NEAR(stick2[1], -0.5, 1e-8);
  auto slide2 = solve(normal_tangent, problem(2, W2, {-2, 3}, {0.3}));
  EXPECT_NEAR(slide2[0], 2, 1e-8);
  EXPECT_NEAR(slide2[1], -0.6, 1e-8);
}

TEST(ApgdNormalTangent, SharedFclibProblems) {
  for (const char* f : {"fclib-local_problem_test.hdf5", "faf-Capsules-i97-269.hdf5", "faf-Box_Stacks-i0035-31-0.hdf5",
                        "spheres-in-a-box-98-i10000-256-10.hdf5", "CubeH8.hdf5"})
    fclib_case(normal_tangent, f, 1e-8, 100000);
}
