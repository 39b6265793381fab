#include "newton_core.hpp"

#include "../work.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>
#include <moreau/contact_error.hpp>

namespace moreau::newton {

namespace {
inline void project_cone(int d, double mu, const double* x, double* out) { project_on_cone(d, mu, x, out); }


/// Φ for every contact; with A, B (d×d blocks, row-major, per contact) when wanted.
void alart_curnier(const LocalProblem& P, const Eigen::VectorXd& rho_n, const Eigen::VectorXd& rho_t,
                   const Eigen::VectorXd& r, const Eigen::VectorXd& u, Eigen::VectorXd& phi, double* A, double* B) {
  const int d = P.dim;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) {
    const double* ra = r.data() + a * d;
    const double* ua = u.data() + a * d;
    double* f = phi.data() + a * d;
    double* Aa = A ? A + a * d * d : nullptr;
    double* Ba = B ? B + a * d * d : nullptr;
    if (Aa)
      for (int k = 0; k < d * d; ++k) Aa[k] = Ba[k] = 0;
    const double mu = P.mu[a], rn = rho_n[a], rt = rho_t[a];
    const double xn = ra[0] - rn * ua[0];
    if (xn > 0) {
      f[0] = rn * ua[0];
      if (Ba) Ba[0] = rn;
    } else {
      f[0] = ra[0];
      if (Aa) Aa[0] = 1;
    }
    const double R = mu * std::max(xn, 0.0);
    double y[2];
    for (int k = 1; k < d; ++k) y[k - 1] = ra[k] - rt * ua[k];
    const double ny = d == 2 ? std::fabs(y[0]) : std::hypot(y[0], y[1]);
    if (ny <= R) {  // sticking: Φ_T = ρ_t u_T
      for (int k = 1; k < d; ++k) {
        f[k] = rt * ua[k];
        if (Ba) Ba[k * d + k] = rt;
      }
    } else {  // sliding (or open): Φ_T = r_T − R ŷ
      double yh[2];
      for (int k = 0; k < d - 1; ++k) yh[k] = y[k] / ny;
      for (int k = 1; k < d; ++k) f[k] = ra[k] - R * yh[k - 1];
      if (Aa) {
        const double c = R / ny;
        for (int i = 1; i < d; ++i)
          for (int j = 1; j < d; ++j) {
            const double p = c * ((i == j ? 1.0 : 0.0) - yh[i - 1] * yh[j - 1]);
            Aa[i * d + j] = (i == j ? 1.0 : 0.0) - p;
            Ba[i * d + j] = rt * p;
          }
        if (xn > 0)
          for (int i = 1; i < d; ++i) {
            Aa[i * d] = -mu * yh[i - 1];
            Ba[i * d] = mu * rn * yh[i - 1];
          }
      }
    }
  }
}

void project_all(const LocalProblem& P, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  const int d = P.dim;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) project_cone(d, P.mu[a], x.data() + a * d, out.data() + a * d);
}

void de_saxce_add(const LocalProblem& P, Eigen::VectorXd& u) {
  const int d = P.dim;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) {
    const double* ua = u.data() + a * d;
    u[a * d] += P.mu[a] * (d == 2 ? std::fabs(ua[1]) : std::hypot(ua[1], ua[2]));
  }
}

}  // namespace

