#pragma once
// The anonymous frictional contact problem a solver sees (DESIGN §1, FCLib local form):
// find r, u with u = W r + q and, for each contact α (normal first),
//   r_α ∈ K_μα,  ũ_α = u_α + μ_α ‖u_T,α‖ e_n ∈ K*_μα,  r_α ⊥ ũ_α.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstddef>
#include <vector>

namespace moreau {

/// Optional factored form of W, W = H M⁻¹ Hᵀ, given by the time-stepper (never by an FCLib
/// file). It lets a solver exchange impulses through body velocities instead of W's
/// off-diagonal blocks (LMGC90's second NLGS variant): a contact touches at most two
/// bodies, so its data is two small blocks however many neighbours it has.
struct BodyFactor {
  int k = 0;  ///< unknowns per body (rigid 2D: 3, rigid 3D: 6); 0: no factor given
  /// nc × 2: the bodies of each contact (index into `inverse_mass`), −1 for a body whose
  /// inverse mass is zero (fixed): impulses do not move it, its block of H is irrelevant.
  std::vector<int> body;
  /// nc × 2 × (dim × k), row-major blocks: u_α = q_α + Σ_s H_αs v_body(α,s) (m/s per m/s).
  std::vector<double> H;
  /// n_bodies × (k × k), row-major, symmetric: velocity change per impulse (1/kg, 1/(kg m²)).
  std::vector<double> inverse_mass;
  /// dim·nc or empty: W = H M⁻¹ Hᵀ + diag(diagonal), the contact laws' compliance
  /// (law.hpp: elastic interfaces, cohesive zones). Whoever uses the factor honours it:
  /// assemble_w, multiply_w (factor_matrix.hpp), the body-velocity NLGS, APGD.
  std::vector<double> diagonal;
  bool present() const { return k > 0; }
};

struct LocalProblem {
  int dim = 3;                                        ///< 2 or 3
  /// (dim·nc)², symmetric positive semi-definite; empty (0 × 0) when the solver said it
  /// does not read it (Solver::reads_matrix_with_factor) and the factor is present. From
  /// the time-stepper it includes the laws' compliance (BodyFactor::diagonal).
  Eigen::SparseMatrix<double, Eigen::RowMajor> W;
  Eigen::VectorXd q;                                  ///< dim·nc
  Eigen::VectorXd mu;                                 ///< nc
  BodyFactor factor;                                  ///< optional, W = H M⁻¹ Hᵀ (see above)
  /// Denominator of the error (contact_error.hpp), in the units of q (m/s); 0: ‖q‖, the
  /// FCLib measure. The time-stepper sets it from the contacts that approach during the
  /// step, so that open contacts (whose q holds gap/h) do not loosen the stopping test.
  double error_scale = 0;
  Eigen::Index contacts() const { return mu.size(); }
};

}  // namespace moreau
