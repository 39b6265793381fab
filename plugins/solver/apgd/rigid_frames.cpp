#include "rigid_frames.hpp"

#include <algorithm>
#include <cmath>

namespace moreau::apgd {

namespace {

inline void cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/// I⁻¹ (xx yy zz xy xz yz) times w.
inline void inertia_times(const double* I, const double* w, double* out) {
  out[0] = I[0] * w[0] + I[3] * w[1] + I[4] * w[2];
  out[1] = I[3] * w[0] + I[1] * w[1] + I[5] * w[2];
  out[2] = I[4] * w[0] + I[5] * w[1] + I[2] * w[2];
}

/// The lever arm r of one side from its block (translational rows ±E, rotational rows
/// ±(r × e_i)), into `r`; false when the block is not of that form to rounding.
bool lever(const double* h, double sign, const double* E, double* r) {
  double c[9], scale = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (std::fabs(sign * h[i * 6 + j] - E[i * 3 + j]) > 1e-13) return false;
      c[i * 3 + j] = sign * h[i * 6 + 3 + j];
      scale = std::max(scale, std::fabs(c[i * 3 + j]));
    }
  r[0] = r[1] = r[2] = 0;
  for (int i = 0; i < 3; ++i) {  // Σ_i e_i × (r × e_i) = 3r − Σ_i e_i (e_i · r) = 2r
    double t[3];
    cross(&E[i * 3], &c[i * 3], t);
    for (int j = 0; j < 3; ++j) r[j] += 0.5 * t[j];
  }
  for (int i = 0; i < 3; ++i) {
    double t[3];
    cross(r, &E[i * 3], t);
    for (int j = 0; j < 3; ++j)
      if (std::fabs(t[j] - c[i * 3 + j]) > 1e-12 * scale) return false;
  }
  return true;
}

/// 1/m I₃ ⊕ I⁻¹ from a 6 × 6 inverse mass into m (7 values); false for another form. I⁻¹
/// in world axes, R I⁻¹ Rᵀ, is symmetric only to rounding: its two halves are averaged.
bool rigid_inverse_mass(const double* M, double* m) {
  double scale = 0;
  for (int i = 3; i < 6; ++i) scale = std::max(scale, std::fabs(M[i * 6 + i]));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (M[i * 6 + 3 + j] != 0 || M[(3 + i) * 6 + j] != 0) return false;  // no coupling
      if (i != j && M[i * 6 + j] != 0) return false;
      if (std::fabs(M[(3 + i) * 6 + 3 + j] - M[(3 + j) * 6 + 3 + i]) > 1e-12 * scale) return false;
    }
  if (M[7] != M[0] || M[14] != M[0]) return false;
  m[0] = M[0];
  m[1] = M[21], m[2] = M[28], m[3] = M[35];
  m[4] = 0.5 * (M[22] + M[27]), m[5] = 0.5 * (M[23] + M[33]), m[6] = 0.5 * (M[29] + M[34]);
  return true;
}

}  // namespace

bool RigidFrames::prepare(int d, const BodyFactor& f) {
  nc_ = 0;
  if (d != 3 || f.k != 6) return false;
  const std::size_t nc = f.body.size() / 2, nb = f.inverse_mass.size() / 36;
  compact_.assign(nb, -1);
  mass_.clear();
  body_.resize(2 * nc);
  contact_.resize(15 * nc);
  int next = 0;
  for (std::size_t a = 0; a < nc; ++a) {
    double* c = &contact_[15 * a];
    std::fill(c, c + 15, 0.0);
    const int first = f.body[2 * a] >= 0 ? 0 : f.body[2 * a + 1] >= 0 ? 1 : -1;
    body_[2 * a] = body_[2 * a + 1] = -1;
    if (first < 0) continue;  // no moving body: the row is the compliance alone
    const double* h = &f.H[(2 * a + first) * 18];
    const double sign = first == 0 ? 1.0 : -1.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[i * 3 + j] = sign * h[i * 6 + j];
    for (int i = 0; i < 3; ++i)  // E orthonormal
      for (int j = 0; j < 3; ++j) {
        const double dot = c[i * 3] * c[j * 3] + c[i * 3 + 1] * c[j * 3 + 1] + c[i * 3 + 2] * c[j * 3 + 2];
        if (std::fabs(dot - (i == j ? 1.0 : 0.0)) > 1e-12) return false;
      }
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      if (!lever(&f.H[(2 * a + side) * 18], side == 0 ? 1.0 : -1.0, c, c + 9 + 3 * side)) return false;
      if (compact_[b] < 0) {
        compact_[b] = next++;
        mass_.resize(static_cast<std::size_t>(next) * 7);
        if (!rigid_inverse_mass(&f.inverse_mass[static_cast<std::size_t>(b) * 36], &mass_[static_cast<std::size_t>(compact_[b]) * 7]))
          return false;
      }
      body_[2 * a + side] = compact_[b];
    }
  }
  z_.resize(static_cast<std::size_t>(next) * 6);
  diag_ = f.diagonal;
  nc_ = nc;
  return true;
}

