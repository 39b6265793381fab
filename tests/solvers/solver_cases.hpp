#pragma once
// Shared checks for the contact solvers: construction with the schema's defaults, the
// hand-made problems with known answers, random problems built as W = Hᵀ M⁻¹ H, and the
// shared FCLib files. Every solve is checked for honesty: a finite r, u = W r + q, an error
// equal to the natural-map error recomputed from r, converged exactly when error ≤ tol.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "kernel/fclib/fclib.hpp"
#include "kernel/scene/validate.hpp"
#include "registered_solver.hpp"
#include "sim.hpp"

namespace solver_cases {

using moreau::LocalProblem;
using moreau::SolverReport;

/// The registered solver `spec` with `params` over its schema's defaults. `spec` is a
/// name or "name:key=value,key=value" (values read as JSON, else as strings), so that every
/// check below also runs on a variant such as "nlgs:local_solver=desaxce".
inline std::unique_ptr<moreau::Solver> make(const std::string& spec, nlohmann::json params = nlohmann::json::object()) {
  const std::string name = spec.substr(0, spec.find(':'));
  if (name.size() < spec.size()) {
    std::string rest = spec.substr(name.size() + 1);
    while (!rest.empty()) {
      const std::string kv = rest.substr(0, rest.find(','));
      rest = kv.size() < rest.size() ? rest.substr(kv.size() + 1) : "";
      const auto eq = kv.find('=');
      const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
      if (!params.contains(key)) {
        const nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
        params[key] = parsed.is_discarded() ? nlohmann::json(value) : parsed;
      }
    }
  }
  return registered_solver(name, params, spec);
}

inline LocalProblem problem(int d, const std::vector<double>& W, const std::vector<double>& q, const std::vector<double>& mu) {
  LocalProblem p;
  p.dim = d;
  const int n = static_cast<int>(q.size());
  p.W.resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (W[i * n + j] != 0) p.W.insert(i, j) = W[i * n + j];
  p.W.makeCompressed();
  p.q = Eigen::Map<const Eigen::VectorXd>(q.data(), n);
  p.mu = Eigen::Map<const Eigen::VectorXd>(mu.data(), static_cast<Eigen::Index>(mu.size()));
  return p;
}

/// The honesty checks every solve must pass, whatever the outcome.
inline void expect_honest(const LocalProblem& p, const Eigen::VectorXd& r, const Eigen::VectorXd& u, const SolverReport& rep,
                          double tol, const std::string& what) {
  ASSERT_EQ(r.size(), p.dim * p.contacts()) << what;
  EXPECT_TRUE(r.allFinite()) << what;
  EXPECT_TRUE(u.allFinite()) << what;
  const Eigen::VectorXd u2 = p.W * r + p.q;
  EXPECT_LE((u - u2).norm(), 1e-12 * (1 + u2.norm())) << what << ": u = W r + q on exit";
  const double e = moreau::natural_map_error(p, r);
  EXPECT_NEAR(rep.error, e, 1e-12 * (1 + e)) << what << ": the reported error is recomputed from r";
  EXPECT_EQ(rep.converged, rep.error <= tol) << what << ": converged iff error <= tolerance (error " << rep.error << ")";
}

/// Solves (from r = 0) and checks honesty and convergence.
inline Eigen::VectorXd solve(const std::string& name, const LocalProblem& p, double tol = 1e-10, long max_it = 10000,
                             nlohmann::json extra = nlohmann::json::object(), SolverReport* out = nullptr) {
  extra["tolerance"] = tol;
  extra["max_iterations"] = max_it;
  auto s = make(name, extra);
  Eigen::VectorXd r, u;
  const SolverReport rep = s->solve(p, r, u);
  expect_honest(p, r, u, rep, tol, name);
  EXPECT_TRUE(rep.converged) << name << ": error " << rep.error << " after " << rep.iterations << " iterations";
  if (out) *out = rep;
  return r;
}

/// W = Hᵀ M⁻¹ H for `bodies` rigid bodies (2D: 3 dof, 3D: 6 dof) and `nc` contacts, each
/// between two random bodies (or a body and the ground), with random frames and masses
/// spanning `mass_ratio`. More contacts than dof make W singular.
inline LocalProblem random_problem(int d, int bodies, int nc, double mu, double mass_ratio, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1), U01(0, 1);
  const int dof = d == 2 ? 3 : 6, n = d * nc;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(bodies * dof, n);
  Eigen::VectorXd minv(bodies * dof);
  for (int b = 0; b < bodies; ++b) {
    const double m = std::pow(mass_ratio, U01(rng));
    for (int k = 0; k < dof; ++k) minv[b * dof + k] = 1 / m;
  }
  for (int a = 0; a < nc; ++a) {
    const int b1 = static_cast<int>(rng() % bodies), b2 = static_cast<int>(rng() % (bodies + 1)) - 1;  // −1: ground
    for (int side = 0; side < 2; ++side) {
      const int b = side == 0 ? b1 : b2;
      if (b < 0 || (side == 1 && b == b1)) continue;
      const double sign = side == 0 ? 1 : -1;
      for (int i = 0; i < d; ++i)
        for (int k = 0; k < dof; ++k) H(b * dof + k, a * d + i) += sign * U(rng);
    }
  }
  Eigen::MatrixXd W = H.transpose() * minv.asDiagonal() * H;
  LocalProblem p;
  p.dim = d;
  p.W = W.sparseView();
  p.W.makeCompressed();
  p.q.resize(n);
  for (int i = 0; i < n; ++i) p.q[i] = U(rng) * (i % d == 0 ? 1.0 : 0.5) - (i % d == 0 ? 0.3 : 0.0);
  p.mu = Eigen::VectorXd::Constant(nc, mu);
  return p;
}

