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

/// q ← q ⊗ exp(φ/2) for a body-frame rotation vector φ, renormalised.
inline void rotate_body(const double* q, const double* phi, double* out) {
  const double a = std::sqrt(phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2]);
  double c, s;  // exp(φ/2) = (cos(a/2), sin(a/2) φ/a)
  if (a < 1e-8) {
    c = 1 - a * a / 8;
    s = 0.5 - a * a / 48;  // sin(a/2)/a
  } else {
    c = std::cos(0.5 * a);
    s = std::sin(0.5 * a) / a;
  }
  const double pw = c, px = s * phi[0], py = s * phi[1], pz = s * phi[2];
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  double r[4] = {w * pw - x * px - y * py - z * pz, w * px + x * pw + y * pz - z * py,
                 w * py - x * pz + y * pw + z * px, w * pz + x * py - y * px + z * pw};
  const double n = 1 / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (int k = 0; k < 4; ++k) out[k] = r[k] * n;
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
