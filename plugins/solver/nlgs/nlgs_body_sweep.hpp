#pragma once
// NLGS exchanging impulses through body velocities (LMGC90's variant without W blocks):
// with W = H M⁻¹ Hᵀ (LocalProblem::factor), contact α's velocity is
//   u_α = q_α + Σ_s H_αs Δv_b(α,s),   Δv = M⁻¹ Hᵀ r,
// so a contact update reads two body velocity changes and writes them back after its
// one-contact solve, instead of reading every neighbour's impulse through a row of W.
// The cost per update is fixed (two d×k blocks each way) whatever the coordination
// number, and the hot data is one packed record per contact, read in sweep order
// (Bullet's solver-body idea: the solver packs its own data and writes r back).
#include <Eigen/Core>
#include <moreau/contact_problem.hpp>
#include <vector>

#include "local_solvers.hpp"

namespace moreau::nlgs {

class BodySweeper {
 public:
  /// Packs the records from P.factor (which must be present) and sets Δv from r.
  void prepare(const LocalProblem& P, const Eigen::VectorXd& r);
  /// r_α ← ω local(α) + (1 − ω) r_α for α in `order`, updating Δv as it goes.
  void sweep(Eigen::VectorXd& r, double omega, const std::vector<Eigen::Index>& order);
  /// The one-contact solver used by the sweeps (exact by default).
  void set_local(const LocalOptions& o) { local_ = o; }
  /// u = q + H Δv with Δv recomputed from r (increments accumulated over many sweeps
  /// would drift by rounding; the error check must see the true u = W r + q).
  void velocities(const Eigen::VectorXd& r, Eigen::VectorXd& u);

 private:
  void reset_velocities(const Eigen::VectorXd& r);
  int d_ = 3, k_ = 6;
  std::size_t stride_ = 0;    ///< doubles per record
  std::vector<double> rec_;   ///< per contact: A (d×d), q (d), μ, H₀ H₁ (d×k), G₀ G₁ = M⁻¹Hᵀ (k×d)
  std::vector<int> body_;     ///< per contact, 2 indices into dv_ blocks; −1: the body does not move
  LocalOptions local_;        ///< the one-contact solver
  std::vector<double> dv_;    ///< moving bodies × k: velocity change due to r, numbered by first use
};

}  // namespace moreau::nlgs