inline std::string shared(const std::string& f) { return std::string(MOREAU_SHARED_DIR) + "/fclib/" + f; }

/// Runs solver `name` on a shared FCLib file from r = 0: honest and converged to `tol`
/// within `max_it` iterations. No wall-clock limit: speed is the benchmarks' business
/// (a 5 s limit failed under AddressSanitizer on a loaded machine; the iteration cap is
/// what bounds a runaway solve).
inline void fclib_case(const std::string& name, const std::string& file, double tol, long max_it) {
  auto prob = moreau::fclib::read(shared(file));
  auto s = make(name, {{"tolerance", tol}, {"max_iterations", max_it}});
  Eigen::VectorXd r = Eigen::VectorXd::Zero(prob.local.dim * prob.local.contacts()), u;
  const SolverReport rep = s->solve(prob.local, r, u);
  expect_honest(prob.local, r, u, rep, tol, name + " on " + file);
  EXPECT_TRUE(rep.converged) << name << " on " << file << ": error " << rep.error << " after " << rep.iterations << " iterations";
  EXPECT_LE(rep.error, tol);
}

// ---- hand-made problems with known answers ------------------------------------------

inline void open_contact(const std::string& s) {
  auto r = solve(s, problem(2, {1, 0, 0, 1}, {0.5, 1}, {0.3}));
  EXPECT_NEAR(r[0], 0, 1e-12);
  EXPECT_NEAR(r[1], 0, 1e-12);
  auto r3 = solve(s, problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {0.1, -1, 2}, {0.5}));
  EXPECT_NEAR(r3.norm(), 0, 1e-12);
}

inline void stick_and_slide_2d(const std::string& s) {
  // W = diag(1, 1): stick iff |q_t| ≤ μ |q_n|.
  auto stick = solve(s, problem(2, {1, 0, 0, 1}, {-1, 0.2}, {0.3}));
  EXPECT_NEAR(stick[0], 1, 1e-8);
  EXPECT_NEAR(stick[1], -0.2, 1e-8);
  auto slide = solve(s, problem(2, {1, 0, 0, 1}, {-1, 0.5}, {0.3}));
  EXPECT_NEAR(slide[0], 1, 1e-8);
  EXPECT_NEAR(slide[1], -0.3, 1e-8);
}

