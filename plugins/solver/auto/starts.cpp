// The warm start's checks: rule 0 for a problem given with W (start_check.hpp, completed only
// when needed: start_error_above()), the start's error before the slices, and the check of a
// step at rest by APGD's start (rest_check() before the set-up, rest_probe() after). Their
// counted work is part of the solve's (start_work()).
#include <moreau/contact_error.hpp>

#include "auto.hpp"

namespace moreau::auto_solver {

/// After a step at rest (at_rest_, within the caches): the warm start's error first, by
/// APGD's start (its packed product, kept for an APGD slice if one follows; NLGS's records
/// are not packed for it). A warm start within the tolerance is the answer, as `apgd`
/// alone takes it (and as rule 0 takes it for a problem given with W). Until branch
/// i15-light NLGS's first sweep from the warm start came first at such a step (a warm
/// start accepted at every step lets resting bodies creep within the tolerance): it cost
/// 1.3–2.3× `apgd` in `solve()` on the light scenes (mortar_wall_2d, the arrays,
/// block_on_incline_3d), for a creep that the tolerance bounds (docs/solvers.md, "A step
/// at rest"). Above the tolerance the step is not at rest: the members go on from the
/// warm start, its error known. True when the step ends here; `u`: its W x + q then.
bool Auto::rest_probe(Eigen::VectorXd& u) {
  if (!(at_rest_ && bodies_ && records_fit_)) return false;
  const double w0 = work_;
  if (rest_.made) {  // rest_check() made it: its outcome, as start_error() keeps it
    work_ += rest_.work;
    keep_start_check(rest_.err, u);
  } else {
    start_error(start_, u);
  }
  if (trace_) trace_rest_check(work_ - w0, best_err_);
  return best_err_ <= tol_;
}

/// rest_probe()'s check made before the rest of the set-up (a warm start that is not
/// r = 0): a step still at rest is then the whole solve, without the members' states, the
/// copies of the start and the memory's bookkeeping, which learn() would leave as they
/// are (on block_on_incline_2d, every solve but two: ~880 instructions of `auto`'s own
/// around APGD's check, which took 2.8·10³). True when it is the answer: r, u and `rep`
/// are the solve's; else rest_probe() takes its outcome (the same numbers as before).
bool Auto::rest_check(Eigen::VectorXd& r, Eigen::VectorXd& u, SolverReport& rep) {
  rest_ = {true, inf, 0};
  const SolverReport s = apgd_start_check(r, u, &rest_.work);
  rest_.err = s.error;
  if (!(s.error <= tol_ && start_x_.allFinite())) return false;
  ++solve_index_;
  r.swap(start_x_);  // (start_x_ is scratch: set from r before its next use)
  rep.error = s.error;
  rep.converged = true;
  rep.work = rest_.work;
  if (trace_) {
    trace_rest_check(rest_.work, s.error);
    trace_solve({}, rep);
  }
  return true;
}

/// MOREAU_AUTO_TRACE: the check of a step at rest, its work and the warm start's error.
void Auto::trace_rest_check(double work, double err) const {
  std::fprintf(stderr, "auto: rest check %.3g work, warm start at %.2e\n", work, err);
}

/// The start's error before the slices (nlgs_sweeps = 0, or records beyond the caches).
/// Without NLGS's records APGD measures it (it packs its product for its first slice
/// anyway; that slice then continues from it): one product instead of two.
void Auto::start_error(Eigen::VectorXd& r, Eigen::VectorXd& u) {
  if (bodies_ && !records_packed_ && !pack_due_) {
    const SolverReport s = apgd_start_check(r, u, &work_);
    keep_start_check(s.error, u);  // its u = W x + q: the answer's when x is (finish())
    return;
  }
  velocities(r, u);
  keep(r, natural_map_error(*P_, r, u));
  work_ += costs_.product + costs_.error;
}

/// APGD's check of the start r (no step): its projection in start_x_ (kept over the solves:
/// no allocation at each step), u = W x + q, its error; its products packed and kept in
/// apgd_state_ for a slice of APGD that follows; the work counted into *work.
SolverReport Auto::apgd_start_check(const Eigen::VectorXd& r, Eigen::VectorXd& u, double* work) {
  apgd::Options o;
  o.tolerance = tol_;
  o.max_iterations = 0;  // the start only
  o.work = work;
  o.state = &apgd_state_;
  o.recompute_error = false;
  o.scaling = apgd_scaling();
  copy(start_x_, r);
  return apgd::solve(*P_, o, start_x_, u);
}

/// APGD's check of the start booked as its first slice: start_x_ the best iterate when its
/// error `err` is the lowest so far, with its u.
void Auto::keep_start_check(double err, const Eigen::VectorXd& u) {
  current_ = apgd_member;
  ++apgd_slices_;
  keep(start_x_, err, &u);
}

/// Whether the warm start's error exceeds `bound`, its check (rule 0, start_check.hpp)
/// going on from where it stopped only as far as that needs: for a problem given with W
/// outside a time step, where rule 0 stopped at the first contacts whose error exceeded
/// the tolerance (on the reduced corpus that check, a product and an error, half a sweep,
/// was the whole of auto's work above NLGS's on the pairs NLGS finishes in one sweep:
/// docs/solvers.md, rule 0). Once complete, the start is kept as an iterate when it is the
/// best (as rule 0 kept it). Rule 2b asks with 1e-3 (newton_first()).
bool Auto::start_error_above(double bound) {
  if (start_known_) return start_err_ > bound;
  work_ += start_check_.examine(*P_, start_, bound);
  if (start_check_.complete(*P_)) {
    start_known_ = true;
    start_err_ = start_check_.error;
    const int by = current_;
    current_ = -1;
    keep(start_, start_err_, &start_check_.u);
    current_ = by;
    if (trace_) std::fprintf(stderr, "auto: start error %.3e (completed when needed)\n", start_err_);
  }
  return start_check_.error > bound;
}

/// The counted work of rule 0 when it answers from r: the start's error, and its product
/// unless r = 0 (u = q then).
double Auto::start_work(const LocalProblem& P, const Eigen::VectorXd& r) {
  const WorkCosts c = WorkCosts::of(P, false);
  return c.error + ((r.array() == 0).all() ? 0.0 : c.product);
}

}  // namespace moreau::auto_solver
