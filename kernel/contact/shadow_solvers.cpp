#include "shadow_solvers.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <moreau/error.hpp>
#include <moreau/factor_matrix.hpp>
#include <nlohmann/json.hpp>
#include <ostream>

namespace moreau::kernel {

void SolverTally::add(const SolverReport& r, double s) {
  ++solves;
  seconds += s;
  iterations += r.iterations;
  work += r.work;
  if (!r.converged) ++misses;
  if (solves == 1 || r.error > worst_error) {
    worst_error = r.error;
    worst_solve = solves;
  }
}

ShadowSolvers::ShadowSolvers(std::string scene_label, std::string scene_block) {
  tallies_.push_back(SolverTally{std::move(scene_label), std::move(scene_block)});
}

void ShadowSolvers::add(std::string label, std::string block, Owned<Solver> solver) {
  shadows_.push_back(Shadow{std::move(solver), {}, {}});
  tallies_.push_back(SolverTally{std::move(label), std::move(block)});
}

SolverReport ShadowSolvers::timed(Solver& s, const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u, SolverTally& t) {
  // Thread CPU time whatever MOREAU_STAGE_CLOCK says: the time other processes held the
  // core is not the solver's (the machine is shared), and the solves of one step are
  // compared with each other.
  const auto t0 = StageClock::thread_cpu();
  const SolverReport report = s.solve(P, r, u);
  const double sec = std::chrono::duration<double>(StageClock::thread_cpu() - t0).count();
  t.add(report, sec);
  // MOREAU_SHADOW_TRACE: one line per solve and solver on stderr, to compare the solvers
  // step by step (scripts/auto_trace_summary.py; docs/solvers.md "Comparing solvers on one run").
  static const bool trace = std::getenv("MOREAU_SHADOW_TRACE") != nullptr;
  if (trace)
    std::fprintf(stderr, "shadow: %s solve %ld cpu %.6e it %ld err %.3e conv %d work %.6e\n", t.label.c_str(), t.solves, sec,
                 static_cast<long>(report.iterations), report.error, report.converged ? 1 : 0, report.work);
  return report;
}

SolverReport ShadowSolvers::solve(Solver& scene, LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) {
  r0_ = r;
  u0_ = u;
  const std::size_t n = shadows_.size() + 1;
  const std::size_t first = static_cast<std::size_t>(calls_++) % n;
  const bool has_w = P.W.rows() > 0 || P.contacts() == 0;
  bool assembled = false;  // other_w_ holds this problem's W
  SolverReport report;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (first + k) % n;
    if (i == 0) {
      report = timed(scene, P, r, u, tallies_[0]);
      continue;
    }
    const auto t0 = StageClock::now();
    Shadow& sh = shadows_[i - 1];
    sh.r = r0_;
    sh.u = u0_;
    // P as in the shadow's own run: with W exactly when it reads W beside the factor.
    const bool swap = P.factor.present() && sh.solver->reads_matrix_with_factor() != has_w;
    Eigen::SparseMatrix<double, Eigen::RowMajor> none;
    if (swap && !has_w && !assembled) {
      other_w_ = assemble_w(P.dim, P.factor);  // as the assembly builds it (contact_assembly.cpp)
      assembled = true;
    }
    if (swap) P.W.swap(has_w ? none : other_w_);
    try {
      timed(*sh.solver, P, sh.r, sh.u, tallies_[i]);
    } catch (...) {
      if (swap) P.W.swap(has_w ? none : other_w_);
      throw;
    }
    if (swap) P.W.swap(has_w ? none : other_w_);
    stage_seconds_ += std::chrono::duration<double>(StageClock::now() - t0).count();
  }
  return report;
}

void ShadowSolvers::print(std::ostream& os) const {
  char line[256];
  std::snprintf(line, sizeof line, "solvers on the same problems (thread CPU time; the first is the scene's, whose answers the run keeps):\n");
  os << line;
  std::snprintf(line, sizeof line, "  %-18s %8s %12s %10s %10s %8s %11s\n", "solver", "solves", "CPU ms/solve", "total s",
                "iter/solve", "missed", "worst error");
  os << line;
  for (const SolverTally& t : tallies_) {
    const double per = t.solves > 0 ? 1.0 / static_cast<double>(t.solves) : 0.0;
    std::snprintf(line, sizeof line, "  %-18s %8ld %12.4f %10.3f %10.1f %8ld %11.3e\n", t.label.c_str(), t.solves,
                  1e3 * t.seconds * per, t.seconds, static_cast<double>(t.iterations) * per, t.misses, t.worst_error);
    os << line;
  }
}

void ShadowSolvers::write_json(const std::string& path, const std::string& scene, long steps) const {
  using nlohmann::json;
  json rows = json::array();
  for (std::size_t i = 0; i < tallies_.size(); ++i) {
    const SolverTally& t = tallies_[i];
    const double per = t.solves > 0 ? 1.0 / static_cast<double>(t.solves) : 0.0;
    rows.push_back({{"label", t.label},
                    {"role", i == 0 ? "scene" : "shadow"},
                    {"solver", json::parse(t.solver)},
                    {"solves", t.solves},
                    {"cpu_seconds", t.seconds},
                    {"cpu_ms_per_solve", 1e3 * t.seconds * per},
                    {"iterations", t.iterations},
                    {"iterations_per_solve", static_cast<double>(t.iterations) * per},
                    {"misses", t.misses},
                    {"worst_error", t.worst_error},
                    {"worst_solve", t.worst_solve},
                    {"work", t.work}});
  }
  const json doc = {{"format", "moreau-shadow-solvers/1"}, {"scene", scene}, {"steps", steps}, {"solvers", rows}};
  const std::string tmp = path + ".part";
  {
    std::ofstream f(tmp);
    f << doc.dump(1) << "\n";
    if (!f.flush()) throw RunError("MOREAU_SHADOW_REPORT: cannot write " + path);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw RunError("MOREAU_SHADOW_REPORT: cannot write " + path);
  }
}

}  // namespace moreau::kernel
