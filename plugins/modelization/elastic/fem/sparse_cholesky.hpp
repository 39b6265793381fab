#pragma once
// Sparse Cholesky factorisation of a symmetric positive definite matrix (the θ-scheme's
// LHS_ff), behind one interface so the backend is chosen by measurement, not by the caller.
// Backends: Eigen's SimplicialLDLT/LLT (AMD ordering) and, when moreau is built with
// SuiteSparse, CHOLMOD (supernodal LLᵀ with BLAS, or simplicial LDLᵀ) through Eigen's
// wrapper. `automatic` is the benchmark's choice (docs/deformable.md): CHOLMOD's simplicial
// LDLᵀ when the build has it, Eigen's LDLᵀ otherwise.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string_view>

namespace moreau::fem {

enum class CholeskyBackend { automatic, eigen_ldlt, eigen_llt, cholmod_supernodal, cholmod_simplicial };

/// "automatic", "eigen-ldlt", "eigen-llt", "cholmod-supernodal", "cholmod-simplicial".
std::string_view backend_name(CholeskyBackend backend);
/// The backend of that name; an unknown name throws std::invalid_argument listing the valid ones.
CholeskyBackend backend_from_name(std::string_view name);
/// Whether this build has the backend (CHOLMOD ones need SuiteSparse at build time).
bool backend_available(CholeskyBackend backend);
/// The backend `automatic` stands for in this build.
CholeskyBackend automatic_backend();

class SparseCholesky {
 public:
  explicit SparseCholesky(CholeskyBackend backend = CholeskyBackend::automatic);
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