inline void stick_and_slide_3d(const std::string& s) {
  // W = 2 I, q = (−1, q_T): r_n = 1/2; sticking needs ‖q_T‖/2 ≤ μ/2.
  auto stick = solve(s, problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 0.1, -0.05}, {0.3}));
  EXPECT_NEAR(stick[0], 0.5, 1e-8);
  EXPECT_NEAR(stick[1], -0.05, 1e-8);
  EXPECT_NEAR(stick[2], 0.025, 1e-8);
  // Sliding along q_T: r_T = −μ r_n q_T/‖q_T‖.
  auto slide = solve(s, problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 1, -1}, {0.3}));
  EXPECT_NEAR(slide[0], 0.5, 1e-8);
  EXPECT_NEAR(slide[1], -0.15 / std::sqrt(2.0), 1e-8);
  EXPECT_NEAR(slide[2], 0.15 / std::sqrt(2.0), 1e-8);
}

inline void frictionless_and_large_friction(const std::string& s) {
  auto smooth = solve(s, problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 1, -1}, {0.0}));
  EXPECT_NEAR(smooth[0], 0.5, 1e-8);
  EXPECT_NEAR(smooth[1], 0, 1e-8);
  EXPECT_NEAR(smooth[2], 0, 1e-8);
  auto rough = solve(s, problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 1, -1}, {5.0}));
  EXPECT_NEAR(rough[0], 0.5, 1e-8);
  EXPECT_NEAR(rough[1], -0.5, 1e-8);
  EXPECT_NEAR(rough[2], 0.5, 1e-8);
  auto rough2 = solve(s, problem(2, {1, 0, 0, 1}, {-1, 0.5}, {1.0}));  // μ = 1 sticks
  EXPECT_NEAR(rough2[0], 1, 1e-8);
  EXPECT_NEAR(rough2[1], -0.5, 1e-8);
}

inline void two_coupled_contacts(const std::string& s) {
  // W = [[2, 1], [1, 2]] on the normals, q = (−1, −1): r = W⁻¹(1, 1) = (1/3, 1/3).
  auto r = solve(s, problem(2, {2, 0, 1, 0, 0, 2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2}, {-1, 0, -1, 0}, {0, 0}));
  EXPECT_NEAR(r[0], 1.0 / 3, 1e-8);
  EXPECT_NEAR(r[2], 1.0 / 3, 1e-8);
  // One closes, one opens: q = (−1, +1): r_1 = 1/2 and u_2 = 1/2 + 1 > 0; frictionless, so
  // the open contact has u_T = 0 and x_n < 0 must project to the apex.
  auto r2 = solve(s, problem(2, {2, 0, 1, 0, 0, 2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2}, {-1, 0, 1, 0}, {0.0, 0.0}));
  EXPECT_NEAR(r2[0], 0.5, 1e-8);
  EXPECT_NEAR(r2[2], 0, 1e-8);
}

inline void redundant_contacts(const std::string& s) {
  // Two identical contacts (singular W): the split is not unique, the sum is.
  auto r = solve(s, problem(2, {1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1}, {-1, 0, -1, 0}, {0.5, 0.5}));
  EXPECT_NEAR(r[0] + r[2], 1.0, 1e-8);
  EXPECT_NEAR(r[1] + r[3], 0.0, 1e-8);
  // 3D, a box on the ground by four identical points: W of rank 3 out of 12.
  std::vector<double> W(144, 0.0);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int k = 0; k < 3; ++k) W[(3 * a + k) * 12 + 3 * b + k] = 1;
  auto r4 = solve(s, problem(3, W, {-1, 0.1, 0, -1, 0.1, 0, -1, 0.1, 0, -1, 0.1, 0}, {0.5, 0.5, 0.5, 0.5}));
  EXPECT_NEAR(r4[0] + r4[3] + r4[6] + r4[9], 1.0, 1e-7);  // total normal impulse: 1 (sticks: total tangent −0.1)
  EXPECT_NEAR(r4[1] + r4[4] + r4[7] + r4[10], -0.1, 1e-7);
}

inline void zero_q(const std::string& s) {
  // q = 0: r = 0 solves it, and the error divides by 1.
  auto r = solve(s, problem(3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {0, 0, 0}, {0.3}));
  EXPECT_NEAR(r.norm(), 0, 1e-12);
}

