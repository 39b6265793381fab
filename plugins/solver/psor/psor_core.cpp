#include "psor_core.hpp"

#include <cmath>
#include <moreau/contact_error.hpp>
#include <vector>

namespace moreau::psor {

namespace {
inline void project_cone(int d, double mu, const double* x, double* out) { project_on_cone(d, mu, x, out); }

}  // namespace

SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u) {
  const int d = P.dim;
  const Eigen::Index nc = P.contacts(), n = d * nc;
  SolverReport rep;
  if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
  if (nc == 0) {
    u = P.q;
    rep.converged = true;
    return rep;
  }
  // Step per contact: ω / W_αα,nn (the mean diagonal where that is zero).
  std::vector<double> step(nc);
  double mean_diag = 0;
  for (Eigen::Index i = 0; i < n; ++i) mean_diag += P.W.coeff(i, i);
  mean_diag = n > 0 ? mean_diag / static_cast<double>(n) : 1;
  if (!(mean_diag > 0)) mean_diag = 1;
  for (Eigen::Index a = 0; a < nc; ++a) {
    double w = P.W.coeff(a * d, a * d);
    if (!(w > 1e-12 * mean_diag)) w = mean_diag;
    step[a] = o.relaxation / w;
  }
  u = P.W * r + P.q;
  double best_err = natural_map_error(P, r, u);
  Eigen::VectorXd best = r;
  for (long it = 1; it <= o.max_iterations && best_err > o.tolerance; ++it) {
    rep.iterations = it;
    for (Eigen::Index a = 0; a < nc; ++a) {
      double ua[3], x[3], p[3];
      for (int i = 0; i < d; ++i) {
        double s = P.q[a * d + i];
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(P.W, a * d + i); e; ++e) s += e.value() * r[e.col()];
        ua[i] = s;
      }
      const double ut = d == 2 ? std::fabs(ua[1]) : std::hypot(ua[1], ua[2]);
      x[0] = r[a * d] - step[a] * (ua[0] + P.mu[a] * ut);
      for (int k = 1; k < d; ++k) x[k] = r[a * d + k] - step[a] * ua[k];
      project_cone(d, P.mu[a], x, p);
      for (int k = 0; k < d; ++k) r[a * d + k] = p[k];
    }
    if (it % o.check_every != 0 && it != o.max_iterations) continue;
    u = P.W * r + P.q;
    const double e = natural_map_error(P, r, u);
    if (!std::isfinite(e) || !r.allFinite()) break;
    if (e < best_err) {
      best_err = e;
      best = r;
    }
  }
  r = best;
  u = P.W * r + P.q;
  rep.error = natural_map_error(P, r, u);
  rep.converged = rep.error <= o.tolerance;
  return rep;
}

}  // namespace moreau::psor
