#include "nlgs_sweep.hpp"

#include "local_solvers.hpp"

namespace moreau::nlgs {

void Sweeper::prepare(const LocalProblem& P) {
  const int d = P.dim;
  const Eigen::Index nc = P.contacts();
  blocks_.assign(static_cast<std::size_t>(nc) * d * d, 0.0);
  for (Eigen::Index a = 0; a < nc; ++a)
    for (int i = 0; i < d; ++i)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(P.W, a * d + i); it; ++it)
        if (it.col() >= a * d && it.col() < (a + 1) * d) blocks_[(a * d + i) * d + (it.col() - a * d)] = it.value();
}

namespace {
inline void one_contact(const LocalProblem& P, const LocalOptions& local, const double* blocks, Eigen::Index a,
                        Eigen::VectorXd& r, double omega) {
  const int d = P.dim;
  double b[3], rn[3], old[3];
  const double* A = &blocks[a * d * d];
  for (int i = 0; i < d; ++i) {
    double s = P.q[a * d + i];
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(P.W, a * d + i); e; ++e) s += e.value() * r[e.col()];
    for (int j = 0; j < d; ++j) s -= A[i * d + j] * r[a * d + j];  // leave out the contact itself
    b[i] = s;
    old[i] = rn[i] = r[a * d + i];
  }
  solve_local(local, d, A, b, P.mu[a], rn);
  for (int i = 0; i < d; ++i) r[a * d + i] = omega * rn[i] + (1 - omega) * old[i];
}
}  // namespace

void Sweeper::sweep(const LocalProblem& P, Eigen::VectorXd& r, double omega, const std::vector<Eigen::Index>& order) const {
  for (Eigen::Index a : order) one_contact(P, local_, blocks_.data(), a, r, omega);
}

void Sweeper::sweep(const LocalProblem& P, Eigen::VectorXd& r, double omega) const {
  const Eigen::Index nc = P.contacts();
  for (Eigen::Index a = 0; a < nc; ++a) one_contact(P, local_, blocks_.data(), a, r, omega);
}

}  // namespace moreau::nlgs