SolverReport Newton::solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u) {
  const int d = P.dim;
  const Eigen::Index nc = P.contacts(), n = d * nc;
  SolverReport rep;
  if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
  if (nc == 0) {
    u = P.q;
    rep.converged = true;
    return rep;
  }
  // ρ per contact from the diagonal of its block.
  Eigen::VectorXd rho_n(nc), rho_t(nc), Dinv(n);
  double mean_diag = 0;
  for (Eigen::Index i = 0; i < n; ++i) mean_diag += P.W.coeff(i, i);
  mean_diag /= static_cast<double>(n);
  if (!(mean_diag > 0)) mean_diag = 1;
  for (Eigen::Index a = 0; a < nc; ++a) {
    double wn = P.W.coeff(a * d, a * d), wt = 0;
    for (int k = 1; k < d; ++k) wt += P.W.coeff(a * d + k, a * d + k);
    wt /= d - 1;
    if (!(wn > 1e-12 * mean_diag)) wn = mean_diag;
    if (!(wt > 1e-12 * mean_diag)) wt = mean_diag;
    rho_n[a] = o.rho_scale / wn;
    rho_t[a] = o.rho_scale / wt;
    const double w = (wn + (d - 1) * wt) / d;
    for (int k = 0; k < d; ++k) Dinv[a * d + k] = 1 / w;
  }
  const Eigen::SparseMatrix<double> W = P.W;

  Eigen::VectorXd phi(n), phi_try(n), dir(n), r_try(n), u_try(n), best(n), tmp(n);
  std::vector<double> A(static_cast<std::size_t>(nc) * d * d), B(A.size());
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::SparseMatrix<double> Bs(n, n), As(n, n), J(n, n), I(n, n);
  I.setIdentity();

  u = P.W * r + P.q;
  double err = natural_map_error(P, r, u);
  double best_err = err;
  best = r;
  std::deque<double> own_merits;
  std::deque<double>& merits = o.merits ? *o.merits : own_merits;
  std::vector<double> best_hist;
  bool analysed = false;
  WorkMeter meter(o.max_work, o.work);
  const WorkCosts cost = WorkCosts::of(P, false);
  meter.add(cost.product + cost.error);  // the start's error
  Eigen::Index pattern_nnz = -1;
  for (long it = 1; it <= o.max_iterations && err > o.tolerance; ++it) {
    rep.iterations = it;
    alart_curnier(P, rho_n, rho_t, r, u, phi, A.data(), B.data());
    const double psi = 0.5 * phi.squaredNorm();
    merits.push_back(psi);
    if (static_cast<int>(merits.size()) > std::max(1, o.nonmonotone)) merits.pop_front();
    const double ref = *std::max_element(merits.begin(), merits.end());
    // J = A + B W.
    trip.clear();
    for (Eigen::Index a = 0; a < nc; ++a)
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j)
          trip.emplace_back(a * d + i, a * d + j, B[(a * d + i) * d + j]);  // zeros kept: a fixed pattern
    Bs.setFromTriplets(trip.begin(), trip.end());
    trip.clear();
    for (Eigen::Index a = 0; a < nc; ++a)
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j)
          trip.emplace_back(a * d + i, a * d + j, A[(a * d + i) * d + j]);
    As.setFromTriplets(trip.begin(), trip.end());
    J = As + Bs * W;
    meter.add(WorkCosts::assembly(static_cast<double>(P.W.nonZeros()), static_cast<double>(n)) + 6 * cost.vector);  // Φ, A, B, J = A + B W
    // Regularised direction (J + λI) d = −Φ, λ = clamp(‖Φ‖/‖r‖, λ_min, λ_max): W is often
    // singular (redundant contacts), and so is J at sticking contacts; λ → λ_min near the
    // solution keeps the convergence fast. A failed line search retries with a larger λ
    // (a shorter, more gradient-like step).
    double reg = std::clamp(phi.norm() / std::max(r.norm(), 1e-300), o.min_regularisation, o.max_regularisation);
    bool stepped = false;
    for (int attempt = 0; attempt < 3 && !stepped; ++attempt, reg *= 100) {
      Eigen::SparseMatrix<double> M = J + reg * I;
      M.makeCompressed();
      if (!analysed || M.nonZeros() != pattern_nnz) {  // the pattern is that of W's block rows: analysed once
        lu_.analyzePattern(M);
        analysed = true;
        pattern_nnz = M.nonZeros();
      }
      lu_.factorize(M);
      analysed_ = true;
      if (lu_.info() != Eigen::Success) continue;
      dir = lu_.solve(-phi);
      {  // the factorisation and the two triangular solves
        const double nl = static_cast<double>(lu_.nnzL()), nu = static_cast<double>(lu_.nnzU());
        meter.add(WorkCosts::factorisation(nl, nu, static_cast<double>(n)) + WorkCosts::triangular_solves(nl, nu));
      }
      if (!dir.allFinite()) continue;
      double t = 1;
      for (int k = 0; k <= o.max_backtracks; ++k, t *= 0.5) {
        r_try = r + t * dir;
        u_try = P.W * r_try + P.q;
        meter.add(cost.product + 3 * cost.vector);
        alart_curnier(P, rho_n, rho_t, r_try, u_try, phi_try, nullptr, nullptr);
        const double psi_try = 0.5 * phi_try.squaredNorm();
        if (std::isfinite(psi_try) && psi_try <= ref - 1e-4 * t * 2 * psi) {
          r.swap(r_try);
          u.swap(u_try);
          stepped = true;
          break;
        }
      }
    }
    if (!stepped) {
      // Projected steps on the natural map: r ← P_K(r − D⁻¹ ũ).
      for (int k = 0; k < o.fallback_steps; ++k) {
        tmp = u;
        de_saxce_add(P, tmp);
        tmp = r - Dinv.cwiseProduct(tmp);
        project_all(P, tmp, r);
        u = P.W * r + P.q;
        meter.add(cost.product + 3 * cost.vector);
      }
      merits.clear();
    }
    err = natural_map_error(P, r, u);
    meter.add(cost.error);
    if (!std::isfinite(err) || !r.allFinite()) break;
    if (err < best_err) {
      best_err = err;
      best = r;
    }
    if (o.stall_window > 0) {
      best_hist.push_back(best_err);
      const auto h = static_cast<long>(best_hist.size());
      if (h > o.stall_window && best_err > o.stall_factor * best_hist[h - 1 - o.stall_window]) break;
    }
    if (meter.exhausted()) break;
  }
  if (o.last) *o.last = r;
  r = best;
  u = P.W * r + P.q;
  rep.error = natural_map_error(P, r, u);
  rep.converged = rep.error <= o.tolerance;
  return rep;
}

}  // namespace moreau::newton
