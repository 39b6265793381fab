#pragma once
// A contact solver (DESIGN §1): the same objects serve the time-stepper and
// `moreau fclib solve`. Parameters (tolerance, max_iterations, …) come from its schema.
#include <moreau/contact_problem.hpp>
#include <moreau/plugin.hpp>

namespace moreau {

struct SolverReport {
  long iterations = 0;
  double error = 0;      ///< DESIGN §1 error, recomputed from the returned r
  bool converged = false;
  /// Counted work of the solve, in nanosecond-equivalents of the solvers' cost model of
  /// their operations (products by W, error evaluations, sweeps, factorisations; sizes only,
  /// so the same on every run and machine: docs/solvers.md "Counted work"). 0: not counted.
  /// `auto` shares this work between its members; each member run alone reports the same
  /// count, which is what the guarantee's test compares.
  double work = 0;
};

class MOREAU_API Solver : public Plugin {
 public:
  static constexpr Kind kind = Kind::solver;
  /// `r`: the warm start on entry (dim·nc values), the solution on exit; `u` = W r + q.
  virtual SolverReport solve(const LocalProblem& problem, Eigen::VectorXd& r, Eigen::VectorXd& u) = 0;
  /// Whether solve() reads `problem.W` when `problem.factor` is present. A solver working
  /// through body velocities only says false, and the time-stepper then skips assembling
  /// W (the largest array of a step) and passes it empty (0 × 0).
  virtual bool reads_matrix_with_factor() const { return true; }
};

}  // namespace moreau
