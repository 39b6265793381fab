#include "rigid_assembly.hpp"

#include <algorithm>
#include <moreau/factor_matrix.hpp>

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

void RigidAssembly::build(const RigidBodies& bodies, const std::vector<RigidContact>& contacts, bool with_W) {
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
  if (with_W)
    build_W(bodies);
  else
    W_.resize(0, 0);
}

void RigidAssembly::build_W(const RigidBodies& bodies) {
  // Through the same factored form the solver receives, so there is one assembly.
  BodyFactor f;
  f.k = k_;
  f.body.resize(2 * contacts_.size());
  const std::size_t nb = bodies.com.size() / 3;
  std::vector<char> moves(nb, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    const double* Mi = &bodies.inverse_mass[b * k_ * k_];
    moves[b] = !std::all_of(Mi, Mi + k_ * k_, [](double x) { return x == 0.0; });
  }
  for (std::size_t a = 0; a < contacts_.size(); ++a)
    for (int side = 0; side < 2; ++side) f.body[2 * a + side] = moves[contacts_[a].body[side]] ? contacts_[a].body[side] : -1;
  f.H.swap(H_);
  f.inverse_mass = bodies.inverse_mass;
  W_ = assemble_w(dim_, f);
  H_.swap(f.H);
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

void RigidAssembly::lend_factor(RigidBodies& bodies, BodyFactor& f) {
  const int k = k_;
  const std::size_t nc = contacts_.size(), nb = bodies.com.size() / 3;
  std::vector<char> moves(nb, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    const double* Mi = &bodies.inverse_mass[b * k * k];
    moves[b] = !std::all_of(Mi, Mi + k * k, [](double x) { return x == 0.0; });
  }
  f.k = k;
  f.body.resize(2 * nc);
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = contacts_[a].body[side];
      f.body[2 * a + side] = moves[b] ? b : -1;
    }
  f.inverse_mass = std::move(bodies.inverse_mass);
  f.H.swap(H_);
}

void RigidAssembly::take_back(BodyFactor& f) {
  H_.swap(f.H);
  f.H.clear();
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
