// Alart–Curnier local Newton for one contact (scalar ρ, see local_solvers.hpp):
//   s_n = r_n − ρ u_n,  Φ_n = r_n − max(0, s_n)
//   s_T = r_T − ρ u_T,  Φ_T = r_T − P_D(R)(s_T),  R = μ max(0, s_n)
// with u = A r + b; Φ(r) = 0 is the Coulomb law. Newton steps on an element of the
// generalized Jacobian, with a backtracking (Armijo) line search on ½‖Φ‖²; when the search
// fails, projection iterations from the cone (local_projection.cpp) move it on.
#include <algorithm>
#include <cmath>
#include <moreau/contact_error.hpp>

#include "local_solvers.hpp"

namespace moreau::nlgs {

namespace {

struct Residual {
  double phi[3];
  double norm2;
};

/// Φ(r), and its generalized Jacobian J (row-major d×d) when J is not null.
Residual alart_curnier(int d, const double* A, const double* b, double mu, double rho, const double* r, double* J) {
  double u[3];
  for (int i = 0; i < d; ++i) {
    u[i] = b[i];
    for (int j = 0; j < d; ++j) u[i] += A[i * d + j] * r[j];
  }
  Residual out{};
  const double sn = r[0] - rho * u[0];
  out.phi[0] = r[0] - std::fmax(0.0, sn);
  double sT[2] = {0, 0};
  for (int k = 1; k < d; ++k) sT[k - 1] = r[k] - rho * u[k];
  const double ns = d == 2 ? std::fabs(sT[0]) : std::hypot(sT[0], sT[1]);
  const double R = mu * std::fmax(0.0, sn);
  const bool inside = ns <= R;
  for (int k = 1; k < d; ++k) out.phi[k] = inside ? r[k] - sT[k - 1] : r[k] - (ns > 0 ? R * sT[k - 1] / ns : 0.0);
  out.norm2 = 0;
  for (int k = 0; k < d; ++k) out.norm2 += out.phi[k] * out.phi[k];
  if (!J) return out;

  // ds/dr = I − ρ A (row i: ∂s_i/∂r).
  double ds[9];
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) ds[i * d + j] = (i == j) - rho * A[i * d + j];
  for (int j = 0; j < d; ++j) J[j] = sn > 0 ? (j == 0) - ds[j] : (j == 0);
  if (inside) {
    for (int i = 1; i < d; ++i)
      for (int j = 0; j < d; ++j) J[i * d + j] = (i == j) - ds[i * d + j];
    return out;
  }
  // Outside the disc: P = R ŝ, dP = ŝ dR + (R/‖s‖)(I − ŝŝᵀ) ds_T, dR = μ ds_n (s_n > 0).
  double e[2] = {0, 0};
  for (int k = 0; k < d - 1; ++k) e[k] = ns > 0 ? sT[k] / ns : 0.0;
  const double g = ns > 0 ? R / ns : 0.0;
  for (int i = 1; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      double dP = e[i - 1] * (sn > 0 ? mu * ds[j] : 0.0);
      for (int k = 1; k < d; ++k) dP += g * ((i == k) - e[i - 1] * e[k - 1]) * ds[k * d + j];
      J[i * d + j] = (i == j) - dP;
    }
  return out;
}

/// x = −J⁻¹ φ by Gaussian elimination with partial pivoting; false when J is singular.
bool newton_direction(int d, double* J, const double* phi, double* x) {
  double rhs[3];
  for (int i = 0; i < d; ++i) rhs[i] = -phi[i];
  for (int c = 0; c < d; ++c) {
    int p = c;
    for (int i = c + 1; i < d; ++i)
      if (std::fabs(J[i * d + c]) > std::fabs(J[p * d + c])) p = i;
    if (!(std::fabs(J[p * d + c]) > 1e-300)) return false;
    if (p != c) {
      for (int j = 0; j < d; ++j) std::swap(J[c * d + j], J[p * d + j]);
      std::swap(rhs[c], rhs[p]);
    }
    for (int i = c + 1; i < d; ++i) {
      const double f = J[i * d + c] / J[c * d + c];
      for (int j = c; j < d; ++j) J[i * d + j] -= f * J[c * d + j];
      rhs[i] -= f * rhs[c];
    }
  }
  for (int i = d - 1; i >= 0; --i) {
    double s = rhs[i];
    for (int j = i + 1; j < d; ++j) s -= J[i * d + j] * x[j];
    x[i] = s / J[i * d + i];
  }
  return true;
}

}  // namespace

void solve_local_alart_curnier(int d, const double* A, const double* b, double mu, double* r, int iterations, double tolerance) {
  const double rho = local_rho(d, A);
  const int n = iterations > 0 ? iterations : default_local_iterations(LocalMethod::alart_curnier);
  double scale = 0;
  for (int k = 0; k < d; ++k) scale += rho * rho * b[k] * b[k];
  scale = std::sqrt(scale);
  double J[9], dir[3], trial[3];
  Residual cur = alart_curnier(d, A, b, mu, rho, r, J);
  for (int it = 0; it < n; ++it) {
    if (std::sqrt(cur.norm2) <= tolerance * scale || cur.norm2 == 0) return;
    bool moved = false;
    if (newton_direction(d, J, cur.phi, dir)) {
      double t = 1;
      for (int ls = 0; ls < 30 && !moved; ++ls, t *= 0.5) {
        for (int k = 0; k < d; ++k) trial[k] = r[k] + t * dir[k];
        const Residual next = alart_curnier(d, A, b, mu, rho, trial, nullptr);
        if (next.norm2 <= (1 - 1e-4 * t) * cur.norm2) moved = true;
      }
    }
    if (!moved) {
      // A local minimum of ½‖Φ‖² (typical of strongly coupled blocks with large μ, where
      // Newton leaves the cone): restart from the cone with projection iterations.
      project_on_cone(d, mu, r, trial);
      solve_local_projection(d, A, b, mu, trial, 100, tolerance);
    }
    for (int k = 0; k < d; ++k) r[k] = trial[k];
    cur = alart_curnier(d, A, b, mu, rho, r, J);
  }
}

}  // namespace moreau::nlgs
