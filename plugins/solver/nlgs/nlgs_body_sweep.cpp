#include "nlgs_body_sweep.hpp"

#include <algorithm>
#include <moreau/error.hpp>
#include <string>

namespace moreau::nlgs {

namespace {

/// Offsets inside a record of dimension D with K unknowns per body.
template <int D, int K>
struct Layout {
  static constexpr int A = 0, q = D * D, mu = q + D, H = mu + 1, G = H + 2 * D * K, size = G + 2 * K * D;
};

template <int D, int K>
void sweep_impl(const LocalOptions& local, const double* rec, const int* body, double* dv, double* r, double omega,
                const std::vector<Eigen::Index>& order) {
  using L = Layout<D, K>;
  for (Eigen::Index a : order) {
    const double* R = rec + a * L::size;
    const int b0 = body[2 * a], b1 = body[2 * a + 1];
    double* ra = r + a * D;
    // b = u_α without the contact's own part: q + Σ_s H_s Δv_s − A r_α.
    double b[D], old[D], rn[D];
    for (int i = 0; i < D; ++i) {
      double s = R[L::q + i];
      for (int j = 0; j < D; ++j) s -= R[L::A + i * D + j] * ra[j];
      b[i] = s;
      old[i] = rn[i] = ra[i];
    }
    if (b0 >= 0) {
      const double* H = R + L::H;
      const double* v = dv + b0 * K;
      for (int i = 0; i < D; ++i)
        for (int l = 0; l < K; ++l) b[i] += H[i * K + l] * v[l];
    }
    if (b1 >= 0) {
      const double* H = R + L::H + D * K;
      const double* v = dv + b1 * K;
      for (int i = 0; i < D; ++i)
        for (int l = 0; l < K; ++l) b[i] += H[i * K + l] * v[l];
    }
    solve_local(local, D, R + L::A, b, R[L::mu], rn);
    double dr[D];
    for (int i = 0; i < D; ++i) {
      const double x = omega * rn[i] + (1 - omega) * old[i];
      dr[i] = x - old[i];
      ra[i] = x;
    }
    if (b0 >= 0) {
      const double* G = R + L::G;
      double* v = dv + b0 * K;
      for (int l = 0; l < K; ++l)
        for (int i = 0; i < D; ++i) v[l] += G[l * D + i] * dr[i];
    }
    if (b1 >= 0) {
      const double* G = R + L::G + K * D;
      double* v = dv + b1 * K;
      for (int l = 0; l < K; ++l)
        for (int i = 0; i < D; ++i) v[l] += G[l * D + i] * dr[i];
    }
  }
}

}  // namespace

void BodySweeper::prepare(const LocalProblem& P, const Eigen::VectorXd& r) {
  const BodyFactor& f = P.factor;
  if (!f.present()) throw InputError("/solver/exchange", "\"bodies\" needs the factored form W = H M⁻¹ Hᵀ, which only the time-stepper gives (not an FCLib file); use \"auto\" or \"w\"");
  d_ = P.dim;
  k_ = f.k;
  const int d = d_, k = k_;
  if (!((d == 2 && k == 3) || (d == 3 && k == 6)))
    throw InputError("/solver/exchange", "\"bodies\" supports rigid bodies (2D: 3 unknowns per body, 3D: 6), not dim " +
                std::to_string(d) + " with " + std::to_string(k));
  const std::size_t nc = static_cast<std::size_t>(P.contacts());
  stride_ = static_cast<std::size_t>(d * d + d + 1 + 4 * d * k);
  rec_.assign(nc * stride_, 0.0);
  body_.assign(2 * nc, -1);
  // Moving bodies numbered by first use, so Δv blocks sit in the order contacts reach them.
  std::vector<int> compact(f.inverse_mass.size() / static_cast<std::size_t>(k * k), -1);
  int next = 0;
  for (std::size_t a = 0; a < nc; ++a) {
    double* R = &rec_[a * stride_];
    double* A = R;
    double* q = R + d * d;
    R[d * d + d] = P.mu[static_cast<Eigen::Index>(a)];
    for (int i = 0; i < d; ++i) q[i] = P.q[static_cast<Eigen::Index>(a * d + i)];
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      if (compact[b] < 0) compact[b] = next++;
      body_[2 * a + side] = compact[b];
      const double* Hs = &f.H[(a * 2 + side) * d * k];
      const double* Mi = &f.inverse_mass[static_cast<std::size_t>(b) * k * k];
      double* H = R + d * d + d + 1 + side * d * k;
      double* G = R + d * d + d + 1 + 2 * d * k + side * k * d;
      for (int i = 0; i < d * k; ++i) H[i] = Hs[i];
      for (int l = 0; l < k; ++l)
        for (int i = 0; i < d; ++i) {
          double s = 0;
          for (int m = 0; m < k; ++m) s += Mi[l * k + m] * Hs[i * k + m];
          G[l * d + i] = s;
        }
      for (int i = 0; i < d; ++i)  // A += H_s G_s
        for (int j = 0; j < d; ++j) {
          double s = 0;
          for (int l = 0; l < k; ++l) s += Hs[i * k + l] * G[l * d + j];
          A[i * d + j] += s;
        }
    }
  }
  dv_.assign(static_cast<std::size_t>(next) * k, 0.0);
  reset_velocities(r);
}

void BodySweeper::reset_velocities(const Eigen::VectorXd& r) {
  const int d = d_, k = k_;
  std::fill(dv_.begin(), dv_.end(), 0.0);
  const std::size_t nc = body_.size() / 2;
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = body_[2 * a + side];
      if (b < 0) continue;
      const double* G = &rec_[a * stride_ + d * d + d + 1 + 2 * d * k + side * k * d];
      for (int l = 0; l < k; ++l)
        for (int i = 0; i < d; ++i) dv_[b * k + l] += G[l * d + i] * r[static_cast<Eigen::Index>(a * d + i)];
    }
}

void BodySweeper::sweep(Eigen::VectorXd& r, double omega, const std::vector<Eigen::Index>& order) {
  if (d_ == 2)
    sweep_impl<2, 3>(local_, rec_.data(), body_.data(), dv_.data(), r.data(), omega, order);
  else
    sweep_impl<3, 6>(local_, rec_.data(), body_.data(), dv_.data(), r.data(), omega, order);
}

void BodySweeper::velocities(const Eigen::VectorXd& r, Eigen::VectorXd& u) {
  reset_velocities(r);
  const int d = d_, k = k_;
  const std::size_t nc = body_.size() / 2;
  u.resize(static_cast<Eigen::Index>(nc * d));
  for (std::size_t a = 0; a < nc; ++a) {
    const double* R = &rec_[a * stride_];
    for (int i = 0; i < d; ++i) {
      double s = R[d * d + i];
      for (int side = 0; side < 2; ++side) {
        const int b = body_[2 * a + side];
        if (b < 0) continue;
        const double* H = R + d * d + d + 1 + side * d * k;
        for (int l = 0; l < k; ++l) s += H[i * k + l] * dv_[b * k + l];
      }
      u[static_cast<Eigen::Index>(a * d + i)] = s;
    }
  }
}

}  // namespace moreau::nlgs
