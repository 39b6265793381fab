#pragma once
// Lowest vibration modes K φ = ω² M φ by subspace iteration (Bathe) on the factorisation of
// K: a check of the assembled matrices against analytic frequencies, and a way to choose a
// time step. K must be positive definite (the body constrained: pass the free blocks).
#include "elasticity.hpp"

namespace moreau::fem {

struct Modes {
  Eigen::VectorXd omega2;   ///< ω² (rad²/s²), increasing
  Eigen::MatrixXd vectors;  ///< [dofs, k], M-orthonormal
  int iterations = 0;
};

/// The k lowest modes, to a relative change of ω² below `tolerance` between iterations.
/// Deterministic (a fixed starting subspace). Throws std::runtime_error without convergence.
Modes lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int k, double tolerance = 1e-10,
                   int max_iterations = 300);

}  // namespace moreau::fem
