#include "admm_core.hpp"

#include "../work.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <moreau/contact_error.hpp>

namespace moreau::admm {

namespace {
inline void project_cone(int d, double mu, const double* x, double* out) { project_on_cone(d, mu, x, out); }


void project_all(const LocalProblem& P, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  const int d = P.dim;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) project_cone(d, P.mu[a], x.data() + a * d, out.data() + a * d);
}

/// s_α = μ_α ‖u_T,α‖ on the normal component, zero on the tangent ones.
void de_saxce(const LocalProblem& P, const Eigen::VectorXd& u, Eigen::VectorXd& s) {
  const int d = P.dim;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) {
    const double* ua = u.data() + a * d;
    const double ut = d == 2 ? std::fabs(ua[1]) : std::sqrt(ua[1] * ua[1] + ua[2] * ua[2]);
    s[a * d] = P.mu[a] * ut;
    for (int k = 1; k < d; ++k) s[a * d + k] = 0;
  }
}

}  // namespace

bool Admm::factorise(double rho) {
  ++factorisations_;
  Eigen::SparseMatrix<double> A = W_ + rho * D_;
  const double n = static_cast<double>(A.rows());
  bool ok;
  double nl, nu;
  if (symmetric_) {
    if (!analysed_) ldlt_.analyzePattern(A);
    analysed_ = true;
    ldlt_.factorize(A);
    ok = ldlt_.info() == Eigen::Success;
    nl = nu = ok ? static_cast<double>(ldlt_.matrixL().nestedExpression().nonZeros()) : 0.0;
  } else {
    if (!analysed_) lu_.analyzePattern(A);
    analysed_ = true;
    lu_.factorize(A);
    ok = lu_.info() == Eigen::Success;
    nl = ok ? static_cast<double>(lu_.nnzL()) : 0.0;
    nu = ok ? static_cast<double>(lu_.nnzU()) : 0.0;
  }
  // Counted work (plugins/solver/work.hpp): the factorisation, and each later solve.
  factorisation_units_ += WorkCosts::factorisation(nl, nu, n);
  solve_units_ = WorkCosts::triangular_solves(nl, nu);
  return ok;
}

void Admm::solve_linear(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (symmetric_) x = ldlt_.solve(b);
  else x = lu_.solve(b);
}

