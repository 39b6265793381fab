#pragma once
// Sparse Cholesky factorisation of a symmetric positive definite matrix (the θ-scheme's
// LHS_ff), behind one interface so the backend is chosen by measurement, not by the caller.
// Backends: Eigen's SimplicialLDLT/LLT (AMD ordering) and, when moreau is built with
// SuiteSparse, CHOLMOD (supernodal LLᵀ with BLAS, or simplicial LDLᵀ) through Eigen's
// wrapper. `automatic` is the benchmark's choice (docs/deformable.md).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string_view>

namespace moreau::fem {

enum class CholeskyBackend { automatic, eigen_ldlt, eigen_llt, cholmod_supernodal, cholmod_simplicial };

std::string_view backend_name(CholeskyBackend backend);
/// Whether this build has the backend (CHOLMOD ones need SuiteSparse at build time).
bool backend_available(CholeskyBackend backend);
/// The backend `automatic` picks for an n × n matrix with nnz stored entries in dimension dim.
CholeskyBackend automatic_backend(Eigen::Index n, Eigen::Index nnz, int dim);

class SparseCholesky {
 public:
  explicit SparseCholesky(CholeskyBackend backend = CholeskyBackend::automatic, int dim = 3);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  /// Ordering, symbolic analysis and numeric factorisation. Reads the lower triangle (full
  /// or lower storage). Throws std::runtime_error when A is not positive definite, or the
  /// backend is not in this build.
  void factorize(const Eigen::SparseMatrix<double>& A);
  /// Numeric factorisation only, for a matrix with the pattern of the last factorize().
  void refactorize(const Eigen::SparseMatrix<double>& A);

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// Several right-hand sides at once (the columns of B).
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B) const;

  CholeskyBackend backend() const;  ///< the one in use (resolved after factorize)
  Eigen::Index rows() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace moreau::fem