inline void mass_ratio(const std::string& s, double tol) {
  // Two contacts sharing a body 1e4 times heavier than the other: compare with NLGS.
  for (int d : {2, 3}) {
    LocalProblem p = random_problem(d, 3, 4, 0.5, 1e4, 7u + static_cast<unsigned>(d));
    auto ref = solve("nlgs", p, 1e-12, 100000, {{"check_every", 1}});
    auto r = solve(s, p, tol, 200000);
    Eigen::VectorXd u = p.W * r + p.q, uref = p.W * ref + p.q;
    EXPECT_LE((u - uref).norm(), 1e3 * tol * (1 + p.q.norm())) << s << " d=" << d << ": velocities agree with NLGS";
  }
}

/// Random problems that have a solution (NLGS, the reference, reaches 1e-12 on them: with
/// a random, non-physical W and μ ≥ 1 some have none, and every solver's iterates grow
/// without bound there), solved to `tol`; at least `count` of them.
inline void random_problems(const std::string& s, double tol, int count, int max_nc, double mu_max) {
  int solved = 0;
  for (int k = 0; solved < count && k < 4 * count; ++k) {
    const int d = 2 + k % 2;
    const double mu = mu_max * (k % 3) / 2.0;  // 0, μ_max/2, μ_max (≥ 1 when mu_max ≥ 1)
    LocalProblem p = random_problem(d, 2 + k % 4, 2 + k % max_nc, mu, 10.0, 100u + static_cast<unsigned>(k));
    {
      auto ref = make("nlgs", {{"tolerance", 1e-12}, {"max_iterations", 20000}, {"check_every", 10}});
      Eigen::VectorXd r, u;
      if (!ref->solve(p, r, u).converged) continue;
    }
    ++solved;
    SCOPED_TRACE("random problem " + std::to_string(k) + ": d " + std::to_string(d) + ", mu " + std::to_string(mu) +
                 ", contacts " + std::to_string(p.contacts()));
    solve(s, p, tol, 100000);
  }
  EXPECT_EQ(solved, count);
}

inline void not_converged(const std::string& s, long max_reported = 1) {
  // One iteration on a hard problem (singular W, μ ≥ 1, mass ratio 1e4): not converged,
  // said so, finite and honest.
  LocalProblem p = random_problem(3, 4, 12, 1.2, 1e4, 3u);
  auto solver = make(s, {{"tolerance", 1e-14}, {"max_iterations", 1}});
  Eigen::VectorXd r, u;
  const SolverReport rep = solver->solve(p, r, u);
  expect_honest(p, r, u, rep, 1e-14, s + " (one iteration)");
  EXPECT_FALSE(rep.converged);
  EXPECT_LE(rep.iterations, max_reported);
}

inline void warm_start(const std::string& s) {
  // A converged warm start comes back unchanged in (almost) no work; a wrong-sized one is reset.
  LocalProblem p = random_problem(3, 3, 6, 0.4, 10.0, 11u);
  Eigen::VectorXd r = solve("nlgs", p, 1e-12, 100000, {{"check_every", 1}}), u;
  auto solver = make(s, {{"tolerance", 1e-10}, {"max_iterations", 100}});
  SolverReport rep = solver->solve(p, r, u);
  expect_honest(p, r, u, rep, 1e-10, s + " (warm)");
  EXPECT_TRUE(rep.converged);
  EXPECT_LE(rep.iterations, 1);
  Eigen::VectorXd bad = Eigen::VectorXd::Ones(5);
  rep = make(s, {{"tolerance", 1e-8}, {"max_iterations", 100000}})->solve(p, bad, u);
  expect_honest(p, bad, u, rep, 1e-8, s + " (wrong-sized start)");
  // No contacts at all.
  LocalProblem empty;
  empty.dim = 3;
  empty.W.resize(0, 0);
  empty.q.resize(0);
  empty.mu.resize(0);
  Eigen::VectorXd r0, u0;
  rep = make(s)->solve(empty, r0, u0);
  EXPECT_TRUE(rep.converged);
  EXPECT_EQ(r0.size(), 0);
}

}  // namespace solver_cases
