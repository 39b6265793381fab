#include "rigid_assembly.hpp"

#include <algorithm>

namespace moreau::kernel {

namespace {

/// H block of one side: rows of the local frame applied to [I, −[r]×] (3D) or
/// [I, (−r_y, r_x)ᵀ] (2D), times `sign`.
void h_block(int dim, const double frame[3][3], const double r[3], double sign, double* H) {
  if (dim == 2) {
    for (int i = 0; i < 2; ++i) {
      const double* e = frame[i];
      H[i * 3 + 0] = sign * e[0];
      H[i * 3 + 1] = sign * e[1];
      H[i * 3 + 2] = sign * (-e[0] * r[1] + e[1] * r[0]);  // e · (ω ẑ × r)
    }
    return;
  }
  for (int i = 0; i < 3; ++i) {
    const double* e = frame[i];
    H[i * 6 + 0] = sign * e[0];
    H[i * 6 + 1] = sign * e[1];
    H[i * 6 + 2] = sign * e[2];
    // e · (ω × r) = ω · (r × e)
    H[i * 6 + 3] = sign * (r[1] * e[2] - r[2] * e[1]);
    H[i * 6 + 4] = sign * (r[2] * e[0] - r[0] * e[2]);
    H[i * 6 + 5] = sign * (r[0] * e[1] - r[1] * e[0]);
  }
}

}  // namespace

void RigidAssembly::build(const RigidBodies& bodies, const std::vector<RigidContact>& contacts) {
  dim_ = bodies.dim;
  k_ = bodies.k();
  contacts_ = contacts;
  const int d = dim_, k = k_;
  const std::size_t nc = contacts.size();
  H_.assign(nc * 2 * d * k, 0.0);
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = contacts[a].body[side];
      const double* c = &bodies.com[3 * b];
      const double r[3] = {contacts[a].point[0] - c[0], contacts[a].point[1] - c[1], contacts[a].point[2] - c[2]};
      h_block(d, contacts[a].frame, r, side == 0 ? 1.0 : -1.0, &H_[(a * 2 + side) * d * k]);
    }

  // Contacts touching each body; W_αβ = Σ over shared bodies of H_α,b M_b⁻¹ H_β,bᵀ.
  const std::size_t nb = bodies.com.size() / 3;
  std::vector<std::vector<std::pair<int, int>>> touching(nb);  // (contact, side)
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) touching[contacts[a].body[side]].push_back({static_cast<int>(a), side});

  std::vector<Eigen::Triplet<double>> trip;
  std::vector<double> HM(d * k);  // H_α,b M_b⁻¹
  for (std::size_t b = 0; b < nb; ++b) {
    const double* Mi = &bodies.inverse_mass[b * k * k];
    if (std::all_of(Mi, Mi + k * k, [](double x) { return x == 0.0; })) continue;  // fixed: no coupling
    for (auto [a, sa] : touching[b]) {
      const double* Ha = &H_[(a * 2 + sa) * d * k];
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < k; ++j) {
          double s = 0;
          for (int l = 0; l < k; ++l) s += Ha[i * k + l] * Mi[l * k + j];
          HM[i * k + j] = s;
        }
      for (auto [c, sc] : touching[b]) {
        const double* Hc = &H_[(c * 2 + sc) * d * k];
        for (int i = 0; i < d; ++i)
          for (int j = 0; j < d; ++j) {
            double s = 0;
            for (int l = 0; l < k; ++l) s += HM[i * k + l] * Hc[j * k + l];
            trip.emplace_back(a * d + i, c * d + j, s);
          }
      }
    }
  }
  W_.resize(static_cast<Eigen::Index>(nc * d), static_cast<Eigen::Index>(nc * d));
  W_.setFromTriplets(trip.begin(), trip.end());  // sums the contributions of both bodies
}

Eigen::VectorXd RigidAssembly::local_velocity(const std::vector<double>& v) const {
  const int d = dim_, k = k_;
  const std::size_t nc = contacts_.size();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nc * d));
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const double* H = &H_[(a * 2 + side) * d * k];
      const double* vb = &v[contacts_[a].body[side] * k];
      for (int i = 0; i < d; ++i) {
        double s = 0;
        for (int l = 0; l < k; ++l) s += H[i * k + l] * vb[l];
        u[static_cast<Eigen::Index>(a * d + i)] += s;
      }
    }
  return u;
}

Eigen::VectorXd RigidAssembly::free_local_velocity(const RigidBodies& bodies) const {
  return local_velocity(bodies.free_velocity);
}

void RigidAssembly::body_impulses(const Eigen::VectorXd& r, std::size_t n_bodies, std::vector<double>& out) const {
  const int d = dim_, k = k_;
  out.assign(n_bodies * k, 0.0);
  for (std::size_t a = 0; a < contacts_.size(); ++a)
    for (int side = 0; side < 2; ++side) {
      const double* H = &H_[(a * 2 + side) * d * k];
      double* P = &out[contacts_[a].body[side] * k];
      for (int l = 0; l < k; ++l) {
        double s = 0;
        for (int i = 0; i < d; ++i) s += H[i * k + l] * r[static_cast<Eigen::Index>(a * d + i)];
        P[l] += s;
      }
    }
}

}  // namespace moreau::kernel
