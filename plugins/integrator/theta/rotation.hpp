#pragma once
// Small rotation helpers on raw arrays (the integrator's hot loop works on the State's
// contiguous fields directly). Quaternions are w x y z, body to world.
#include <cmath>

namespace moreau::theta {

/// Rotation matrix (row-major) of a unit quaternion.
inline void quat_to_matrix(const double* q, double* R) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z); R[1] = 2 * (x * y - w * z);     R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);     R[4] = 1 - 2 * (x * x + z * z); R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);     R[7] = 2 * (y * z + w * x);     R[8] = 1 - 2 * (x * x + y * y);
}

inline void mul(const double* R, const double* v, double* out) {
  out[0] = R[0] * v[0] + R[1] * v[1] + R[2] * v[2];
  out[1] = R[3] * v[0] + R[4] * v[1] + R[5] * v[2];
  out[2] = R[6] * v[0] + R[7] * v[1] + R[8] * v[2];
}

inline void mul_transpose(const double* R, const double* v, double* out) {
  out[0] = R[0] * v[0] + R[3] * v[1] + R[6] * v[2];
  out[1] = R[1] * v[0] + R[4] * v[1] + R[7] * v[2];
  out[2] = R[2] * v[0] + R[5] * v[1] + R[8] * v[2];
}

/// Symmetric tensor (xx yy zz xy xz yz) times a vector.
inline void sym_mul(const double* S, const double* v, double* out) {
  out[0] = S[0] * v[0] + S[3] * v[1] + S[4] * v[2];
  out[1] = S[3] * v[0] + S[1] * v[1] + S[5] * v[2];
  out[2] = S[4] * v[0] + S[5] * v[1] + S[2] * v[2];
}

inline void cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/// Unit quaternion exp(φ/2) of a rotation vector φ. Below 0.1 rad (every ordinary step)
/// a Taylor series exact to double precision replaces sin and cos.
inline void exp_half(const double* phi, double* p) {
  const double a2 = phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2];
  double c, s;  // cos(a/2), sin(a/2)/a
  if (a2 < 0.01) {
    const double x = a2 / 4;  // (a/2)²; terms up to (a/2)^8 leave < 1e-19
    c = 1 - x / 2 * (1 - x / 12 * (1 - x / 30 * (1 - x / 56)));
    s = 0.5 * (1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72))));
  } else {
    const double a = std::sqrt(a2);
    c = std::cos(0.5 * a);
    s = std::sin(0.5 * a) / a;
  }
  p[0] = c;
  p[1] = s * phi[0];
  p[2] = s * phi[1];
  p[3] = s * phi[2];
}

/// out = p ⊗ q, renormalised.
inline void quat_mul_normalised(const double* p, const double* q, double* out) {
  const double r[4] = {p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
                       p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
                       p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
                       p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0]};
  const double n = 1 / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (int k = 0; k < 4; ++k) out[k] = r[k] * n;
}

/// out = p v p* for a unit quaternion p (v rotated by p).
inline void quat_rotate(const double* p, const double* v, double* out) {
  // t = 2 (u × v), out = v + w t + u × t, with p = (w, u).
  const double u[3] = {p[1], p[2], p[3]};
  double t[3], ut[3];
  cross(u, v, t);
  for (double& x : t) x *= 2;
  cross(u, t, ut);
  for (int k = 0; k < 3; ++k) out[k] = v[k] + p[0] * t[k] + ut[k];
}

/// Solves A x = b for a general 3×3 (row-major) by Cramer's rule (A well conditioned:
/// I + hθJ with I positive definite and h small).
inline void solve3(const double* A, const double* b, double* x) {
  const double c0 = A[4] * A[8] - A[5] * A[7], c1 = A[5] * A[6] - A[3] * A[8], c2 = A[3] * A[7] - A[4] * A[6];
  const double det = A[0] * c0 + A[1] * c1 + A[2] * c2;
  const double inv = 1 / det;
  x[0] = (b[0] * c0 + A[1] * (A[5] * b[2] - b[1] * A[8]) + A[2] * (b[1] * A[7] - A[4] * b[2])) * inv;
  x[1] = (A[0] * (b[1] * A[8] - A[5] * b[2]) + b[0] * c1 + A[2] * (A[3] * b[2] - b[1] * A[6])) * inv;
  x[2] = (A[0] * (A[4] * b[2] - b[1] * A[7]) + A[1] * (b[1] * A[6] - A[3] * b[2]) + b[0] * c2) * inv;
}

}  // namespace moreau::theta
