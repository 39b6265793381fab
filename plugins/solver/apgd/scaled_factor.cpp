#include "scaled_factor.hpp"

#include <algorithm>
#include <cmath>

namespace moreau::apgd {

namespace {

/// Cholesky factor L (row-major, lower) of the symmetric positive semi-definite k × k
/// matrix A, zero columns for zero pivots (a body locked in some directions has zero rows
/// and columns in M⁻¹). False when L Lᵀ does not give A back to rounding (A indefinite, or
/// semi-definite with a zero pivot on a coupled direction).
/// `diagonal` is set when A is diagonal (a sphere's or a disk's inverse mass): L is then
/// diagonal too (the same entries the general loop gives), and H L a scaling of H's columns.
bool semidefinite_cholesky(int k, const double* A, double* L, bool& diagonal) {
  double scale = 0;
  for (int i = 0; i < k; ++i) scale = std::max(scale, std::fabs(A[i * k + i]));
  std::fill(L, L + k * k, 0.0);
  diagonal = true;
  for (int i = 0; i < k && diagonal; ++i)
    for (int j = 0; j < k; ++j)
      if (i != j && A[i * k + j] != 0) {
        diagonal = false;
        break;
      }
  if (scale == 0) return true;  // a body impulses do not move
  const double tiny = 1e-14 * scale;
  if (diagonal) {
    for (int j = 0; j < k; ++j)
      if (A[j * k + j] > tiny) L[j * k + j] = std::sqrt(A[j * k + j]);
      else if (A[j * k + j] < -1e-12 * scale) return false;  // as the general check below
    return true;
  }
  for (int j = 0; j < k; ++j) {
    double p = A[j * k + j];
    for (int l = 0; l < j; ++l) p -= L[j * k + l] * L[j * k + l];
    if (p <= tiny) continue;  // a zero column
    const double Ljj = std::sqrt(p);
    L[j * k + j] = Ljj;
    for (int i = j + 1; i < k; ++i) {
      double s = A[i * k + j];
      for (int l = 0; l < j; ++l) s -= L[i * k + l] * L[j * k + l];
      L[i * k + j] = s / Ljj;
    }
  }
  for (int i = 0; i < k; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = 0;
      for (int l = 0; l <= j; ++l) s += L[i * k + l] * L[j * k + l];
      if (std::fabs(s - A[i * k + j]) > 1e-12 * scale) return false;
    }
  return true;
}

template <int D, int K>
void multiply_impl(std::size_t nc, const double* H, const int* body, double* z, std::size_t nz, const double* x, double* out,
                   const double* diag) {
  std::fill(z, z + nz, 0.0);
  for (std::size_t a = 0; a < nc; ++a) {  // z = H̃ᵀ x, per moving body
    const double* xa = x + a * D;
    for (int s = 0; s < 2; ++s) {
      const int b = body[2 * a + s];
      if (b < 0) continue;
      const double* h = H + (2 * a + s) * D * K;
      double* zb = z + static_cast<std::size_t>(b) * K;
      for (int l = 0; l < K; ++l) {
        double t = 0;
        for (int i = 0; i < D; ++i) t += h[i * K + l] * xa[i];
        zb[l] += t;
      }
    }
  }
  for (std::size_t a = 0; a < nc; ++a) {  // out = H̃ z
    double o[D] = {};
    for (int s = 0; s < 2; ++s) {
      const int b = body[2 * a + s];
      if (b < 0) continue;
      const double* h = H + (2 * a + s) * D * K;
      const double* zb = z + static_cast<std::size_t>(b) * K;
      for (int i = 0; i < D; ++i)
        for (int l = 0; l < K; ++l) o[i] += h[i * K + l] * zb[l];
    }
    for (int i = 0; i < D; ++i) out[a * D + i] = diag ? o[i] + diag[a * D + i] * x[a * D + i] : o[i];
  }
}

}  // namespace

bool ScaledFactor::prepare(int d, const BodyFactor& f) {
  nc_ = 0;
  const int k = f.k;
  if (!((d == 2 && k == 3) || (d == 3 && k == 6))) return false;
  const std::size_t nc = f.body.size() / 2, nb = f.inverse_mass.size() / static_cast<std::size_t>(k * k);
  // Each moving body's L, computed once, numbered by first use. The arrays are the last
  // call's, resized (a solve per time step: at 10⁴ spheres H̃ alone is 9 MB, which a fresh
  // array paid in page faults and zero fills at every step); every entry used is written.
  std::vector<int>& compact = compact_;
  std::vector<double>& L = L_;
  std::vector<char>& diagonal = diagonal_;  // per moving body: L is diagonal
  compact.assign(nb, -1);
  L.clear();
  diagonal.clear();
  body_.resize(2 * nc);
  int next = 0;
  for (std::size_t s = 0; s < 2 * nc; ++s) {
    const int b = f.body[s];
    body_[s] = -1;
    if (b < 0) continue;
    if (compact[b] < 0) {
      compact[b] = next++;
      L.resize(static_cast<std::size_t>(next) * k * k);
      bool diag = false;
      if (!semidefinite_cholesky(k, &f.inverse_mass[static_cast<std::size_t>(b) * k * k], &L[static_cast<std::size_t>(compact[b]) * k * k], diag))
        return false;
      diagonal.push_back(diag ? 1 : 0);
    }
    body_[s] = compact[b];
  }
  H_.resize(2 * nc * d * k);
  for (std::size_t s = 0; s < 2 * nc; ++s) {  // H̃ = H L
    const int b = body_[s];
    double* out = &H_[s * d * k];
    if (b < 0) {
      std::fill(out, out + d * k, 0.0);
      continue;
    }
    const double* h = &f.H[s * d * k];
    const double* l = &L[static_cast<std::size_t>(b) * k * k];
    if (diagonal[static_cast<std::size_t>(b)]) {
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < k; ++j) out[i * k + j] = h[i * k + j] * l[j * k + j];
      continue;
    }
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < k; ++j) {
        double t = 0;
        for (int m = j; m < k; ++m) t += h[i * k + m] * l[m * k + j];  // L is lower: L[m][j] = 0 for m < j
        out[i * k + j] = t;
      }
  }
  z_.resize(static_cast<std::size_t>(next) * k);  // zeroed by each product
  diag_ = f.diagonal;
  d_ = d;
  k_ = k;
  nc_ = nc;
  return true;
}

void ScaledFactor::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  out.resize(x.size());
  const double* diag = diag_.empty() ? nullptr : diag_.data();
  if (d_ == 2)
    multiply_impl<2, 3>(nc_, H_.data(), body_.data(), z_.data(), z_.size(), x.data(), out.data(), diag);
  else
    multiply_impl<3, 6>(nc_, H_.data(), body_.data(), z_.data(), z_.size(), x.data(), out.data(), diag);
}

Eigen::VectorXd ScaledFactor::diagonal() const {
  const int d = d_, k = k_;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nc_ * d));
  for (std::size_t s = 0; s < 2 * nc_; ++s) {
    if (body_[s] < 0) continue;
    const double* h = &H_[s * d * k];
    for (int i = 0; i < d; ++i) {
      double t = 0;
      for (int l = 0; l < k; ++l) t += h[i * k + l] * h[i * k + l];
      w[static_cast<Eigen::Index>(s / 2 * d + i)] += t;
    }
  }
  for (std::size_t i = 0; i < diag_.size(); ++i) w[static_cast<Eigen::Index>(i)] += diag_[i];
  return w;
}

}  // namespace moreau::apgd
