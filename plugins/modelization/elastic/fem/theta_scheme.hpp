#pragma once
// The θ-scheme of a linear structure (LMGC90 paper, §3.1, eq. 6) with constrained DOFs:
//   LHS = M + hθC + h²θ²K,
//   RHS = [M − h(1−θ)C − h²θ(1−θ)K] v⁻ − hK u⁻ + h[(1−θ)f⁻ + θf⁺],
//   LHS v⁺ = RHS + p (p: contact impulses),   u⁺ = u⁻ + h[(1−θ)v⁻ + θv⁺].
// Constrained DOFs (fixed nodes, imposed velocities) take their imposed v⁺; the free ones
// solve LHS_ff v⁺_f = RHS_f − LHS_fc v⁺_c + p_f with LHS_ff factorised once.
#include <memory>

#include "dof_partition.hpp"
#include "sparse_cholesky.hpp"

namespace moreau::fem {

class LinearThetaScheme {
 public:
  /// M, C, K over all DOFs; h the time step (s), θ in [0.5, 1].
  LinearThetaScheme(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K, double h, double theta,
                    DofPartition partition, CholeskyBackend backend = CholeskyBackend::automatic);

  /// v⁺ without contact impulses, over all DOFs; `v_imposed` gives the constrained DOFs'
  /// end-of-step values (in DofPartition::constrained() order).
  Eigen::VectorXd free_velocity(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& f_begin,
                                const Eigen::VectorXd& f_end, const Eigen::VectorXd& v_imposed) const;
  /// The velocity change an impulse p [dofs] causes: LHS_ff⁻¹ p_f on the free DOFs, zero
  /// on the constrained ones (they do not move under contact); impulse_responses: the columns
  /// of P at once (for W = Hᵀ LHS⁻¹ H).
  Eigen::VectorXd impulse_response(const Eigen::VectorXd& p) const;
  Eigen::MatrixXd impulse_responses(const Eigen::MatrixXd& P) const;
  /// u⁺ = u⁻ + h[(1−θ)v⁻ + θv⁺].
  Eigen::VectorXd displacement(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& v_next) const;

  const DofPartition& partition() const { return partition_; }
  const SparseCholesky& factor() const { return factor_; }
  double step() const { return h_; }
  double theta() const { return theta_; }

 private:
  double h_, theta_;
  DofPartition partition_;
  SparseMatrix K_, R_, lhs_fc_;  // R: the matrix that multiplies v⁻ in RHS
  SparseCholesky factor_;
};

}  // namespace moreau::fem
