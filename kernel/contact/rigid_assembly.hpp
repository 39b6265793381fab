#pragma once
// The local contact problem of rigid bodies (DESIGN §1): u = W r + q with
// W = H M⁻¹ Hᵀ assembled from per-contact, per-body blocks, and the way back from
// local impulses r to body impulses Hᵀ r.
//
// Generalised velocity of a body: k = 3 (2D: vx vy ω) or 6 (3D: v, ω), world frame, of
// the centre of mass. For contact α between bodies a (first) and b (second), with
// r_a = x_α − c_a, the relative velocity of a with respect to b at the contact is
// (v_a + ω_a × r_a) − (v_b + ω_b × r_b), written in the local frame (n, t[, s]);
// n points from b toward a, so u_n > 0 separates.
#include <Eigen/Sparse>
#include <cstdint>
#include <moreau/contact_problem.hpp>
#include <vector>

namespace moreau::kernel {

struct RigidContact {
  int body[2] = {-1, -1};  ///< first (the force acts on it), second (the opposite)
  double point[3] = {0, 0, 0};
  double frame[3][3] = {};  ///< rows n, t[, s] (world); 2D uses [0..1][0..1]
};

/// Per body, at the configuration the contacts were detected on.
struct RigidBodies {
  int dim = 3;
  std::vector<double> com;            ///< nb × 3 (2D: z unused), world
  std::vector<double> inverse_mass;   ///< nb × k × k, row-major, world; zero for fixed bodies
  std::vector<double> free_velocity;  ///< nb × k
  int k() const { return dim == 2 ? 3 : 6; }
};

class RigidAssembly {
 public:
  /// Builds the H blocks for these contacts, and W unless `with_W` is false (a solver
  /// working through body velocities does not read it; it is the largest array of a step).
  void build(const RigidBodies& bodies, const std::vector<RigidContact>& contacts, bool with_W = true);
  /// q = H v_free (normal shifts are added by the caller).
  Eigen::VectorXd free_local_velocity(const RigidBodies& bodies) const;
  /// W = H M⁻¹ Hᵀ; empty (0 × 0) when the last build was without it.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& W() const { return W_; }
  /// Body impulses Hᵀ r, nb × k, world frame (about the centre of mass).
  void body_impulses(const Eigen::VectorXd& r, std::size_t n_bodies, std::vector<double>& out) const;
  /// Local velocity of each contact at the start of the step, H v (v: nb × k).
  Eigen::VectorXd local_velocity(const std::vector<double>& v) const;
  /// Hands the H blocks to `factor` for the solve (moved, not copied: they are the
  /// biggest array of the step), with the bodies and the inverse masses (moved out of
  /// `bodies`); bodies whose inverse mass is zero are marked −1. `take_back` returns H,
  /// which `body_impulses` needs after the solve.
  void lend_factor(RigidBodies& bodies, BodyFactor& factor);
  void take_back(BodyFactor& factor);

 private:
  void build_W(const RigidBodies& bodies);
  int dim_ = 3, k_ = 6;
  std::vector<RigidContact> contacts_;
  std::vector<double> H_;  ///< per contact, per side: d × k, row-major (side 1 already negated)
  Eigen::SparseMatrix<double, Eigen::RowMajor> W_;
};

}  // namespace moreau::kernel
