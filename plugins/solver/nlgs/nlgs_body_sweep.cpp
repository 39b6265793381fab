#include "nlgs_body_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <moreau/error.hpp>
#include <moreau/factor_matrix.hpp>
#include <string>

namespace moreau::nlgs {

namespace {

/// Offsets inside a record of dimension D with K unknowns per body. Iso: both bodies'
/// inverse masses are scalars per block (spheres, disks): the record keeps them (m: side
/// 0 translation, rotation, side 1 the same) instead of G = M⁻¹Hᵀ, 53 doubles in 3D
/// instead of 85.
template <int D, int K, bool Iso = false>
struct Layout {
  static constexpr int A = 0, q = D * D, mu = q + D, m = mu + 1, H = Iso ? m + 4 : mu + 1, G = H + 2 * D * K,
                       size = Iso ? G : G + 2 * K * D;
};

/// D: rows kept per contact (1: frictionless, the normal only); K: columns per body;
/// rd: the stride of r (the problem's dimension).
/// diag: the laws' compliance (BodyFactor::diagonal, rd per contact) or null: part of A,
/// not of the body velocities, so the contact's own part b leaves out is A − diag.
template <int D, int K, bool Iso = false>
void sweep_impl(const LocalOptions& local, const double* rec, const int* body, double* dv, double* r, int rd, double omega,
                const std::vector<Eigen::Index>& order, const double* diag) {
  using L = Layout<D, K, Iso>;
  for (Eigen::Index a : order) {
    const double* R = rec + a * L::size;
    const int b0 = body[2 * a], b1 = body[2 * a + 1];
    double* ra = r + a * rd;
    // b = u_α without the contact's own part: q + Σ_s H_s Δv_s − A r_α.
    double b[D], old[D], rn[D];
    for (int i = 0; i < D; ++i) {
      double s = R[L::q + i];
      for (int j = 0; j < D; ++j) s -= R[L::A + i * D + j] * ra[j];
      if (diag) s += diag[a * rd + i] * ra[i];
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
    if constexpr (D == 1) {  // frictionless: u_n = A r_n + b ≥ 0, r_n ≥ 0, complementary
      rn[0] = R[L::A] > 0 ? std::max(0.0, -b[0] / R[L::A]) : 0.0;
      for (int i = 1; i < rd; ++i) ra[i] = 0;  // r_t = 0 when μ = 0
    } else {
      solve_local(local, D, R + L::A, b, R[L::mu], rn);
    }
    double dr[D];
    for (int i = 0; i < D; ++i) {
      const double x = omega * rn[i] + (1 - omega) * old[i];
      dr[i] = x - old[i];
      ra[i] = x;
    }
    for (int side = 0; side < 2; ++side) {
      const int bs = side == 0 ? b0 : b1;
      if (bs < 0) continue;
      double* v = dv + bs * K;
      if constexpr (Iso) {  // Δv = M⁻¹ Hᵀ dr with M⁻¹ = diag(m_t, m_r): D translations first
        const double* H = R + L::H + side * D * K;
        const double* m = R + L::m + 2 * side;
        for (int l = 0; l < K; ++l) {
          double s = 0;
          for (int i = 0; i < D; ++i) s += H[i * K + l] * dr[i];
          v[l] += (l < D ? m[0] : m[1]) * s;
        }
      } else {
        const double* G = R + L::G + side * K * D;
        for (int l = 0; l < K; ++l)
          for (int i = 0; i < D; ++i) v[l] += G[l * D + i] * dr[i];
      }
    }
  }
}

/// Whether no contact of P turns a body through its normal row (the rotation columns of
/// the normal rows of H add at most 1e-14 of A_nn) and every inverse mass leaves
/// translation and rotation uncoupled: then a frictionless problem needs no rotation.
bool normals_through_centres(const LocalProblem& P) {
  const BodyFactor& f = P.factor;
  const int d = P.dim, k = f.k;
  for (Eigen::Index a = 0; a < P.contacts(); ++a) {
    double trans = 0, rot = 0;
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      const double* H = &f.H[(static_cast<std::size_t>(a) * 2 + side) * d * k];  // row 0: the normal
      const double* Mi = &f.inverse_mass[static_cast<std::size_t>(b) * k * k];
      for (int i = 0; i < d; ++i)
        for (int j = d; j < k; ++j)
          if (Mi[i * k + j] != 0 || Mi[j * k + i] != 0) return false;
      for (int i = 0; i < d; ++i) trans += H[i] * Mi[i * k + i] * H[i];
      for (int i = d; i < k; ++i)
        for (int j = d; j < k; ++j) rot += std::fabs(H[i] * Mi[i * k + j] * H[j]);
    }
    if (rot > 1e-14 * trans) return false;
  }
  return true;
}

/// The translation and rotation scalars of a body's inverse mass when it is diagonal with
/// one value per block (to 1e-12: a sphere's world inertia R I⁻¹ Rᵀ has rounding off the
/// diagonal); false otherwise.
bool isotropic(const double* Mi, int d, int k, double& mt, double& mr) {
  mt = Mi[0];
  mr = Mi[d * k + d];
  const double scale = std::max(std::fabs(mt), std::fabs(mr));
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double want = i != j ? 0.0 : i < d ? mt : mr;
      if (std::fabs(Mi[i * k + j] - want) > 1e-12 * scale) return false;
    }
  return true;
}

}  // namespace

