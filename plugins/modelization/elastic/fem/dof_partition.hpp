#pragma once
// Free and constrained DOFs. A constrained DOF has its velocity imposed (zero for a fixed
// node); the θ-scheme then solves only for the free ones:
//     LHS_ff v_f = RHS_f − LHS_fc v_c (+ contact impulses on free DOFs),
// so the factorised matrix is LHS_ff, built once, whatever the imposed values are.
#include <array>
#include <vector>

#include "elasticity.hpp"

namespace moreau::fem {

/// DOF numbers of the given components (x, y[, z]) of some nodes, increasing.
std::vector<int> node_dofs(const Mesh& mesh, const std::vector<int>& nodes,
                           std::array<bool, 3> components = {true, true, true});

class DofPartition {
 public:
  /// `constrained`: DOF numbers in [0, dofs), any order, repeats allowed.
  DofPartition(int dofs, const std::vector<int>& constrained);

  int dof_count() const { return static_cast<int>(equation_.size()); }
  const std::vector<int>& free() const { return free_; }                ///< increasing
  const std::vector<int>& constrained() const { return constrained_; }  ///< increasing
  /// Position of a DOF among the free ones, or −1 when it is constrained.
  int equation(int dof) const { return equation_[dof]; }

  SparseMatrix free_block(const SparseMatrix& A) const;      ///< A_ff
  SparseMatrix coupling_block(const SparseMatrix& A) const;  ///< A_fc (rows free, columns constrained)
  Eigen::VectorXd free_part(const Eigen::VectorXd& v) const;
  Eigen::VectorXd constrained_part(const Eigen::VectorXd& v) const;
  /// The full vector from its free and constrained parts.
  Eigen::VectorXd combine(const Eigen::VectorXd& v_free, const Eigen::VectorXd& v_constrained) const;

 private:
  SparseMatrix block(const SparseMatrix& A, const std::vector<int>& columns) const;
  std::vector<int> free_, constrained_, equation_;
};

}  // namespace moreau::fem
