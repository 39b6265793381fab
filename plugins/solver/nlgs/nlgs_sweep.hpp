#pragma once
// One NLGS sweep: every contact's one-contact Coulomb problem solved exactly
// (local_coulomb.hpp) with the other contacts' impulses frozen, in a given order. Shared by
// the `nlgs` plugin and the solvers that start with NLGS sweeps (`auto`).
#include <Eigen/Core>
#include <moreau/contact_problem.hpp>
#include <vector>

#include "local_solvers.hpp"

namespace moreau::nlgs {

class Sweeper {
 public:
  /// Packs the diagonal blocks of W (contiguous, dim×dim per contact, row-major).
  void prepare(const LocalProblem& P);
  /// The one-contact solver used by the sweeps (exact by default).
  void set_local(const LocalOptions& o) { local_ = o; }
  /// r_α ← ω solve_local(α) + (1 − ω) r_α for α in `order` (r already sized dim·nc).
  void sweep(const LocalProblem& P, Eigen::VectorXd& r, double omega, const std::vector<Eigen::Index>& order) const;
  /// The same over the contacts in their given order.
  void sweep(const LocalProblem& P, Eigen::VectorXd& r, double omega = 1.0) const;

 private:
  std::vector<double> blocks_;
  LocalOptions local_;
};

}  // namespace moreau::nlgs
