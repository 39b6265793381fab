#pragma once
// What a run's contact solves achieved, for honest reporting (docs/solvers.md, "Reading a
// run"): how many steps ended above the solver's tolerance, the worst error and its step,
// and the bodies of the contact with the largest residual there. The first miss is said at
// once on stderr; the rest waits for the end-of-run summary. The per-frame `solver`
// attributes of the output are unchanged.
#include <iosfwd>
#include <moreau/solver.hpp>
#include <string>
#include <vector>

namespace moreau::kernel {

/// Numbers as a user reads them in a log: scientific notation, 3 digits ("7.02e-02").
std::string scientific(double x);

class SolveLog {
 public:
  double tolerance = 0;  ///< the solver's `tolerance` (0: unknown, misses are then the solver's word)
  /// One step's solve; `bodies` names the two bodies of the contact with the largest
  /// residual (called only when the step missed, or set a new worst error).
  template <class WorstBodies>
  void record(long step, const SolverReport& report, WorstBodies&& bodies) {
    ++solves_;
    const bool miss = !report.converged;
    const bool worst = report.error > worst_error_ || solves_ == 1;
    if (!miss && !worst) return;
    std::string who = (miss || worst) ? bodies() : std::string();
    if (worst) {
      worst_error_ = report.error;
      worst_step_ = step;
      worst_bodies_ = who;
    }
    if (miss) note_miss(step, report, who);
  }
  long solves() const { return solves_; }
  long misses() const { return misses_; }
  double worst_error() const { return worst_error_; }
  long worst_step() const { return worst_step_; }
  /// The end-of-run lines (nothing when no step had contacts). A run that missed lists
  /// its first `listed_misses` missed steps, each with its error and the bodies of the
  /// contact with the largest residual (issue 11: which bodies and steps failed).
  void print_summary(std::ostream& err) const;
  static constexpr std::size_t listed_misses = 20;

 private:
  void note_miss(long step, const SolverReport& report, const std::string& bodies);
  long solves_ = 0, misses_ = 0, first_miss_ = -1, worst_step_ = -1;
  double worst_error_ = 0;
  std::string worst_bodies_;
  struct Miss {
    long step;
    double error;
    std::string bodies;
  };
  std::vector<Miss> missed_;  ///< the first listed_misses misses
};

}  // namespace moreau::kernel
