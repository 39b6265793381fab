#include "solve_log.hpp"

#include "../run/console.hpp"

#include <cstdio>
#include <ostream>

namespace moreau::kernel {

std::string scientific(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", x);
  return b;
}

void SolveLog::note_miss(long step, const SolverReport& report, const std::string& bodies) {
  ++misses_;
  if (missed_.size() < listed_misses) missed_.push_back({step, report.error, bodies});
  if (first_miss_ >= 0) return;
  first_miss_ = step;
  // Once, at the first miss: the user learns now, not after hours, that the run is not
  // solved to its tolerance (and where the residual is largest).
  // warn(): on a terminal the progress bar is erased first, so the line stands on its own.
  warn("step " + std::to_string(step) + ": the contact solver stopped at error " + scientific(report.error) +
       (tolerance > 0 ? " above its tolerance " + scientific(tolerance) : std::string(" without converging")) +
       " after " + std::to_string(report.iterations) + " iterations" +
       (bodies.empty() ? std::string() : "; largest residual at the contact of " + bodies) +
       ". The run goes on (\"on_failure\": \"stop\" would end it); the end-of-run summary counts such steps.");
}

void SolveLog::print_summary(std::ostream& err) const {
  if (solves_ == 0) return;
  if (misses_ == 0) {
    err << "contact solves: " << solves_ << " steps, all converged";
    if (tolerance > 0) err << " to " << scientific(tolerance);
    err << " (worst error " << scientific(worst_error_) << " at step " << worst_step_ << ")\n";
    return;
  }
  err << "warning: contact solves: " << misses_ << " of " << solves_ << " steps ended above the tolerance"
      << (tolerance > 0 ? " " + scientific(tolerance) : std::string()) << " (first at step " << first_miss_
      << "); worst error " << scientific(worst_error_) << " at step " << worst_step_;
  if (!worst_bodies_.empty()) err << ", largest residual at the contact of " << worst_bodies_;
  err << "\n";
  err << "  missed steps (error, contact with the largest residual):";
  for (const Miss& m : missed_)
    err << "\n    step " << m.step << ": " << scientific(m.error) << (m.bodies.empty() ? std::string() : ", " + m.bodies);
  if (misses_ > static_cast<long>(missed_.size())) err << "\n    … and " << misses_ - static_cast<long>(missed_.size()) << " more";
  err << "\n";
}

}  // namespace moreau::kernel
