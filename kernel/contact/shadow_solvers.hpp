#pragma once
// Shadow solvers: a measurement mode (docs/solvers.md, "Comparing solvers on one run").
// Whole runs of a scene with different solvers are different realisations (a silo jams in
// one and flows in another), so their times compare the realisations as much as the
// solvers. With MOREAU_SHADOW_SOLVERS, every problem the scene's solver solves is also
// solved by each shadow solver, from the same warm start, on copies of r and u; the run
// goes on with the scene solver's answer only, so its output is the one without shadows.
// Each solver's thread CPU time and reports are summed into one table at the end.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <iosfwd>
#include <moreau/solver.hpp>
#include <string>
#include <vector>

#include "../plugin/owned.hpp"
#include "../run/stage_timer.hpp"

namespace moreau::kernel {

/// What one solver did over a run's solves.
struct SolverTally {
  std::string label;     ///< "auto", "nlgs", "apgd #2" (a repeated type is numbered)
  std::string solver;    ///< its block as JSON, parameters filled in
  long solves = 0;       ///< calls (a step whose laws iterate is solved more than once)
  double seconds = 0;    ///< thread CPU time in solve() (s)
  long iterations = 0;
  long misses = 0;       ///< solves that returned converged = false
  double worst_error = 0;
  long worst_solve = 0;  ///< which solve (from 1) had the worst error
  double work = 0;       ///< SolverReport::work summed (counted units)
  void add(const SolverReport& r, double s);
};

class ShadowSolvers {
 public:
  /// The scene's solver (its label and block): the table's first row.
  explicit ShadowSolvers(std::string scene_label, std::string scene_block);
  void add(std::string label, std::string block, Owned<Solver> solver);
  /// Solves P with `scene` into r, u (as `scene.solve` would) and with every shadow from
  /// the same r, u on copies. The order of the solvers turns from one call to the next, so
  /// none is always the one that finds the problem in the cache. A shadow is given P as it
  /// would be in its own run: W assembled from the factor for one that reads it, or left
  /// out for one that does not (Solver::reads_matrix_with_factor); P is as given on return.
  SolverReport solve(Solver& scene, LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u);
  /// The stage clock's time (StageClock) spent on the shadows: not the scene's solve stage.
  double stage_seconds() const { return stage_seconds_; }
  const std::vector<SolverTally>& tallies() const { return tallies_; }
  /// The end-of-run table (one row per solver, the scene's first).
  void print(std::ostream& os) const;
  /// The same as JSON, written whole or not at all (a temporary file renamed).
  void write_json(const std::string& path, const std::string& scene, long steps) const;

 private:
  struct Shadow {
    Owned<Solver> solver;
    Eigen::VectorXd r, u;
  };
  std::vector<Shadow> shadows_;
  std::vector<SolverTally> tallies_;  ///< the scene's first, then the shadows'
  Eigen::VectorXd r0_, u0_;           ///< the warm start
  Eigen::SparseMatrix<double, Eigen::RowMajor> other_w_;  ///< W swapped into/out of P for a shadow
  long calls_ = 0;
  double stage_seconds_ = 0;
  SolverReport timed(Solver& s, const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u, SolverTally& t);
};

}  // namespace moreau::kernel
