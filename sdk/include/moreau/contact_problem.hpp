#pragma once
// The anonymous frictional contact problem a solver sees (DESIGN §1, FCLib local form):
// find r, u with u = W r + q and, for each contact α (normal first),
//   r_α ∈ K_μα,  ũ_α = u_α + μ_α ‖u_T,α‖ e_n ∈ K*_μα,  r_α ⊥ ũ_α.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace moreau {

struct LocalProblem {
  int dim = 3;                                        ///< 2 or 3
  Eigen::SparseMatrix<double, Eigen::RowMajor> W;     ///< (dim·nc)², symmetric positive semi-definite
  Eigen::VectorXd q;                                  ///< dim·nc
  Eigen::VectorXd mu;                                 ///< nc
  Eigen::Index contacts() const { return mu.size(); }
};

}  // namespace moreau
