#pragma once
// The scene key `export_problems` (docs/scene.md): the contact problem of chosen steps
// written as an FCLib file (DESIGN §3.5), local (W, q) or global (M, H, f, w), with the warm start the run used as
// /guesses/1 and the run's own answer as /solution, so moreau's problems join the
// work-precision benchmark and can be handed to other codes.
#include <Eigen/Core>
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>
#include <string>
#include <vector>

#include "../fclib/fclib.hpp"

namespace moreau::kernel {

struct ProblemExportSettings {
  std::vector<long> steps;  ///< sorted, unique, ≥ 1; empty when `every` is used
  long every = 0;           ///< export steps every, 2·every, …; 0 when `steps` is used
  std::string directory;    ///< absolute
  std::string stem;         ///< file names: <stem>-stepNNNNNNNN.hdf5
  long min_contacts = 1;    ///< steps with fewer contacts write nothing
  std::string scene_file;   ///< for the description inside the files
  std::string solver;       ///< the scene's solver section, as JSON text, for the description
  bool global = false;      ///< `kind: "global"`: FCLib's global form (M, H, f, w) instead of (W, q)
};

class ProblemExport {
 public:
  explicit ProblemExport(ProblemExportSettings s) : s_(std::move(s)) {}

  /// `step` counts completed steps once this one is done (1 for the first step), the
  /// number of the output frame that shows its impulses.
  bool due(long step) const;
  /// Creates the directory (before the run, so that an unusable one is bad input, exit 2).
  void prepare() const;
  /// Writes the problem of `step`, unless it has fewer than min_contacts contacts. When the
  /// solver did not ask for W (it exchanged through bodies), W is assembled here from
  /// the factor, which must still be lent to `p`.
  void write(long step, double time, double h, const LocalProblem& p, const Eigen::VectorXd& warm_start,
             const Eigen::VectorXd& r, const SolverReport& report);
  /// The same problem in FCLib's global form (settings().global), built by the caller
  /// (ContactAssembly::global_problem).
  void write_global(long step, double time, double h, const fclib::GlobalProblem& g, const Eigen::VectorXd& warm_start,
                    const Eigen::VectorXd& r, const SolverReport& report);
  /// One line for the end of the run: what was written, what was skipped and why.
  std::string summary() const;

  const ProblemExportSettings& settings() const { return s_; }
  std::string path_of(long step) const;

 private:
  std::string description(const char* form, long step, double time, double h, Eigen::Index contacts, int dim,
                          const SolverReport& report, bool finite) const;
  ProblemExportSettings s_;
  std::vector<long> written_, too_few_;
};

}  // namespace moreau::kernel
