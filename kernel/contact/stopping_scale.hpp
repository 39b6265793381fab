#pragma once
// The denominator of the time-stepper's stopping test (LocalProblem::error_scale,
// docs/solvers.md "Stopping test"). The FCLib measure divides by ‖q‖, but in a time step q
// holds max(0, g)/h for every open predicted contact: up to alert/h each, so a larger alert
// distance or a smaller h would loosen the test on the contacts that matter. Here the
// norm runs over the contacts that approach during the step (q_n < 0): those are the
// contacts that can carry force. A contact closes within the step only if it is
// detected whatever the alert (detection reaches 2h‖v‖ + h²‖g‖ beyond it), so the set, and
// the test, do not depend on the alert distance nor on the open contacts.
#include <algorithm>
#include <cmath>
#include <limits>
#include <moreau/contact_problem.hpp>

namespace moreau::kernel {

/// sqrt(Σ ‖q_α‖² over contacts with q_n,α < 0), floored at √ε ‖q‖; 0 (the FCLib ‖q‖) when
/// none approaches, where r = 0 solves the problem and any scale gives the same answer.
///
/// Why the floor: a contact can approach by a rounding residue only (a grain pressed on a
/// side wall by its neighbours with no normal motion of its own: q_n ≈ -1e-17 while ‖q‖ is
/// 16). Divided by that, the rounding of W r + q on the loaded contacts around it, about
/// ε ‖q‖, reads as an error of 0.3 and no solver can stop. √ε ‖q‖ keeps that rounding
/// below √ε ≈ 1.5e-8 in the error, under any tolerance a solve uses, and is far below the
/// approaching contacts' norm whenever they approach by more than rounding (gravity alone
/// gives g h ≈ 1e-3 m/s per step), so there the test is the one above, independent of
/// the alert distance and of the open contacts.
inline double approaching_contacts_scale(const LocalProblem& p) {
  const int d = p.dim;
  double approaching = 0;
  double all = 0;
  for (Eigen::Index a = 0; a < p.contacts(); ++a) {
    double sum = 0;
    for (int k = 0; k < d; ++k) sum += p.q[a * d + k] * p.q[a * d + k];
    all += sum;
    if (p.q[a * d] < 0) approaching += sum;
  }
  if (approaching == 0) return 0;
  const double floor = std::sqrt(std::numeric_limits<double>::epsilon() * all);
  return std::max(std::sqrt(approaching), floor);
}

}  // namespace moreau::kernel
