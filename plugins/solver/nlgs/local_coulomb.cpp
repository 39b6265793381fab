#include "local_coulomb.hpp"

#include <cmath>
#include <moreau/contact_error.hpp>

namespace moreau::nlgs {

namespace {

bool solve_small(int d, const double* A, const double* b, double* x) {
  // x = −A⁻¹ b by Cramer's rule (d ≤ 3).
  if (d == 2) {
    const double det = A[0] * A[3] - A[1] * A[2];
    if (!(std::fabs(det) > 0)) return false;
    x[0] = -(A[3] * b[0] - A[1] * b[1]) / det;
    x[1] = -(-A[2] * b[0] + A[0] * b[1]) / det;
    return true;
  }
  const double c0 = A[4] * A[8] - A[5] * A[7], c1 = A[5] * A[6] - A[3] * A[8], c2 = A[3] * A[7] - A[4] * A[6];
  const double det = A[0] * c0 + A[1] * c1 + A[2] * c2;
  if (!(std::fabs(det) > 0)) return false;
  const double inv = -1 / det;
  x[0] = (b[0] * c0 + A[1] * (A[5] * b[2] - b[1] * A[8]) + A[2] * (b[1] * A[7] - A[4] * b[2])) * inv;
  x[1] = (A[0] * (b[1] * A[8] - A[5] * b[2]) + b[0] * c1 + A[2] * (A[3] * b[2] - b[1] * A[6])) * inv;
  x[2] = (A[0] * (A[4] * b[2] - b[1] * A[7]) + A[1] * (b[1] * A[6] - A[3] * b[2]) + b[0] * c2) * inv;
  return true;
}

}  // namespace

void solve_local(int d, const double* A, const double* b, double mu, double* r) {
  if (b[0] >= 0) {  // open: r = 0 leaves u_n = b_n ≥ 0
    for (int k = 0; k < d; ++k) r[k] = 0;
    return;
  }
  double x[3];
  if (solve_small(d, A, b, x)) {
    const double t = d == 2 ? std::fabs(x[1]) : std::hypot(x[1], x[2]);
    if (x[0] >= 0 && t <= mu * x[0]) {  // sticking
      for (int k = 0; k < d; ++k) r[k] = x[k];
      return;
    }
  }
  if (mu == 0) {  // frictionless: r_t = 0, u_n = 0
    r[0] = -b[0] / A[0];
    for (int k = 1; k < d; ++k) r[k] = 0;
    return;
  }
  if (d == 2) {
    // Sliding in direction s (u_t has the sign of s, r_t = −s μ r_n, u_n = 0).
    for (double s : {1.0, -1.0}) {
      const double den = A[0] - s * mu * A[1];
      if (!(den > 0)) continue;
      const double rn = -b[0] / den, rt = -s * mu * rn;
      const double ut = A[2] * rn + A[3] * rt + b[1];
      if (rn >= 0 && s * ut >= 0) {
        r[0] = rn;
        r[1] = rt;
        return;
      }
    }
  }
  // 3D sliding (and 2D fallback): r ← P_K(r − ρ ∘ (A r + b + μ‖u_T‖ e_n)), ρ_k = 1/A_kk.
  double rho[3];
  for (int k = 0; k < d; ++k) rho[k] = A[k * d + k] > 0 ? 1 / A[k * d + k] : 1.0;
  for (int it = 0; it < 200; ++it) {
    double u[3], y[3], p[3];
    for (int i = 0; i < d; ++i) {
      u[i] = b[i];
      for (int j = 0; j < d; ++j) u[i] += A[i * d + j] * r[j];
    }
    const double ut = d == 2 ? std::fabs(u[1]) : std::hypot(u[1], u[2]);
    y[0] = r[0] - rho[0] * (u[0] + mu * ut);
    for (int k = 1; k < d; ++k) y[k] = r[k] - rho[k] * u[k];
    project_on_cone(d, mu, y, p);
    double change = 0, size = 0;
    for (int k = 0; k < d; ++k) {
      change += (p[k] - r[k]) * (p[k] - r[k]);
      size += p[k] * p[k];
      r[k] = p[k];
    }
    if (change <= 1e-30 * (size + 1e-300)) break;
  }
}

}  // namespace moreau::nlgs
