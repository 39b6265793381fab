#include "problem_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>
#include <moreau/factor_matrix.hpp>
#include <moreau/version.hpp>
#include <sstream>

#include "../fclib/fclib.hpp"

namespace fs = std::filesystem;

namespace moreau::kernel {

namespace {

std::string list(const std::vector<long>& v) {
  std::string s;
  for (long x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s;
}

}  // namespace

bool ProblemExport::due(long step) const {
  if (s_.every > 0) return step % s_.every == 0;
  return std::binary_search(s_.steps.begin(), s_.steps.end(), step);
}

std::string ProblemExport::path_of(long step) const {
  char name[32];
  std::snprintf(name, sizeof name, "-step%08ld.hdf5", step);
  return (fs::path(s_.directory) / (s_.stem + name)).string();
}

void ProblemExport::prepare() const {
  std::error_code ec;
  fs::create_directories(s_.directory, ec);
  if (ec || !fs::is_directory(s_.directory))
    throw InputError("/export_problems/directory", "cannot create the folder " + s_.directory +
                                                       (ec ? ": " + ec.message() : std::string(": a file has that name")),
                     s_.scene_file);
}

void ProblemExport::write(long step, double time, double h, const LocalProblem& p, const Eigen::VectorXd& warm_start,
                          const Eigen::VectorXd& r, const SolverReport& report) {
  if (p.contacts() < s_.min_contacts) {
    too_few_.push_back(step);
    return;
  }
  // A solver exchanging through body velocities was given no W: build it from the same
  // factored form it used, so the file holds the problem that was solved.
  LocalProblem built;
  const LocalProblem* problem = &p;
  if (p.W.rows() != p.dim * p.contacts()) {
    if (!p.factor.present()) throw RunError("internal: FCLib export at step " + std::to_string(step) + ": neither W nor its factor");
    built.dim = p.dim;
    built.W = assemble_w(p.dim, p.factor);
    built.q = p.q;
    built.mu = p.mu;
    problem = &built;
  }
  // A solver that failed badly leaves non-finite impulses (the run stops on them just
  // after): the problem is still worth having, its "solution" is not.
  const bool finite = r.allFinite();
  fclib::ProblemInfo info{s_.stem + " step " + std::to_string(step),
                          description("local", step, time, h, p.contacts(), p.dim, report, finite), ""};
  fclib::write_local(path_of(step), *problem, info, &warm_start, finite ? &r : nullptr);
  written_.push_back(step);
}

void ProblemExport::write_global(long step, double time, double h, const fclib::GlobalProblem& g,
                                 const Eigen::VectorXd& warm_start, const Eigen::VectorXd& r, const SolverReport& report) {
  if (g.mu.size() < s_.min_contacts) {
    too_few_.push_back(step);
    return;
  }
  const bool finite = r.allFinite();
  fclib::ProblemInfo info{s_.stem + " step " + std::to_string(step),
                          description("global", step, time, h, g.mu.size(), g.dim, report, finite) +
                              " M: the LHS of the touched bodies on their free unknowns (" + std::to_string(g.M.rows()) +
                              "), f = M v_free, w = q - H^T v_free.",
                          ""};
  fclib::write_global(path_of(step), g, info, &warm_start, finite ? &r : nullptr);
  written_.push_back(step);
}

std::string ProblemExport::description(const char* form, long step, double time, double h, Eigen::Index contacts, int dim,
                                       const SolverReport& report, bool finite) const {
  std::ostringstream d;
  d.precision(6);
  d << "moreau " << MOREAU_SDK_VERSION << ": " << form << " contact problem of scene "
    << fs::path(s_.scene_file).filename().string() << ", step " << step << " (t = " << time << " s, h = " << h << " s), "
    << contacts << " contacts, spacedim " << dim << ".\nsolver " << s_.solver << ": " << report.iterations
    << " iterations, error " << report.error << (report.converged ? ", converged" : ", not converged")
    << ".\n/guesses/1: the run's warm start (previous impulses of persisting contacts). "
    << (finite ? "/solution: the run's answer." : "No /solution: the run's answer was not finite.");
  return d.str();
}

std::string ProblemExport::summary() const {
  std::string s = "exported " + std::to_string(written_.size()) + " FCLib problem" + (written_.size() == 1 ? "" : "s") +
                  " to " + s_.directory;
  if (!written_.empty()) s += " (steps " + list(written_) + ")";
  if (!too_few_.empty())
    s += "; nothing written for step" + std::string(too_few_.size() == 1 ? " " : "s ") + list(too_few_) + " (fewer than " +
         std::to_string(s_.min_contacts) + " contact" + (s_.min_contacts == 1 ? "" : "s") + ")";
  if (s_.every == 0) {
    std::vector<long> missed;
    for (long x : s_.steps)
      if (!std::binary_search(written_.begin(), written_.end(), x) && std::find(too_few_.begin(), too_few_.end(), x) == too_few_.end())
        missed.push_back(x);
    if (!missed.empty()) s += "; step" + std::string(missed.size() == 1 ? " " : "s ") + list(missed) + " not run";
  }
  return s;
}

}  // namespace moreau::kernel
