// The floor under rule 2's slices for a problem given with W (floor.hpp states the bound):
// the floor's view of the members (floor_runs()), the cap of NLGS's first stage, one slice
// under the floor (floor_slice()), NLGS's and APGD's own runs (own_slice()), and rule 2b's
// Newton steps from a warm start close to the answer (newton_first()).
#include "auto.hpp"

namespace moreau::auto_solver {

/// The share of a Newton step that APGD's own run gets before rule 2b buys the step when
/// the warm start is within 10× of the tolerance (floor_slice()); 1/4 and 1/2 cost the
/// pairs Newton wins in one step more (1.45 → 1.78, 2.06), 1/16 was too short for APGD's
/// rate to show (box tower step 100 warm at 1e-4 stayed at 4.48).
constexpr double newton_rent = 0.125;

/// The floor's view of the members (floor.hpp): NLGS's and APGD's own runs (OwnRun),
/// Newton's own run and ADMM (theirs are their slices of the rule too).
std::array<auto_floor::Run, member_count> Auto::floor_runs(const std::array<MemberState, member_count>& m) const {
  std::array<auto_floor::Run, member_count> f{};
  for (int k : {nlgs_member, apgd_member}) {
    const OwnRun& o = own_[k];
    f[k].in = o.iterations < max_it_;
    f[k].spent = o.spent;
    f[k].step = iteration_work(k, o.per_iteration);
    f[k].k = floor_k_[0];
  }
  for (int k : {newton_start_member, admm_member}) {
    const MemberState& s = m[k];
    f[k].in = s.available && s.iterations < member_max(k);
    f[k].spent = s.spent;
    f[k].step = iteration_work(k, s.per_iteration);
    f[k].k = floor_k_[1];
  }
  return f;
}

/// The work at which NLGS's first stage ends (it ends sooner when its rate says it would
/// not finish within twice the work spent): 8 times the least K·s over the other floor
/// members (s their first iteration, K theirs). At 1× (every choice of the slices,
/// floor.hpp) the stage ended after about 5 sweeps, and on problems NLGS alone finishes in
/// a few tens of sweeps the floor then paid APGD's and Newton's first slices: at 8× the
/// pairs within 1× of the least member on the reduced corpus (main 18cca7e) went 78 → 81 (1e-4) and
/// 59 → 65 (1e-8), where one member dominates 15 → 20 of 57 at 1e-8, the worst unchanged
/// (3.77 / 4.89; 2×, 3×: no change, 4×, 6×: the bonded beam at 1e-4 1.31 → 4.6; 16×: 84
/// and 66). The bound's first slice is then at most 8·K_j·s_j (docs/solvers.md, 2a).
/// The cap stays that of K = 5 and 8 (40 APGD steps, 64 ADMM steps) with the K of 4.5
/// (floor.hpp): 36 APGD steps cut the stage before NLGS finished the bonded beam at 1e-4
/// (1.19 → 3.04× NLGS's work; at 1e-4 the corpus within 1.5× / 2×: 105 / 118 → 107 / 122).
double Auto::first_stage_cap(bool direct) const {
  double s = (direct ? 5.0 : floor_k_[0]) * iteration_work(apgd_member, 0);
  if (direct) s = std::min(s, floor_k_[1] * iteration_work(admm_member, 0));  // (Newton's probe is 4 of them)
  return 8 * s;
}

/// One slice of rule 2. The rule picks a member and its slice (the least it takes: its
/// budget, at least 5 of its iterations, Newton's 4-step probe; NLGS's and APGD's slices
/// continue their own runs, and the floor's slices of APGD's run are booked as APGD's
/// slices, so the rule ranks APGD by its run's rate); a floor member that
/// would then be behind (total + slice)/K gets a slice of its own run first (the floor
/// pays ahead, so the rule's slice never takes the total past K·(w + s) of a floor run);
/// when the rule has none left, the floor member with the least work. False when every
/// floor member has used its iterations and the others are excluded: a floor member's
/// own run is never given up before its cap (a run that gains nothing for a while can
/// still converge: Newton on the mass-ratio pile), so auto reaches what a member reaches.
bool Auto::floor_slice(std::array<MemberState, member_count>& m) {
  const auto runs = floor_runs(m);
  bool any = false;
  for (int k = 0; k < member_count; ++k) any = any || runs[k].in || !excluded(m[k], k);
  if (!any) return false;
  // Rule 2b's steps (newton_first()) go before the floor pays for them: they are left out
  // of the total the floor shares (`unfloored`), so the bound grows by their work alone (a
  // few Newton steps, each of which but the last gained 10×). Paid ahead, as every other
  // slice, they came after NLGS's and APGD's fifths of them: the warm pairs Newton wins
  // in one to three steps ended at 1.6–1.8× its work (docs/solvers.md "Guarantee").
  if (newton_first(m)) {
    MemberState& s = m[newton_start_member];
    exploring_ = -1;
    // Rule 2b's rent (docs/solvers.md): a warm start within 10× of the tolerance needs no
    // more than the 10× one Newton step promises, and APGD often gains that cheaply; its own
    // run first gets an eighth of a Newton step, and its rate then decides whether the step
    // is bought (newton_first() asks again). Box tower step 100 warm at 1e-4 (start 1.03e-4):
    // the step gained 1 % and cost 2.5× APGD's whole solve, 4.48 → 1.73× APGD's work; the
    // pairs Newton wins in one step there pay the eighth (box tower step 5: 1.45 → 1.62).
    const double rent = newton_rent * newton_step_estimate() - own_[apgd_member].spent;
    if (s.slices == 0 && rent > 0 && own_[apgd_member].iterations < max_it_ && !start_error_above(10 * tol_)) {
      own_slice(apgd_member, rent, &m[apgd_member]);  // booked as its slice: the rule sees its rate
      return true;
    }
    const double from = s.slices ? s.own_err : start_err_, w0 = work_;
    slice(m, newton_start_member, 0.5 * iteration_work(newton_start_member, s.per_iteration), false);  // one step
    s.unfloored += work_ - w0;
    newton_led_ = s.own_err < 0.1 * from;  // goes on while each step gains 10×
    return true;
  }
  const double total = work_ - m[newton_start_member].unfloored;  // the floor's total
  int who = next_member(m, work_);
  double upcoming = 0;  // the least work of the rule's slice
  int own = -1;         // the floor run that slice continues (Newton's own run, ADMM), if any
  double budget = 0;
  // NLGS or APGD picked: the slice continues its own run (it then counts for the floor
  // too), never a new run from the best iterate: a new APGD run restarted its
  // acceleration at every slice, and its work did not count for the floor. The floor's
  // slices of APGD's run are booked as APGD's slices (the rule then ranks APGD by its
  // run's rate; NLGS's are not: booked too, the rule took NLGS's window rate near 1e-8
  // over Newton's and ADMM's, tests/data/corpus dense disks μ 1 warm 3.79 → 6.21).
  // Measured on main 18cca7e (docs/solvers.md "Guarantee"): worst 4.93 → 4.24 (1e-4),
  // 5.12 → 4.88 (1e-8).
  const bool continues_own = who == nlgs_member || who == apgd_member;
  if (who >= 0) {
    own = who == newton_start_member || who == admm_member || continues_own ? who : -1;
    budget = probe_share(m, who) * work_;
    const MemberState& ms = m[who];
    const bool newton = who == newton_start_member || who == newton_member;
    const double step = iteration_work(who, ms.per_iteration);
    upcoming = newton && ms.slices == 0 ? 4 * step : std::max(5 * step, costs_.sweep);
    if (newton_slow_start(ms, who)) {
      upcoming = std::min(upcoming, std::max(ms.spent, step));
      budget = std::min(budget, upcoming);
    }
  }
  auto floor_runs_but = runs;
  if (own >= 0) floor_runs_but[own].in = false;  // its own run grows with the slice
  const int f = auto_floor::behind(floor_runs_but, total + upcoming);
  if (f >= 0 || who < 0) {
    int k = f;
    if (k < 0)  // the rule has none: the floor member with the least work
      for (int i = 0; i < member_count; ++i)
        if (runs[i].in && (k < 0 || runs[i].spent < runs[k].spent)) k = i;
    if (k < 0) return false;
    exploring_ = -1;
    const double b = std::max((total + upcoming) / runs[k].k - runs[k].spent, runs[k].step);
    if (k == nlgs_member || k == apgd_member)
      own_slice(k, b, k == apgd_member ? &m[k] : nullptr);  // APGD's: booked as its slice (the rule sees its run's rate)
    else
      slice(m, k, b, false);  // as many steps as fit (no probe of 4)
    return true;
  }
  // Its budget: the rule's (the work spent so far, or a quarter for a probe), within the
  // room the floor leaves (at least its least slice, which the floor has paid ahead for).
  budget = std::max(std::min(budget, auto_floor::room(runs, total, own)), upcoming);
  if (continues_own)
    own_slice(who, budget, &m[who]);
  else
    slice(m, who, budget, true);
  return true;
}

/// Rule 2b (docs/solvers.md): on a problem given with W whose warm start is close to the
/// answer (start error ≤ 1e-3, a factorisation fits), Newton's own run takes one step as
/// soon as the members tried so far need more than a Newton step at their rates (ski
/// rental: one step is bought when renting would cost more), and goes on one step at a
/// time while each step gains 10× (its quadratic convergence). On the corpus every warm
/// pair that Newton wins starts at 2e-5–5e-4 and converges in 1–3 steps (masonry arch,
/// step 5, 1e-8: 10.45 → 1.49× Newton's work); started later, by the probe rule's 4-step
/// probe that waits for 4 steps' work, it paid for ADMM and APGD first.
bool Auto::newton_first(const std::array<MemberState, member_count>& m) {
  if (bodies_ || cold_) return false;
  const MemberState& s = m[newton_start_member];
  if (s.slices > 0) return newton_led_ && !excluded(s, newton_start_member);
  if (!s.available) return false;
  double remaining = inf;
  for (int k = 0; k < member_count; ++k)
    if (m[k].slices > 0 && !excluded(m[k], k)) remaining = std::min(remaining, work_left(m[k], k));
  return remaining > newton_step_estimate() && !start_error_above(1e-3);  // (newton_led_ implies it)
}

/// A slice of NLGS's or APGD's own run (floor.hpp): from the warm start at first, then on
/// from where its last slice stopped, as the member alone (NLGS: its iterate and its
/// checks' schedule; APGD: its state, ApgdFactored.SlicesWithKeptProductsAreOneRun).
/// `ms`: the rule's view of the member, when the rule picked it (booked as its slice).
void Auto::own_slice(int k, double budget, MemberState* ms) {
  OwnRun& o = own_[k];
  if (o.x.size() == 0) o.x = start_;
  const double w0 = work_, t0 = trace_ ? thread_seconds() : 0;
  const long it0 = total_;
  const double from = std::isfinite(o.err) ? o.err : best_err_;
  double reached = inf, window_rate = 0;
  current_ = k;
  if (k == nlgs_member) {
    nlgs_run_sweeps_ = o.sweeps;
    window_rate = run_nlgs(o.x, std::max<long>(1, max_it_ - o.iterations), budget, false, &reached);
    o.sweeps = nlgs_run_sweeps_;
  } else {
    // Only with W given (the floor): one scalar per contact, as `apgd` alone.
    const apgd::Options a = apgd_options(std::max<long>(1, max_it_ - o.iterations), budget, own_apgd_state_,
                                         o.slices > 0, o.slices > 0);
    Eigen::VectorXd v;
    const SolverReport s = apgd::solve(*P_, a, o.x, v);
    total_ += std::max<long>(s.iterations, 1);
    keep(o.x, s.error);
    reached = s.error;
  }
  ++o.slices;
  o.iterations += total_ - it0;
  o.spent += work_ - w0;
  o.err = std::min(o.err, reached);
  if (total_ > it0) o.per_iteration = (work_ - w0) / static_cast<double>(total_ - it0);
  if (ms) {  // booked as the rule's slice of this member, as slice() does
    const double took = work_ - w0;
    ms->iterations += total_ - it0;
    if (total_ > it0) ms->per_iteration = o.per_iteration;
    book_slice(*ms, k, took, from, reached, window_rate);
  }
  if (trace_)
    std::fprintf(stderr, "auto: floor, own %s, budget %.3g, took %.3g work (%.3g ns), reached %.2e, best %.2e, it %ld\n",
                 member_name[k], budget, work_ - w0, 1e9 * (thread_seconds() - t0), reached, best_err_, total_);
}

}  // namespace moreau::auto_solver
