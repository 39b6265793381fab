#include "local_coulomb.hpp"

#include "local_solvers.hpp"

#include <algorithm>
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

/// 3D sliding for any block: with e(φ) = (cos φ, sin φ) the sliding direction,
/// r = r_n (1, −μ e), r_n = −b_n / (A_nn − μ A_nT·e), and u_T(φ) = r_n (A_Tn − μ A_TT e) + b_T
/// must be parallel to e: f(φ) = u_T × e = 0 with u_T·e > 0 and r_n ≥ 0. Roots are
/// bracketed on 64 angles and refined by bisection to rounding.
bool slide_by_angle(const double* A, const double* b, double mu, double* r) {
  struct Eval {
    double f, along, rn;
    bool valid;
  };
  auto eval = [&](double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    const double den = A[0] - mu * (A[1] * c + A[2] * s);
    Eval e{0, 0, 0, den > 0};
    if (!e.valid) return e;
    e.rn = -b[0] / den;
    const double u1 = e.rn * (A[3] - mu * (A[4] * c + A[5] * s)) + b[1];
    const double u2 = e.rn * (A[6] - mu * (A[7] * c + A[8] * s)) + b[2];
    e.f = u1 * s - u2 * c;
    e.along = u1 * c + u2 * s;
    e.valid = e.rn >= 0;
    return e;
  };
  constexpr int n = 64;
  const double step = 2 * M_PI / n;
  Eval prev = eval(0);
  for (int k = 1; k <= n; ++k) {
    double lo = (k - 1) * step, hi = k * step;
    Eval cur = eval(hi);
    if (prev.valid && cur.valid && (prev.f == 0 || (prev.f < 0) != (cur.f < 0))) {
      Eval flo = prev;
      for (int it = 0; it < 60 && hi - lo > 1e-16; ++it) {
        const double mid = 0.5 * (lo + hi);
        Eval fm = eval(mid);
        if (!fm.valid) break;
        if ((fm.f < 0) == (flo.f < 0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      const double phi = 0.5 * (lo + hi);
      Eval e = eval(phi);
      if (e.valid && e.along > 0) {
        r[0] = e.rn;
        r[1] = -mu * e.rn * std::cos(phi);
        r[2] = -mu * e.rn * std::sin(phi);
        return true;
      }
    }
    prev = cur;
  }
  return false;
}

/// ‖r − P_K(r − ũ)‖ for u = A r + b: zero exactly at the one-contact Coulomb solution.
double local_residual(const double* A, const double* b, double mu, const double* r) {
  double u[3];
  for (int i = 0; i < 3; ++i) u[i] = b[i] + A[3 * i] * r[0] + A[3 * i + 1] * r[1] + A[3 * i + 2] * r[2];
  return std::sqrt(contact_natural_map_squared(3, mu, r, u));
}

/// 3D sliding by the Alart–Curnier local Newton (quadratic: a few steps where the
/// direction fixed point below converges linearly on anisotropic blocks), started from the
/// previous r when it is sliding, else from the slide along −b_T. Its answer is kept only
/// when the natural map vanishes to rounding, so `exact` stays exact.
bool slide_by_newton(const double* A, const double* b, double mu, double* r) {
  double x[3] = {r[0], r[1], r[2]};
  if (!(x[0] > 0)) {
    const double len = std::hypot(b[1], b[2]);
    const double ex = len > 0 ? b[1] / len : 1.0, ey = len > 0 ? b[2] / len : 0.0;
    const double den = A[0] - mu * (A[1] * ex + A[2] * ey);
    if (!(den > 0)) return false;
    x[0] = -b[0] / den;
    x[1] = -mu * x[0] * ex;
    x[2] = -mu * x[0] * ey;
  }
  solve_local_alart_curnier(3, A, b, mu, x, 12, 1e-15);
  // Rounding scale of the residual: the sizes of b and of A r.
  const double scale = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]) +
                       (std::fabs(A[0]) + std::fabs(A[4]) + std::fabs(A[8])) * std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  if (!(local_residual(A, b, mu, x) <= 1e-13 * scale)) return false;
  r[0] = x[0];
  r[1] = x[1];
  r[2] = x[2];
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
  if (d == 3 && slide_by_newton(A, b, mu, r)) return;
  if (d == 3) {
    // Sliding along a unit direction e of the tangent plane: r = r_n (1, −μ e), u_n = 0,
    // and e must be the direction of u_T. Fixed point on e from the direction of b_T
    // (exact at once when A_TT is isotropic and A_Tn = 0, as for round shapes).
    double ex = b[1], ey = b[2];
    double len = std::hypot(ex, ey);
    if (len == 0) {
      ex = -r[1];
      ey = -r[2];
      len = std::hypot(ex, ey);
    }
    if (len > 0) {
      ex /= len;
      ey /= len;
      for (int it = 0; it < 50; ++it) {
        const double den = A[0] - mu * (A[1] * ex + A[2] * ey);
        if (!(den > 0)) break;
        const double rn = -b[0] / den;
        const double rt1 = -mu * rn * ex, rt2 = -mu * rn * ey;
        const double u1 = A[3] * rn + A[4] * rt1 + A[5] * rt2 + b[1];
        const double u2 = A[6] * rn + A[7] * rt1 + A[8] * rt2 + b[2];
        const double ul = std::hypot(u1, u2);
        if (rn < 0 || ul == 0) break;
        const double nx = u1 / ul, ny = u2 / ul;
        const bool settled = std::fabs(nx - ex) + std::fabs(ny - ey) < 1e-15;
        ex = nx;
        ey = ny;
        if (settled) {
          const double den2 = A[0] - mu * (A[1] * ex + A[2] * ey);
          r[0] = -b[0] / den2;
          r[1] = -mu * r[0] * ex;
          r[2] = -mu * r[0] * ey;
          return;
        }
      }
    }
  }
  if (d == 3 && slide_by_angle(A, b, mu, r)) return;
  // Fallback: the projection fixed point with a scalar ρ (local_solvers.hpp); a diagonal ρ
  // would have another fixed point than the Coulomb law's.
  solve_local_projection(d, A, b, mu, r, 200, 1e-15);
}

}  // namespace moreau::nlgs
