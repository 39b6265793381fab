#include <Eigen/SparseCholesky>
#include <moreau/error.hpp>

#include "fclib.hpp"

namespace moreau::fclib {

namespace {
bool is_diagonal(const Eigen::SparseMatrix<double>& M) {
  for (int k = 0; k < M.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0) return false;
  return true;
}

/// A Cholesky reads one triangle: a matrix that is not symmetric would be silently replaced
/// by another (read() rebuilds one-triangle storage, so this only stops other callers).
void require_symmetric(const Eigen::SparseMatrix<double>& M, const std::string& file) {
  const MatrixStorage s = symmetric_storage(M);
  if (s != MatrixStorage::full && s != MatrixStorage::diagonal)
    throw InputError("/fclib_global/M", "M is not symmetric: refused for its Cholesky factorisation", file);
}
}  // namespace

LocalProblem reduce(const GlobalProblem& g, const std::string& file) {
  LocalProblem p;
  p.dim = g.dim;
  p.mu = g.mu;
  Eigen::SparseMatrix<double> MinvH;
  Eigen::VectorXd Minvf;
  if (is_diagonal(g.M)) {
    Eigen::VectorXd d = g.M.diagonal();
    for (Eigen::Index k = 0; k < d.size(); ++k)
      if (!(d[k] > 0)) throw InputError("/fclib_global/M", "diagonal entry " + std::to_string(k) + " is not positive", file);
    Eigen::VectorXd inv = d.cwiseInverse();
    MinvH = inv.asDiagonal() * g.H;
    Minvf = inv.cwiseProduct(g.f);
  } else {
    require_symmetric(g.M, file);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> chol(g.M);
    if (chol.info() != Eigen::Success)
      throw InputError("/fclib_global/M", "M is not symmetric positive definite (its factorisation failed)", file);
    MinvH = chol.solve(g.H);
    Minvf = chol.solve(g.f);
  }
  Eigen::SparseMatrix<double> Ht = g.H.transpose();
  Eigen::SparseMatrix<double> W = Ht * MinvH;
  p.W = W;  // to row-major
  p.q = g.w + Ht * Minvf;
  return p;
}

Eigen::VectorXd global_velocity(const GlobalProblem& g, const Eigen::VectorXd& r) {
  const Eigen::VectorXd rhs = g.H * r + g.f;
  require_symmetric(g.M, "");
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> chol(g.M);
  return chol.solve(rhs);
}

}  // namespace moreau::fclib
