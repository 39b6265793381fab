#pragma once
// Sparse Cholesky factorisation of a symmetric positive definite matrix (the θ-scheme's
// LHS_ff), behind one interface so the backend is chosen by measurement, not by the caller.
// Backends: Eigen's SimplicialLDLT/LLT (AMD ordering) and, when moreau is built with
// SuiteSparse, CHOLMOD (supernodal LLᵀ with BLAS, its factor then made simplicial for the
// solves; or simplicial LDLᵀ) through Eigen's wrapper. `automatic` is the benchmark's
// choice (docs/deformable.md): CHOLMOD's supernodal when the build has it, Eigen's LDLᵀ
// otherwise.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string_view>
#include <vector>

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

/// A column of the factor's inverse, as far as it reaches: for a row i of A = Pᵀ L D Lᵀ P,
/// z_i = D^{-1/2} L⁻¹ P e_i (D = 1 for an LLᵀ factor). It is nonzero only on the path of
/// i's pivot up the elimination tree, a small part of the matrix (the separators above it),
/// and (A⁻¹)_ij = z_i · z_j: the entries of A⁻¹ among a few rows cost a few partial forward
/// solves instead of full solves. `index` ascending (pivot order), `value` alongside.
struct FactorColumn {
  std::vector<int> index;
  std::vector<double> value;
};
/// z_i · z_j, summed in ascending pivot order (so dot(a, b) == dot(b, a) to the bit).
double dot(const FactorColumn& a, const FactorColumn& b);

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

  /// Whether factor_column works with the factor in use: CHOLMOD's (supernodal, once made
  /// simplicial, and simplicial) and Eigen's LDLᵀ; not Eigen's LLᵀ.
  bool has_factor_columns() const;
  /// z_i (FactorColumn) for row i of A; throws std::logic_error without has_factor_columns().
  FactorColumn factor_column(Eigen::Index i) const;

  CholeskyBackend backend() const;  ///< the one in use (resolved after factorize)
  Eigen::Index rows() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace moreau::fem
