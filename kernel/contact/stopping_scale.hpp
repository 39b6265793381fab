#pragma once
// The denominator of the time-stepper's stopping test (LocalProblem::error_scale,
// docs/solvers.md "Stopping test"). The FCLib measure divides by ‖q‖, but in a time step q
// holds max(0, g)/h for every open predicted contact: up to alert/h each, so a larger alert
// distance or a smaller h would loosen the test on the contacts that matter. Here the
// norm runs over the contacts that approach during the step (q_n < 0): those are the
// contacts that can carry force. A contact closes within the step only if it is
// detected whatever the alert (detection reaches 2h‖v‖ + h²‖g‖ beyond it), so the set, and
// the test, do not depend on the alert distance nor on the open contacts.
#include <cmath>
#include <moreau/contact_problem.hpp>

namespace moreau::kernel {

/// sqrt(Σ ‖q_α‖² over contacts with q_n,α < 0); 0 (the FCLib ‖q‖) when none approaches,
/// where r = 0 solves the problem and any scale gives the same answer.
inline double approaching_contacts_scale(const LocalProblem& p) {
  const int d = p.dim;
  double sum = 0;
  for (Eigen::Index a = 0; a < p.contacts(); ++a) {
    if (!(p.q[a * d] < 0)) continue;
    for (int k = 0; k < d; ++k) sum += p.q[a * d + k] * p.q[a * d + k];
  }
  return std::sqrt(sum);
}

}  // namespace moreau::kernel