SolverReport Admm::solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u) {
  const int d = P.dim;
  const Eigen::Index nc = P.contacts(), n = d * nc;
  SolverReport rep;
  factorisations_ = 0;
  factorisation_units_ = 0;
  WorkMeter meter(o.max_work, o.work);
  const WorkCosts cost = WorkCosts::of(P, false);
  if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
  if (nc == 0) {
    u = P.q;
    rep.converged = true;
    return rep;
  }
  const bool resuming = o.resume && state_.z.size() == n;
  double rho = o.rho;
  if (!resuming) {  // resumed, the run keeps its weights, W's copy and its factorisation
    meter.add(WorkCosts::assembly(static_cast<double>(P.W.nonZeros()), static_cast<double>(n)));  // W, D, ρ, symmetry: a few passes over W
    // Per-contact weights D (a scalar per contact keeps the projection on K exact).
    Eigen::VectorXd& D = weights_;
    D.resize(n);
    double mean_diag = 0;
    for (Eigen::Index i = 0; i < n; ++i) mean_diag += P.W.coeff(i, i);
    mean_diag /= static_cast<double>(n);
    if (!(mean_diag > 0)) mean_diag = 1;
    for (Eigen::Index a = 0; a < nc; ++a) {
      double t = 0;
      for (int k = 0; k < d; ++k) t += P.W.coeff(a * d + k, a * d + k);
      t /= d;
      if (!(t > 1e-12 * mean_diag)) t = mean_diag;
      for (int k = 0; k < d; ++k) D[a * d + k] = t;
    }
    W_ = P.W;  // column-major copy for the factorisation
    {
      Eigen::SparseMatrix<double> T = W_.transpose();
      symmetric_ = (W_ - T).norm() <= 1e-14 * W_.norm();
    }
    D_.resize(n, n);
    D_.setIdentity();
    for (Eigen::Index i = 0; i < n; ++i) D_.coeffRef(i, i) = D[i];
    analysed_ = false;
    if (!(rho > 0)) {
      // A few hundredths of ‖D^-1/2 W D^-1/2‖∞ (the largest row sum of |W| relative to D).
      double m = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        double s = 0;
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(P.W, i); it; ++it)
          s += std::fabs(it.value()) / std::sqrt(D[i] * D[it.col()]);
        m = std::max(m, s);
      }
      rho = 0.03 * (m > 0 ? m : 1.0);
    }
  }
  const Eigen::VectorXd& D = weights_;
  const Eigen::VectorXd sqrtD = D.cwiseSqrt();
  Eigen::VectorXd z(n), zk(n), zh(n), xi(n), xik(n), xih(n), s(n), rhs(n), x(n), best(n), tmp(n);
  if (resuming) {
    z = state_.z, zk = state_.zk, zh = state_.zh, xi = state_.xi, xik = state_.xik, xih = state_.xih, x = state_.x;
    rho = state_.rho;
  } else {
    project_all(P, r, z);
  }
  u = P.W * z + P.q;
  double err = natural_map_error(P, z, u);
  meter.add(cost.product + cost.error);
  best = z;
  double best_err = err;
  rep.error = err;
  if (err <= o.tolerance) {
    r = z;
    rep.converged = true;
    return rep;
  }
  if (!resuming) {
    de_saxce(P, u, s);
    // ξ at the fixed point of a converged start: W z + q + s = −ρ D ξ.
    xi = -(u + s).cwiseQuotient(D) / rho;
    zk = z;
    xik = xi;
    zh = z;
    xih = xi;
    x = z;  // r iterate
  }
  if (!resuming && !factorise(rho)) {
    r = best;
    u = P.W * r + P.q;
    rep.error = natural_map_error(P, r, u);
    return rep;
  }
  double tau_k = resuming ? state_.tau : 1, e_k = resuming ? state_.e : INFINITY;
  std::vector<double> best_hist;
  for (long it = 1; it <= o.max_iterations; ++it) {
    rep.iterations = it;
    tmp = P.W * x + P.q;  // the shift from the unprojected iterate, as Siconos does
    de_saxce(P, tmp, s);
    rhs = rho * D.cwiseProduct(zh - xih) - P.q - s;
    solve_linear(rhs, x);
    tmp = x + xih;
    project_all(P, tmp, z);
    xi = tmp - z;
    // Residuals in the D^1/2-scaled variables, where they are comparable whatever the
    // units and the mass ratios: primal ‖x − z‖, dual ρ‖ẑ − z‖.
    const double primal = (x - z).cwiseProduct(sqrtD).norm();
    const double dual = rho * (zh - z).cwiseProduct(sqrtD).norm();
    u = P.W * z + P.q;
    err = natural_map_error(P, z, u);
    // Two products by W, the solves, the error, a dozen vector passes, new factorisations.
    meter.add(2 * cost.product + solve_units_ + cost.error + 6 * cost.vector + factorisation_units_);
    factorisation_units_ = 0;
    if (!std::isfinite(err) || !std::isfinite(primal) || !std::isfinite(dual)) break;
    if (err < best_err) {
      best_err = err;
      best = z;
    }
    if (err <= o.tolerance) break;
    if (o.stall_window > 0) {
      best_hist.push_back(best_err);
      const auto h = static_cast<long>(best_hist.size());
      if (h > o.stall_window && best_err > o.stall_factor * best_hist[h - 1 - o.stall_window]) break;
    }
    const double e = primal * primal + dual * dual;
    if (o.acceleration && e < o.restart * e_k) {
      const double tau = 0.5 * (1 + std::sqrt(1 + 4 * tau_k * tau_k));
      const double a = (tau_k - 1) / tau;
      zh = (1 + a) * z - a * zk;
      xih = (1 + a) * xi - a * xik;
      tau_k = tau;
      e_k = e;
    } else {
      tau_k = 1;
      e_k = o.acceleration ? e_k / o.restart : e;
      if (o.acceleration) {
        zh = zk;
        xih = xik;
      } else {
        zh = z;
        xih = xi;
      }
    }
    zk = z;
    xik = xi;
    if (o.adaptive) {
      // Residual balancing (Boyd et al. 2011, §3.4.1).
      double change = 1;
      if (primal > o.balance * dual) change = o.factor;
      else if (dual > o.balance * primal) change = 1 / o.factor;
      if (change != 1) {
        rho *= change;
        xi /= change;  // the unscaled multiplier ρ D ξ is kept
        xih /= change;
        xik /= change;
        if (!factorise(rho)) break;
      }
    }
    // The budget is checked once the step is complete (its extrapolation and penalty
    // included), so that the state saved below resumes the run exactly where one run
    // alone would go on: `auto`'s slices of ADMM are then one run.
    if (meter.exhausted()) break;
  }
  state_ = State{z, zk, zh, xi, xik, xih, x, rho, tau_k, e_k};
  r = best;
  u = P.W * r + P.q;
  rep.error = natural_map_error(P, r, u);
  rep.converged = rep.error <= o.tolerance;
  return rep;
}

}  // namespace moreau::admm
