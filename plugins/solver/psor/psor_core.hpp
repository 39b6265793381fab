#pragma once
// Projected SOR on the Coulomb cone: a Gauss–Seidel sweep over contacts in which each
// contact takes one projected step instead of an exact one-contact solve (cheaper than
// NLGS per contact, slower to converge):
//   u_α = (W r + q)_α with the latest r,   r_α ← P_K(r_α − ω / W_αα,nn (u_α + μ‖u_T,α‖ e_n)).
// Stopping test: the DESIGN §1 error every few sweeps; the best finite iterate is returned.
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>

namespace moreau::psor {

struct Options {
  double tolerance = 1e-6;
  long max_iterations = 10000;  ///< sweeps
  double relaxation = 0.5;      ///< ω (1 cycles on some real problems with the De Saxcé shift)
  long check_every = 5;         ///< sweeps between two evaluations of the error
};

SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u);

}  // namespace moreau::psor
