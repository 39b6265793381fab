#pragma once
// A contact solver (DESIGN §1): the same objects serve the time-stepper and
// `moreau fclib solve`. Parameters (tolerance, max_iterations, …) come from its schema.
#include <moreau/contact_problem.hpp>
#include <moreau/plugin.hpp>
#include <moreau/state.hpp>
#include <vector>

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

  /// What the solver keeps from one solve to the next that changes its later answers (e.g.
  /// `auto`'s memory of its members' costs, with `remember`), as fields of the kernel's
  /// `solver` set (one row; `set`, `depths`, `output` and `restart` are the kernel's). They
  /// are written with every frame (/frames/N/solver/<name>, docs/output.md) and restored by
  /// `--restart`, so a continuation stays bit-identical. None (the default): the solver's
  /// answer depends only on the problem and the warm start.
  virtual std::vector<FieldSpec> state_fields(int /*dim*/) const { return {}; }
  /// Writes that state into the set's fields; called after each step's solve.
  virtual void save_state(EntitySet& /*set*/) const {}
  /// Takes that state from the set's fields; called once, before the first solve of a run
  /// restarted from a frame that holds every one of them (a file without them: the state
  /// starts as in a new run).
  virtual void load_state(const EntitySet& /*set*/) {}
};

}  // namespace moreau
