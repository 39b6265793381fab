// The mass matrix M of a global FCLib problem is symmetric, but some writers store it as one
// triangle only: LMGC90's symmetric storage keeps the upper triangle (Siconos's
// LMGC_GlobalFrictionContactProblem files, the shared CubeH8.hdf5). Read literally, such an
// M is not symmetric, and a Cholesky that reads the other triangle sees its diagonal only:
// the solve then answers another problem. This file tells the storages apart and rebuilds
// the symmetric matrix; it is kept apart from the reader's validation on purpose.
#include <algorithm>
#include <cmath>
#include <moreau/error.hpp>

#include "fclib.hpp"

namespace moreau::fclib {

MatrixStorage symmetric_storage(const Eigen::SparseMatrix<double>& M, double relative_tolerance) {
  bool upper = false, lower = false;
  double largest = 0;
  for (int k = 0; k < M.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it) {
      largest = std::max(largest, std::fabs(it.value()));
      if (it.value() == 0) continue;
      if (it.row() < it.col()) upper = true;
      if (it.row() > it.col()) lower = true;
    }
  if (!upper && !lower) return MatrixStorage::diagonal;
  if (upper != lower) return upper ? MatrixStorage::upper : MatrixStorage::lower;
  // Both triangles hold entries: symmetric when every entry equals its mirror, to a
  // tolerance relative to the largest entry (files written as decimal text round).
  const Eigen::SparseMatrix<double> D = M - Eigen::SparseMatrix<double>(M.transpose());
  double asym = 0;
  for (int k = 0; k < D.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(D, k); it; ++it) asym = std::max(asym, std::fabs(it.value()));
  return asym <= relative_tolerance * largest ? MatrixStorage::full : MatrixStorage::unsymmetric;
}

Eigen::SparseMatrix<double> symmetric_matrix(const Eigen::SparseMatrix<double>& M, const std::string& dataset,
                                             const std::string& file, std::string* note) {
  const MatrixStorage s = symmetric_storage(M);
  if (s == MatrixStorage::diagonal || s == MatrixStorage::full) return M;
  if (s == MatrixStorage::unsymmetric)
    throw InputError(dataset, "the matrix is not symmetric (and not one stored triangle of a symmetric matrix): "
                              "a mass matrix must be symmetric positive definite", file);
  // One triangle T: the matrix it stands for is T + Tᵀ − diag(T).
  Eigen::SparseMatrix<double> T = M;
  Eigen::SparseMatrix<double> S = T + Eigen::SparseMatrix<double>(T.transpose());
  Eigen::SparseMatrix<double> D(M.rows(), M.cols());
  std::vector<Eigen::Triplet<double>> diag;
  for (int k = 0; k < M.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, k); it; ++it)
      if (it.row() == it.col()) diag.emplace_back(it.row(), it.col(), it.value());
  D.setFromTriplets(diag.begin(), diag.end());
  S -= D;
  if (note)
    *note = file + ": " + dataset + " is stored as its " + (s == MatrixStorage::upper ? "upper" : "lower") +
            " triangle only (symmetric storage, as LMGC90 writes it); read as the symmetric matrix T + Tᵀ − diag(T)";
  return S;
}

}  // namespace moreau::fclib
