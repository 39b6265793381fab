#pragma once
// The bulk of one body of a linear modelization (Modelization::linear_bulk), as its
// integrator reads it: the seed's eq. 3 with F(q, q̇) = −K q − C q̇ and constant matrices,
//     M q̈ + C q̇ + K q = load + gravity g + P(t) + r,
// over the body's nodes × k unknowns, node-major (unknown = k·node + component, node
// counted within the body). The `linear_theta` integrator builds the seed's eq. 6 from it:
// LHS = M + hθC + h²θ²K, factorised once per run. Separate from modelization.hpp so that
// only the plugins that use it include Eigen's sparse module.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace moreau {

struct LinearBulk {
  Eigen::SparseMatrix<double> M;  ///< mass (kg; 2D: kg per unit thickness), symmetric, both triangles
  Eigen::SparseMatrix<double> C;  ///< damping (N s/m), symmetric; empty (0 × 0): none
  Eigen::SparseMatrix<double> K;  ///< stiffness (N/m), symmetric
  Eigen::VectorXd load;           ///< constant loads (N), size nodes·k; empty: none
  /// [nodes·k, d]: the load of a unit gravity along each axis (kg): the body's gravity load
  /// is gravity · g. Empty: gravity does not act.
  Eigen::MatrixXd gravity;
  std::vector<int> fixed;         ///< unknowns whose velocity is zero for the whole run
};

}  // namespace moreau
