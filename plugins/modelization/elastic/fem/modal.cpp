#include "modal.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <random>
#include <stdexcept>

#include "sparse_cholesky.hpp"

namespace moreau::fem {

Modes lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int k, double tolerance, int max_iterations) {
  const Eigen::Index n = K.rows();
  if (k < 1 || k > n) throw std::invalid_argument("lowest_modes: k must lie in [1, dofs]");
  const int q = static_cast<int>(std::min<Eigen::Index>(n, std::max(2 * k, k + 8)));
  SparseCholesky factor;
  factor.factorize(K);
  // Starting subspace: the diagonal of M (Bathe's first vector), then seeded random ones.
  Eigen::MatrixXd X(n, q);
  X.col(0) = M.diagonal();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int j = 1; j < q; ++j)
    for (Eigen::Index i = 0; i < n; ++i) X(i, j) = uniform(rng);
  Modes modes;
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(k, -1);
  for (int it = 1; it <= max_iterations; ++it) {
    const Eigen::MatrixXd Y = factor.solve_columns(M * X);
    const Eigen::MatrixXd Kr = Y.transpose() * (K * Y), Mr = Y.transpose() * (M * Y);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> reduced(0.5 * (Kr + Kr.transpose()),
                                                                      0.5 * (Mr + Mr.transpose()));
    if (reduced.info() != Eigen::Success) throw std::runtime_error("lowest_modes: reduced eigenproblem failed");
    X = Y * reduced.eigenvectors();  // eigenvalues come increasing, vectors M-orthonormal
    const Eigen::VectorXd omega2 = reduced.eigenvalues().head(k);
    const double change = ((omega2 - previous).array().abs() / omega2.array().abs()).maxCoeff();
    previous = omega2;
    if (change <= tolerance) {
      modes.omega2 = omega2;
      modes.vectors = X.leftCols(k);
      modes.iterations = it;
      return modes;
    }
  }
  throw std::runtime_error("lowest_modes: no convergence in " + std::to_string(max_iterations) + " iterations");
}

}  // namespace moreau::fem