void RigidFrames::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  out.resize(x.size());
  std::fill(z_.begin(), z_.end(), 0.0);
  const double* C = contact_.data();
  const int* body = body_.data();
  double* z = z_.data();
  for (std::size_t a = 0; a < nc_; ++a) {  // z = Hᵀ x: each body's impulse and angular impulse
    const double* E = C + 15 * a;
    const double* xa = x.data() + 3 * a;
    const double f[3] = {E[0] * xa[0] + E[3] * xa[1] + E[6] * xa[2], E[1] * xa[0] + E[4] * xa[1] + E[7] * xa[2],
                         E[2] * xa[0] + E[5] * xa[1] + E[8] * xa[2]};
    for (int s = 0; s < 2; ++s) {
      const int b = body[2 * a + s];
      if (b < 0) continue;
      double t[3];
      cross(E + 9 + 3 * s, f, t);
      double* zb = z + 6 * static_cast<std::size_t>(b);
      if (s == 0)
        for (int j = 0; j < 3; ++j) zb[j] += f[j], zb[3 + j] += t[j];
      else
        for (int j = 0; j < 3; ++j) zb[j] -= f[j], zb[3 + j] -= t[j];
    }
  }
  const std::size_t nb = z_.size() / 6;
  for (std::size_t b = 0; b < nb; ++b) {  // z = M⁻¹ z: each body's velocity change
    const double* m = &mass_[7 * b];
    double* zb = z + 6 * b;
    double w[3];
    inertia_times(m + 1, zb + 3, w);
    for (int j = 0; j < 3; ++j) zb[j] *= m[0], zb[3 + j] = w[j];
  }
  const double* diag = diag_.empty() ? nullptr : diag_.data();
  for (std::size_t a = 0; a < nc_; ++a) {  // out = H z: E (u₀ − u₁), u_s = v_s + ω_s × r_s
    const double* E = C + 15 * a;
    double u[3] = {0, 0, 0};
    for (int s = 0; s < 2; ++s) {
      const int b = body[2 * a + s];
      if (b < 0) continue;
      const double* zb = z + 6 * static_cast<std::size_t>(b);
      double t[3];
      cross(zb + 3, E + 9 + 3 * s, t);
      if (s == 0)
        for (int j = 0; j < 3; ++j) u[j] += zb[j] + t[j];
      else
        for (int j = 0; j < 3; ++j) u[j] -= zb[j] + t[j];
    }
    double* o = out.data() + 3 * a;
    for (int i = 0; i < 3; ++i) o[i] = E[3 * i] * u[0] + E[3 * i + 1] * u[1] + E[3 * i + 2] * u[2];
    if (diag)
      for (int i = 0; i < 3; ++i) o[i] += diag[3 * a + i] * x[static_cast<Eigen::Index>(3 * a + i)];
  }
}

Eigen::VectorXd RigidFrames::diagonal() const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(3 * nc_));
  for (std::size_t a = 0; a < nc_; ++a) {
    const double* E = &contact_[15 * a];
    for (int s = 0; s < 2; ++s) {
      const int b = body_[2 * a + s];
      if (b < 0) continue;
      const double* m = &mass_[7 * static_cast<std::size_t>(b)];
      for (int i = 0; i < 3; ++i) {
        double t[3], It[3];
        cross(&E[9 + 3 * s], &E[3 * i], t);  // the rotational row r × e_i
        inertia_times(m + 1, t, It);
        const double e2 = E[3 * i] * E[3 * i] + E[3 * i + 1] * E[3 * i + 1] + E[3 * i + 2] * E[3 * i + 2];
        w[static_cast<Eigen::Index>(3 * a + i)] += m[0] * e2 + t[0] * It[0] + t[1] * It[1] + t[2] * It[2];
      }
    }
  }
  for (std::size_t i = 0; i < diag_.size(); ++i) w[static_cast<Eigen::Index>(i)] += diag_[i];
  return w;
}

}  // namespace moreau::apgd
