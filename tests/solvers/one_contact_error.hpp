#pragma once
// The DESIGN §1 error of an answer r to one contact's problem u = A r + b (A: d × d,
// row-major), for the tests of the one-contact solvers.
#include <moreau/contact_error.hpp>

namespace moreau_test {

inline double one_contact_error(int d, const double* A, const double* b, double mu, const double* r) {
  moreau::LocalProblem P;
  P.dim = d;
  P.W.resize(d, d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) P.W.insert(i, j) = A[i * d + j];
  P.q = Eigen::Map<const Eigen::VectorXd>(b, d);
  P.mu = Eigen::VectorXd::Constant(1, mu);
  return moreau::natural_map_error(P, Eigen::Map<const Eigen::VectorXd>(r, d));
}

}  // namespace moreau_test