BodySweeper::Offsets BodySweeper::offsets(int pd, int pk, bool iso) {
  const int H = pd * pd + pd + 1 + (iso ? 4 : 0);
  const int G = H + 2 * pd * pk;
  return {H, G, static_cast<std::size_t>(G + (iso ? 0 : 2 * pd * pk))};
}

std::size_t BodySweeper::largest_record_size(int d, int k) {
  return std::max(offsets(d, k, true).stride, offsets(d, k, false).stride);
}

void BodySweeper::prepare(const LocalProblem& P, const Eigen::VectorXd& r) {
  layout(P);
  pack(P, r);
}

void BodySweeper::layout(const LocalProblem& P) {
  const BodyFactor& f = P.factor;
  if (!f.present()) throw InputError("/solver/exchange", "\"bodies\" needs the factored form W = H M⁻¹ Hᵀ, which only the time-stepper gives (not an FCLib file); use \"auto\" or \"w\"");
  d_ = P.dim;
  k_ = f.k;
  problem_ = &P;
  const int d = d_, k = k_;
  if (!supports(d, k))
    throw InputError("/solver/exchange", "\"bodies\" supports rigid bodies (2D: 3 unknowns per body, 3D: 6), not dim " +
                std::to_string(d) + " with " + std::to_string(k));
  const bool frictionless = (P.mu.array() == 0.0).all();
  pd_ = frictionless ? 1 : d;
  pk_ = frictionless && normals_through_centres(P) ? d : k;
  const int pd = pd_, pk = pk_;
  // Scalar inverse masses (with friction: the frictionless records are small already).
  iso_ = pd == d && pk == k;
  // Each body once (a sphere has ~6 contact sides: at 10⁴ spheres checking every side was
  // about 0.8 ms a solve, which `auto` pays at every step for the records' size).
  std::vector<char>& checked = layout_checked_;
  checked.assign(f.inverse_mass.size() / static_cast<std::size_t>(k * k), 0);
  for (std::size_t i = 0; i < f.body.size() && iso_; ++i) {
    const int b = f.body[i];
    if (b < 0 || checked[static_cast<std::size_t>(b)]) continue;
    checked[static_cast<std::size_t>(b)] = 1;
    double mt, mr;
    iso_ = isotropic(&f.inverse_mass[static_cast<std::size_t>(b) * k * k], d, k, mt, mr);
  }
  const Offsets o = offsets(pd, pk, iso_);
  off_H_ = o.H;
  off_G_ = o.G;
  stride_ = o.stride;
}

void BodySweeper::pack(const LocalProblem& P, const Eigen::VectorXd& r) {
  const BodyFactor& f = P.factor;
  const int d = d_, k = k_, pd = pd_, pk = pk_;
  const std::size_t nc = static_cast<std::size_t>(P.contacts());
  rec_.assign(nc * stride_, 0.0);
  body_.assign(2 * nc, -1);
  // Moving bodies numbered by first use, so Δv blocks sit in the order contacts reach them.
  std::vector<int> compact(f.inverse_mass.size() / static_cast<std::size_t>(k * k), -1);
  int next = 0;
  std::vector<double> G(static_cast<std::size_t>(k * d));
  for (std::size_t a = 0; a < nc; ++a) {
    double* R = &rec_[a * stride_];
    double* A = R;
    double* q = R + pd * pd;
    R[pd * pd + pd] = P.mu[static_cast<Eigen::Index>(a)];
    for (int i = 0; i < pd; ++i) q[i] = P.q[static_cast<Eigen::Index>(a * d + i)];
    if (!f.diagonal.empty())  // the laws' compliance: part of W, not of H M⁻¹ Hᵀ
      for (int i = 0; i < pd; ++i) A[i * pd + i] += f.diagonal[a * d + i];
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      if (compact[b] < 0) compact[b] = next++;
      body_[2 * a + side] = compact[b];
      const double* Hs = &f.H[(a * 2 + side) * d * k];
      const double* Mi = &f.inverse_mass[static_cast<std::size_t>(b) * k * k];
      for (int l = 0; l < k; ++l)  // G = M⁻¹ Hᵀ, whole
        for (int i = 0; i < d; ++i) {
          double s = 0;
          for (int m = 0; m < k; ++m) s += Mi[l * k + m] * Hs[i * k + m];
          G[l * d + i] = s;
        }
      for (int i = 0; i < pd; ++i)  // A += H_s G_s over the kept rows
        for (int j = 0; j < pd; ++j) {
          double s = 0;
          for (int l = 0; l < k; ++l) s += Hs[i * k + l] * G[l * d + j];
          A[i * pd + j] += s;
        }
      double* H = R + off_H_ + side * pd * pk;
      for (int i = 0; i < pd; ++i)
        for (int l = 0; l < pk; ++l) H[i * pk + l] = Hs[i * k + l];
      if (iso_) {
        isotropic(Mi, d, k, R[pd * pd + pd + 1 + 2 * side], R[pd * pd + pd + 2 + 2 * side]);
      } else {
        double* Gp = R + off_G_ + side * pk * pd;
        for (int i = 0; i < pd; ++i)
          for (int l = 0; l < pk; ++l) Gp[l * pd + i] = G[l * d + i];
      }
    }
  }
  dv_.assign(static_cast<std::size_t>(next) * pk, 0.0);
  reset_velocities(r);
}

