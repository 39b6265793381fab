// Rule 2: the slices that double, in a time step and (under the floor, floor_slices.cpp) for
// a problem given with W. next_member() picks the member (the least work left at its rate,
// else an untried member or one that had under a fifth of the work, probe_order()), slice()
// runs it and book_slice() books its rate, its need and whether it gained.
#include <moreau/contact_error.hpp>

#include "auto.hpp"

namespace moreau::auto_solver {

/// One slice of `who`, at most `budget` work (0: none), then the bookkeeping. `later`: in
/// the slices stage (a Newton probe is 4 steps whatever their work).
void Auto::slice(std::array<MemberState, member_count>& m, int who, double budget, bool later) {
  MemberState& ms = m[who];
  const bool newton = who == newton_member || who == newton_start_member;
  if ((newton || who == admm_member) && refine_fill(m) && (later || !in_step())) return;  // decided anew (refine_fill())
  if (later) budget = std::max({budget, 5 * ms.per_iteration, costs_.sweep});
  if (later && newton_slow_start(ms, who)) budget = std::min(budget, std::max(ms.spent, ms.per_iteration));
  if (who == newton_member && in_step() && !std::isfinite(best_err_)) {
    // Newton from the best iterate first in a solve whose start's error is not known yet
    // (it starts with that member, remembered: NLGS's records are not packed): the start's
    // error first, one product (the own runs take it too, below). Without it the slice
    // gained "from ∞": an infinite rate, so the rule gave Newton the next slice at once, as
    // long as all the work spent, and on silo_janssen_2d at 1e-4 that slice often ended
    // where it began (2 × 0.08 s, then APGD finished in 0.01 s).
    Eigen::VectorXd v;
    velocities(start_, v);
    work_ += costs_.product + costs_.error;
    keep(start_, natural_map_error(*P_, start_, v), &v);
    if (best_err_ <= tol_) return;  // the warm start is the answer
  }
  if (ms.own_run && ms.own.size() == 0) {
    ms.own = start_;
    if (std::isfinite(best_err_) && (best_ - start_).squaredNorm() == 0) ms.own_err = best_err_;
  }
  if (ms.own_run && !std::isfinite(ms.own_err)) {  // its start's error, once
    Eigen::VectorXd v;
    velocities(ms.own, v);
    ms.own_err = natural_map_error(*P_, ms.own, v);
    work_ += costs_.product + costs_.error;
    keep(ms.own, ms.own_err);
  }
  Eigen::VectorXd& x = slice_x_;  // (kept over the solves: no allocation at each slice)
  copy(x, ms.own_run ? ms.own : best_);
  const double from = ms.own_run ? ms.own_err : best_err_;
  if (!ms.own_run && ms.clean && !continues_own_run(who) && (x - start_).squaredNorm() != 0) ms.clean = false;
  const double t_start = work_, t0 = trace_ ? thread_seconds() : 0;
  double reached = inf;
  const long before_it = total_;
  const bool newton_probe = later && newton && ms.slices == 0;
  // A probe is 4 steps, but stops after the step that takes it past 6 estimated steps: a
  // first step far above the estimate (a 3D LU with much more fill than W: the wet pile,
  // 27 times) ends it there (floor.hpp: the slice over the floor's room stays one step).
  const double probe_work = newton_probe && !bodies_ ? 6 * newton_step_estimate() : 0.0;
  const double window_rate = run_member(static_cast<Member>(who), x, newton_probe ? probe_work : budget,
                                        newton_probe ? std::min<long>(4, member_max(who) - ms.iterations)
                                                     : std::max<long>(1, member_max(who) - ms.iterations),
                                        &reached);
  ms.iterations += total_ - before_it;
  const double took = work_ - t_start;
  if (total_ > before_it) ms.per_iteration = took / static_cast<double>(total_ - before_it);
  if (newton && ms.per_iteration > 0 && !bodies_) newton_step_ = ms.per_iteration;  // measured on this problem
  if (trace_)
    std::fprintf(stderr, "auto: %s [%s], budget %.3g, took %.3g work (%.3g ns), from %.2e reached %.2e, best %.2e, it %ld, n %ld nnz %ld\n",
                 member_name[who], later ? (who == exploring_ ? "probe" : "slice") : who == challenger_ ? "challenger" : "first", budget, took, 1e9 * (thread_seconds() - t0), from, reached, best_err_, total_,
                 static_cast<long>(P_->q.size()), static_cast<long>(P_->W.nonZeros()));
  book_slice(ms, who, took, from, reached, window_rate);
  if (ms.own_run) {
    ms.own = who == newton_start_member ? last_ : x;  // Newton resumes from its last step, not its best
    ms.own_err = std::min(ms.own_err, reached);
  }
}

/// Books a slice of rule 2 (slice(), or own_slice() when the rule picked the member) that
/// took `took` from error `from` to `reached`: its rate (NLGS's over its last checks,
/// `window_rate`; the others' over the slice), whether it was fruitless, and its work to
/// converge extrapolated at that rate, or the winner when the tolerance is met.
void Auto::book_slice(MemberState& ms, int who, double took, double from, double reached, double window_rate) {
  const double gain = reached < from ? std::log(from / reached) : 0.0;
  const double before = ms.rate;
  account(ms, took, who == nlgs_member ? window_rate : gain / std::max(took, 1e-12));
  // In a time step an APGD slice that never got below where it started keeps APGD's last
  // rate (still counted fruitless: three such and it is given up): its error is not
  // monotone, so near the tolerance a slice often ends above its start, and with a rate
  // of 0 APGD got no further slice while Newton and ADMM took the solve (silo_janssen_2d
  // replayed from step 3000 of a run, 250 steps: 2.17 -> 1.01 s, `apgd` alone 0.66;
  // wet_pile_3d from step 1400 of `nlgs`'s run: 0.38 -> 0.20 s, `nlgs` 0.17). Given W
  // (the floor's APGD run) too: the mortar wall, step 100, 1e-4, APGD's run at 8.5e-4 →
  // 9.7e-4 in one slice, then ADMM got 2× APGD's whole work before APGD's next slice took
  // it to 9.1e-5 (docs/solvers.md "Guarantee": worst at 1e-4 4.24 → 3.77, on 18cca7e).
  if (who == apgd_member && reached > from && before > 0) ms.rate = before;
  ms.fruitless = gain < std::log(1 / 0.99) ? ms.fruitless + 1 : 0;
  if (best_err_ > tol_)
    ms.need = ms.rate > 0 ? ms.spent + std::log(std::min(from, reached) / tol_) / ms.rate : 0;
  else
    winner_ = who;
}

/// The next member: the one whose last rate finishes soonest; but while that one would
/// not finish within the work already spent, an untried member first, then one that has
/// had under a fifth of the work. −1 when every member is excluded.
int Auto::next_member(const std::array<MemberState, member_count>& m, double elapsed) {
  int best = -1;
  double remaining = inf;
  for (int k = 0; k < member_count; ++k) {
    if (excluded(m[k], k) || m[k].slices == 0) continue;
    const double left = work_left(m[k], k);
    if (best < 0 || left < remaining || (left == remaining && m[k].rate > m[best].rate)) best = k, remaining = left;
  }
  exploring_ = -1;
  if (remaining > elapsed) {
    // Untried members, the cheapest iterations first. Newton's probe (4 steps, each a
    // factorisation; its own run first, as `newton` alone) and ADMM's first step (a
    // factorisation) wait until the work spent reaches their cost, unless the tried
    // members' rates say they need more than a Newton probe: as in ski rental, a problem
    // the others finish within a probe's work never pays for it, and one that Newton
    // solves pays at most the probe's work on top of Newton's. In a time step (W through
    // the bodies) the probe always waits for the work spent to reach its cost (the step
    // measured on the run's earlier solves once known, newton_step_estimate()), whatever
    // the rates say: near the tolerance of a warm-started step a slice's rate is noise
    // (APGD's error is not monotone: 1.11e-3 -> 2.82e-3 within a slice on wet_pile_3d, so
    // it showed no gain), and the probe came at once on 650 3D contacts, 1.2·10⁹ units in
    // one solve, on steps that APGD alone finishes: replayed from the same state (step
    // 1400, 200 steps) `auto` took 2.02 s against `apgd`'s 0.28 s, 0.41 s with the wait.
    double step = newton_step_estimate();
    // In a time step a factorisation measured in this solve (ADMM's first step, Newton's)
    // raises the estimate: before the run's first Newton solve it comes from W's size, and
    // a 3D LU fills in far beyond it (wet_pile_3d: ADMM's first step 1.1e7 units, Newton's
    // 3e7 a step, against an estimate of a few 10⁶).
    if (in_step())
      for (int k : {newton_start_member, newton_member, admm_member}) step = std::max(step, m[k].per_iteration);
    // In a time step a factorisation also waits while NLGS or APGD, tried and not given
    // up, has had under a fifth of the work (they get their quarter first, below): near
    // the tolerance their slices show no rate (APGD's error is not monotone, NLGS's stall
    // test cuts a slice after 25 sweeps), and Newton's probe came before APGD's second
    // look (wet_pile_3d, a step of 650 contacts: APGD stopped after 160 steps at
    // 1.01e-3, Newton then took 1.5·10⁹ units; APGD alone converges there in 662 steps).
    int starved = -1;  // (the best by rate too: here it would not finish within the work spent)
    if (in_step())
      for (int k : {nlgs_member, apgd_member})
        if (!excluded(m[k], k) && m[k].slices != 0 && m[k].spent < 0.2 * elapsed && (starved < 0 || m[k].spent < m[starved].spent))
          starved = k;
    int waiting = -1;
    for (int k : probe_order()) {
      if (k < 0 || excluded(m[k], k) || m[k].slices != 0) continue;
      const bool factors = k != apgd_member && k != nlgs_member;
      const double probe = k == admm_member ? step : factors ? 4 * step : 0.0;
      if ((probe > elapsed && (in_step() || remaining < 4 * step)) || (factors && starved >= 0)) {
        if (waiting < 0) waiting = k;
        continue;
      }
      return exploring_ = k;
    }
    if (starved >= 0) return exploring_ = starved;
    int least = -1;
    for (int k = 0; k < member_count; ++k)
      if (!excluded(m[k], k) && m[k].slices != 0 && k != best && m[k].spent < 0.2 * elapsed &&
          (least < 0 || m[k].spent < m[least].spent))
        least = k;
    if (least >= 0) return exploring_ = least;
    if (best < 0 && waiting >= 0) return exploring_ = waiting;
  }
  return best;
}

/// The order in which untried members are probed: APGD (the cheapest steps), the two
/// Newtons, ADMM. Newton's own run first (as `newton` alone: from NLGS's iterate Newton
/// can crawl), but from r = 0 on a problem given with W Newton from the best iterate
/// first (box tower, cold, 1e-4: Newton's own run spent its 4-step probe, 1.6× APGD's
/// whole solve, without moving from error 1.0; from APGD's iterate it converged in 4).
/// In a time step whose solve started with another remembered member, NLGS (its first
/// stage skipped, records within the caches) comes right after APGD: when that member
/// stalls it is the usual finisher (wet_pile_3d, APGD remembered and stalling at 2.5e-3
/// on a step: Newton's own run then took 0.88 s; with NLGS probed the run's solve stage
/// 1.24 → 0.49 s). −1: no member.
std::array<int, 5> Auto::probe_order() const {
  if (cold_ && !in_step()) return {apgd_member, newton_member, newton_start_member, admm_member, -1};
  if ((bodies_ ? records_fit_ : in_step()) && nlgs_sweeps_ > 0) return {apgd_member, nlgs_member, newton_start_member, newton_member, admm_member};
  return {apgd_member, newton_start_member, newton_member, admm_member, -1};
}

/// The share of the work spent so far that a slice of `who` gets: all of it for the member
/// picked for its rate; a quarter for a probe (a member picked to measure its rate), but
/// all of it for APGD's first on a problem given with W (FCLib) from r = 0: an accelerated
/// method's error is not monotone and its rate shows only after a few tens of steps (box
/// tower, cold, 1e-4: a quarter was 13 steps, 0.387 → 0.363, where APGD alone converges in
/// 126; auto then probed Newton for 3× APGD's whole work). Not from a warm start: there
/// NLGS usually finishes, and the larger probe cost brick_wall_2d 17 % more work over 300
/// steps. Not in the time-stepper (W through the bodies): there only a run's first step
/// starts from r = 0, and changing its answer within the tolerance changed the work of the
/// next 1000 steps by chance (box_tower_3d −45 %, brick_wall_2d +19 %).
double Auto::probe_share(const std::array<MemberState, member_count>& m, int who) const {
  if (who != exploring_) return 1.0;
  return who == apgd_member && m[who].slices == 0 && cold_ && !in_step() ? 1.0 : 0.25;
}

}  // namespace moreau::auto_solver
