// NLGS on hand-made problems with known solutions, 2D and 3D.
#include <gtest/gtest.h>

#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>

#include "sim.hpp"

using moreau::LocalProblem;

namespace {

std::unique_ptr<moreau::Solver> nlgs(double tol = 1e-12, long max_it = 1000) {
  return moreau_test::create<moreau::Solver>("nlgs",
                                             {{"tolerance", tol}, {"max_iterations", max_it}, {"relaxation", 1.0},
                                              {"ordering", "given"}, {"seed", 1}, {"check_every", 1}, {"exchange", "w"},
                                               {"local_solver", "exact"}, {"local_iterations", 0}, {"local_tolerance", 1e-14}},
                                             moreau::BuildContext{});
}

LocalProblem problem(int d, const std::vector<double>& W, const std::vector<double>& q, const std::vector<double>& mu) {
  LocalProblem p;
  p.dim = d;
  const int n = static_cast<int>(q.size());
  p.W.resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (W[i * n + j] != 0) p.W.insert(i, j) = W[i * n + j];
  p.q = Eigen::Map<const Eigen::VectorXd>(q.data(), n);
  p.mu = Eigen::Map<const Eigen::VectorXd>(mu.data(), static_cast<Eigen::Index>(mu.size()));
  return p;
}

Eigen::VectorXd solve(const LocalProblem& p, moreau::SolverReport* rep = nullptr) {
  Eigen::VectorXd r, u;
  auto s = nlgs();
  auto report = s->solve(p, r, u);
  if (rep) *rep = report;
  EXPECT_TRUE(report.converged);
  EXPECT_NEAR(report.error, moreau::natural_map_error(p, r), 1e-15) << "the reported error is recomputed from r";
  return r;
}

}  // namespace

TEST(Nlgs, OpenContactHasNoImpulse) {
  auto r = solve(problem(2, {1, 0, 0, 1}, {0.5, 1}, {0.3}));
  EXPECT_EQ(r[0], 0);
  EXPECT_EQ(r[1], 0);
}

TEST(Nlgs, StickingAndSlidingIn2D) {
  // W = diag(1, 1): stick iff |q_t| ≤ μ |q_n|.
  auto stick = solve(problem(2, {1, 0, 0, 1}, {-1, 0.2}, {0.3}));
  EXPECT_NEAR(stick[0], 1, 1e-12);
  EXPECT_NEAR(stick[1], -0.2, 1e-12);
  auto slide = solve(problem(2, {1, 0, 0, 1}, {-1, 0.5}, {0.3}));
  EXPECT_NEAR(slide[0], 1, 1e-12);
  EXPECT_NEAR(slide[1], -0.3, 1e-12);
}

TEST(Nlgs, FrictionlessAndLargeFrictionIn3D) {
  auto smooth = solve(problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 1, -1}, {0.0}));
  EXPECT_NEAR(smooth[0], 0.5, 1e-12);
  EXPECT_EQ(smooth[1], 0);
  EXPECT_EQ(smooth[2], 0);
  auto rough = solve(problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 1, -1}, {5.0}));
  EXPECT_NEAR(rough[0], 0.5, 1e-12);
  EXPECT_NEAR(rough[1], -0.5, 1e-12);
  EXPECT_NEAR(rough[2], 0.5, 1e-12);
}

TEST(Nlgs, TwoCoupledContacts) {
  // Two frictionless contacts sharing a body: W = [[2, 1], [1, 2]], q = (−1, −1):
  // both closed, r = W⁻¹(1, 1) = (1/3, 1/3).
  auto r = solve(problem(2, {2, 0, 1, 0, 0, 2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2}, {-1, 0, -1, 0}, {0, 0}));
  EXPECT_NEAR(r[0], 1.0 / 3, 1e-10);
  EXPECT_NEAR(r[2], 1.0 / 3, 1e-10);
}

TEST(Nlgs, RedundantContactsStayFiniteAndHonest) {
  // Two identical contacts (singular W): the split of the impulse is not unique, the
  // sum is; the solver must stay finite and report an error computed from r.
  moreau::SolverReport rep;
  auto r = solve(problem(2, {1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1}, {-1, 0, -1, 0}, {0.5, 0.5}), &rep);
  EXPECT_TRUE(r.allFinite());
  EXPECT_NEAR(r[0] + r[2], 1.0, 1e-10);
}

TEST(Nlgs, NotConvergedIsReportedAsSuch) {
  auto s = nlgs(1e-30, 3);
  LocalProblem p = problem(2, {2, 0, 1, 0, 0, 2, 0, 1, 1, 0, 2, 0, 0, 1, 0, 2}, {-1, 0.3, -1, -0.2}, {0.3, 0.3});
  Eigen::VectorXd r, u;
  auto rep = s->solve(p, r, u);
  EXPECT_FALSE(rep.converged);
  EXPECT_EQ(rep.iterations, 3);
  EXPECT_TRUE(r.allFinite());
}