void BodySweeper::reset_velocities(const Eigen::VectorXd& r) {
  const int d = d_, pd = pd_, pk = pk_;
  std::fill(dv_.begin(), dv_.end(), 0.0);
  const std::size_t nc = body_.size() / 2;
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = body_[2 * a + side];
      if (b < 0) continue;
      const double* R = &rec_[a * stride_];
      const double* ra = &r[static_cast<Eigen::Index>(a * d)];
      if (iso_) {
        const double* H = R + off_H_ + side * pd * pk;
        const double* m = R + pd * pd + pd + 1 + 2 * side;
        for (int l = 0; l < pk; ++l)
          for (int i = 0; i < pd; ++i) dv_[b * pk + l] += (l < d ? m[0] : m[1]) * H[i * pk + l] * ra[i];
      } else {
        const double* G = R + off_G_ + side * pk * pd;
        for (int l = 0; l < pk; ++l)
          for (int i = 0; i < pd; ++i) dv_[b * pk + l] += G[l * pd + i] * ra[i];
      }
    }
}

void BodySweeper::sweep(Eigen::VectorXd& r, double omega, const std::vector<Eigen::Index>& order) {
  double* x = r.data();
  const double* R = rec_.data();
  const int* b = body_.data();
  double* v = dv_.data();
  const double* g = problem_->factor.diagonal.empty() ? nullptr : problem_->factor.diagonal.data();
  if (pd_ == 1) {
    if (pk_ == 2) sweep_impl<1, 2>(local_, R, b, v, x, d_, omega, order, g);
    else if (pk_ == 3) sweep_impl<1, 3>(local_, R, b, v, x, d_, omega, order, g);
    else sweep_impl<1, 6>(local_, R, b, v, x, d_, omega, order, g);
  } else if (d_ == 2) {
    if (iso_) sweep_impl<2, 3, true>(local_, R, b, v, x, d_, omega, order, g);
    else sweep_impl<2, 3>(local_, R, b, v, x, d_, omega, order, g);
  } else {
    if (iso_) sweep_impl<3, 6, true>(local_, R, b, v, x, d_, omega, order, g);
    else sweep_impl<3, 6>(local_, R, b, v, x, d_, omega, order, g);
  }
}

void BodySweeper::velocities(const Eigen::VectorXd& r, Eigen::VectorXd& u) {
  reset_velocities(r);
  const int d = d_, k = k_;
  const std::size_t nc = body_.size() / 2;
  u.resize(static_cast<Eigen::Index>(nc * d));
  if (pd_ == d && pk_ == k) {
    for (std::size_t a = 0; a < nc; ++a) {
      const double* R = &rec_[a * stride_];
      for (int i = 0; i < d; ++i) {
        double s = R[d * d + i];
        for (int side = 0; side < 2; ++side) {
          const int b = body_[2 * a + side];
          if (b < 0) continue;
          const double* H = R + off_H_ + side * d * k;
          for (int l = 0; l < k; ++l) s += H[i * k + l] * dv_[b * k + l];
        }
        if (!problem_->factor.diagonal.empty()) s += problem_->factor.diagonal[a * d + i] * r[static_cast<Eigen::Index>(a * d + i)];
        u[static_cast<Eigen::Index>(a * d + i)] = s;
      }
    }
    return;
  }
  // Packed records lack the tangential rows (and maybe the rotations): u = q + H M⁻¹ Hᵀ r
  // from the problem's own factor, so the caller still gets every component.
  multiply_w(d, problem_->factor, r, u, full_impulse_, full_dv_);
  u += problem_->q;
}

}  // namespace moreau::nlgs
