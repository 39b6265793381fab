#pragma once
// The one error measure of DESIGN §1, used by every solver's stopping test, the
// benchmarks and the FCLib comparisons: the normalised natural-map residual
//   err(r) = sqrt(Σ_α ‖r_α − P_Kμ(r_α − ũ_α)‖²) / ‖q‖   (‖q‖ = 0: divide by 1),
// with ũ_α = u_α + μ‖u_T,α‖ e_n. Always recomputed from r. In a time step the denominator
// is LocalProblem::error_scale instead (the contacts that approach; docs/solvers.md).
#include <cmath>
#include <moreau/contact_problem.hpp>

namespace moreau {

/// Projection of x (dim values, normal first) on the Coulomb cone of coefficient mu.
inline void project_on_cone(int dim, double mu, const double* x, double* out) {
  const double n = x[0];
  const double t = dim == 2 ? std::fabs(x[1]) : std::sqrt(x[1] * x[1] + x[2] * x[2]);
  if (t <= mu * n && n >= 0) {  // inside the cone ‖x_T‖ ≤ μ x_n (n ≥ 0: with μ = 0, x_T = 0, x_n < 0 is outside)
    for (int k = 0; k < dim; ++k) out[k] = x[k];
  } else if (mu * t <= -n) {  // inside the polar cone: projects to the apex
    for (int k = 0; k < dim; ++k) out[k] = 0;
  } else {
    const double a = (mu * t + n) / (mu * mu + 1);
    out[0] = a;
    for (int k = 1; k < dim; ++k) out[k] = t > 0 ? mu * a * x[k] / t : 0.0;
  }
}

/// ‖r_α − P_Kμ(r_α − ũ_α)‖² of one contact (dim values each, normal first).
inline double contact_natural_map_squared(int d, double mu, const double* ra, const double* ua) {
  const double ut = d == 2 ? std::fabs(ua[1]) : std::sqrt(ua[1] * ua[1] + ua[2] * ua[2]);
  double x[3], px[3];
  x[0] = ra[0] - (ua[0] + mu * ut);
  for (int k = 1; k < d; ++k) x[k] = ra[k] - ua[k];
  project_on_cone(d, mu, x, px);
  double sum = 0;
  for (int k = 0; k < d; ++k) sum += (ra[k] - px[k]) * (ra[k] - px[k]);
  return sum;
}

/// The error's denominator: LocalProblem::error_scale when set (time-stepping), else ‖q‖
/// (the FCLib measure); 1 when that is 0.
inline double error_denominator(const LocalProblem& p) {
  const double s = p.error_scale > 0 ? p.error_scale : p.q.norm();
  return s > 0 ? s : 1.0;
}

/// err(r) for u = W r + q already computed.
inline double natural_map_error(const LocalProblem& p, const Eigen::VectorXd& r, const Eigen::VectorXd& u) {
  const int d = p.dim;
  double sum = 0;
  for (Eigen::Index a = 0; a < p.contacts(); ++a)
    sum += contact_natural_map_squared(d, p.mu[a], r.data() + a * d, u.data() + a * d);
  return std::sqrt(sum) / error_denominator(p);
}

inline double natural_map_error(const LocalProblem& p, const Eigen::VectorXd& r) {
  Eigen::VectorXd u = p.W * r + p.q;
  return natural_map_error(p, r, u);
}

}  // namespace moreau
