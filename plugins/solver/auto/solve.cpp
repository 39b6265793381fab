// One solve of `auto` (auto.hpp states the rule): the set-up, rule 0's start, the incumbent
// or a challenger first, NLGS's first stage, the slices of rule 2, and the answer (the
// `finish` lambda: the best iterate, learn(), the trace). Kept as one function so that the
// order of the rule's stages reads from top to bottom; the stages' parts live in the other
// files of this directory.
#include <moreau/contact_error.hpp>

#include "auto.hpp"

namespace moreau::auto_solver {

SolverReport Auto::solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) {
  const int d = P.dim;
  sweep_costed_ = false;  // NLGS's preparations, each when first needed in this solve (sweep_cost())
  nlgs_ready_ = false;
  rest_.made = false;
  const Eigen::Index nc = P.contacts(), n = d * nc;
  SolverReport rep;
  if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
  if (nc == 0) {
    u = P.q;
    rep.converged = true;
    return rep;
  }
  P_ = &P;
  nc_ = static_cast<double>(nc);
  bodies_ = P.factor.present();
  apgd_check_every_ = 1;  // records() may raise it
  assembled_ready_ = false;
  best_u_ok_ = false;
  start_wr_ok_ = false;
  // 0. The start: given W (an FCLib problem), a warm start that already meets the
  // tolerance is the answer, for one product and one error evaluation (less than a
  // sweep); from r = 0 the answer is r = 0 exactly when no contact approaches (every
  // q_n ≥ 0: u = q lies in the dual cone), checked without a product. `newton` and
  // `prox` check their start too.
  double start_err = inf;
  start_known_ = true;
  start_check_work_ = -1;  // (a product and an error when the start's error is known)
  const bool zero = (r.array() == 0).all();  // (cold_ below: r is unchanged until then)
  if (zero) {
    bool open = true;
    for (Eigen::Index a = 0; a < nc && open; ++a) open = P.q[d * a] >= 0;
    if (open) {
      u = P.q;
      start_err = natural_map_error(P, r, u);
    }
    if (bodies_ && !(start_err <= tol_)) records(P, true);
  } else if (bodies_) {
    // A solve that starts with another remembered member, or after a step at rest with the
    // warm start's check (rest_probe(), through APGD's product), packs NLGS's records only
    // if NLGS runs (run_nlgs()).
    records(P, !at_rest_ && !starts_with_another_member(nc <= direct_max_contacts_));  // once per solve
    if (at_rest_ && records_fit_ && rest_check(r, u, rep)) return rep;  // still at rest: the whole solve
  } else if (P.error_scale > 0) {  // a time step given with W (finite elements): as before
    // W r kept for APGD's start (run_member(), apgd::Options::start_wr), which took it again.
    start_wr_.noalias() = P.W * r;  // (into its own memory: Eigen assumes aliasing and would allocate a temporary)
    start_wr_ok_ = true;
    u = start_wr_ + P.q;  // (as velocities(): the product, then + q)
    start_err = natural_map_error(P, r, u);
  } else {
    // Given with W outside a time step (FCLib): the check stops at the first contacts whose
    // error alone exceeds the tolerance (start_check.hpp); start_error_above() goes on.
    start_known_ = false;
    start_check_.reset(P);
    start_check_work_ = start_check_.examine(P, r, tol_);
    if (start_check_.complete(P)) {
      start_known_ = true;
      start_err = start_check_.error;
      u = start_check_.u;
    }
  }
  start_err_ = start_err;
  newton_led_ = false;
  if (trace_) std::fprintf(stderr, "auto: start error %.3e\n", start_err);
  if (start_err <= tol_) {
    rep.error = start_err;
    rep.converged = true;
    rep.work = start_work(P, r);
    return rep;
  }
  costs_ = bodies_ ? WorkCosts::of(P, true) : WorkCosts::with_w_in_step(P);  // NLGS over W's rows in a time step (work.hpp)
  bool nlgs_first = true;  // run the first NLGS stage (false: records far beyond the caches)
  if (bodies_) {
    // NLGS's sweep cost (costs_.sweep) waits for the records' layout, done after the rest
    // probe (lay_out_records()): nothing before reads it.
    // Where its cache factor reaches its cap (records beyond 4× the cache: about 2·10⁴ contacts
    // of spheres), the first NLGS stage costs as much as APGD's whole warm solve before its
    // rate is even measured (10⁴ spheres: ~50 ms a step), so the slices start at once, as
    // with `nlgs_sweeps: 0`; NLGS stays a member of the slices.
    nlgs_first = records_fit_;  // records() packs them then (within 4× the cache)
  }
  copy(start_, r);
  cold_ = zero;
  copy(best_, r);
  best_err_ = start_err;  // ∞ when not evaluated (r = 0 with approaching contacts)
  best_by_ = -1;
  winner_ = -1;
  challenger_ = -1;
  incumbent_ = -1;
  total_ = 0;
  work_ = start_check_work_ >= 0 ? start_check_work_ : std::isfinite(start_err) ? costs_.product + costs_.error : 0;  // the start's check
  admm_slices_ = 0;
  apgd_slices_ = 0;
  newton_merits_.clear();
  current_ = -1;
  ++solve_index_;
  const bool direct = nc <= direct_max_contacts_;
  std::array<MemberState, member_count> m;
  m[nlgs_member].available = true;
  m[apgd_member].available = true;
  m[newton_member].available = direct;
  m[newton_start_member].available = direct;
  m[admm_member].available = direct;
  for (Member k : {newton_start_member, admm_member}) m[k].own_run = true;
  nlgs_run_sweeps_ = 0;
  own_ = {};
  newton_step_ = 0;
  fill_known_ = fill_analysed_ = false;
  floor_k_ = {auto_floor::member_k(direct, false), auto_floor::member_k(direct, true)};
  // Problems given with W (FCLib): the floor from the first stage on. In a time step (W
  // through the bodies) NLGS's first stage or the incumbent's slice is the first slice,
  // the floor acting from the slices on (a step that NLGS finishes costs what `nlgs` costs).
  first_stage_cap_ = in_step() ? inf : first_stage_cap(direct);

  auto finish = [&]() {
    if (!std::isfinite(best_err_)) best_ = start_;  // no iterate was ever evaluated
    // The answer handed over by swapping buffers, not copied (best_ and best_u_ are set
    // anew by the next solve before they are read; r and u keep their sizes, n).
    r.swap(best_);
    rep.iterations = total_;
    rep.work = work_;
    if (best_u_ok_ && std::isfinite(best_err_)) {  // u and the error of the best iterate, as its member computed them
      u.swap(best_u_);
      rep.error = best_err_;
    } else {
      velocities(r, u);
      rep.error = natural_map_error(P, r, u);
      rep.work += costs_.product + costs_.error;  // the answer's u and error, recomputed
    }
    rep.converged = rep.error <= tol_;
    if (remember_) learn(m);
    if (trace_) trace_solve(m, rep);
    return rep;
  };

  // 0. The incumbent, and now and then another member first on the incumbent's budget.
  // After a step at rest the warm start's check first (a step still at rest ends there;
  // a challenge waits for a step that moves: at rest every member's cost is its check).
  if (rest_probe(u)) return finish();
  const int inc = remember_ ? incumbent(m) : -1;
  incumbent_ = inc;
  // NLGS's sweep cost now if NLGS may run or be weighed before the slices (first, or as
  // the challenger, whose turn challenger() checks): else it waits (sweep_cost()).
  if (inc < 0 || inc == nlgs_member || memory_[nlgs_member].next_probe <= solve_index_) sweep_cost();
  bool challenged = false;  // a challenger ran first and lost
  if (inc >= 0) {
    const int c = challenger(m, inc);
    challenger_ = c;
    if (c >= 0) {
      slice(m, c, memory_[inc].cost * nc_, false);
      Memory& mc = memory_[c];
      if (best_err_ <= tol_) {
        mc.interval = 4;
      } else {
        mc.interval = std::min<long>(2 * mc.interval, 256);
        challenged = true;
        m[apgd_member].clean = false;  // the others now start from its iterate; NLGS from the warm start
        m[newton_member].clean = false;
      }
      mc.next_probe = solve_index_ + mc.interval;
      if (best_err_ <= tol_) return finish();
    }
  }

  // 1. The first member: NLGS on the `nlgs` schedule, or the incumbent on thrice its work.
  const int first = inc >= 0 ? inc : nlgs_member;
  if (first == nlgs_member && nlgs_sweeps_ > 0 && nlgs_first) {
    MemberState& ms = m[nlgs_member];
    const double before = work_;
    const long before_it = total_;
    const double t0 = trace_ ? thread_seconds() : 0;
    double reached = inf;
    // The warm start, unless a tried member did better; after a lost challenge the warm
    // start (the challenger's iterate, whose error is all that is known, can be far worse:
    // APGD's on bonded contacts), with Δv set anew (the challenger may have moved it).
    Eigen::VectorXd& x = first_x_;  // (kept over the solves: no allocation at each)
    x = challenged ? start_ : best_;
    if ((x - start_).squaredNorm() != 0) ms.clean = false;
    if (bodies_ && records_packed_ && (challenged || !ms.clean)) body_sweeper_.reset_velocities(x);  // (else run_nlgs packs them from x)
    current_ = nlgs_member;
    const double rate = run_nlgs(x, std::min(nlgs_sweeps_, max_it_), 0, true, &reached);
    ms.iterations += total_ - before_it;
    if (total_ > before_it) ms.per_iteration = (work_ - before) / static_cast<double>(total_ - before_it);
    if (trace_)
      std::fprintf(stderr, "auto: first nlgs %.3g work (%.3g ns), best %.2e, rate %.2e, it %ld, n %ld nnz %ld\n", work_ - before,
                   1e9 * (thread_seconds() - t0), best_err_, rate, total_, static_cast<long>(P_->q.size()),
                   static_cast<long>(P_->W.nonZeros()));
    account(ms, work_ - before, rate);
    // From the warm start (a lost challenge restarts it there), as `nlgs` alone: the
    // start of NLGS's own run for the floor (floor.hpp).
    own_[nlgs_member] = OwnRun{x, work_ - before, total_ - before_it, ms.per_iteration, nlgs_run_sweeps_, 1, reached};
    if (best_err_ <= tol_) {
      winner_ = nlgs_member;
      return finish();
    }
    ms.need = rate > 0 ? (work_ - before) + std::log(best_err_ / tol_) / rate : 0;
  } else if (first != nlgs_member) {
    slice(m, first, 3 * memory_[first].cost * nc_, false);
    if (best_err_ <= tol_) return finish();
  } else if (!std::isfinite(best_err_)) {  // nlgs_sweeps = 0: the start's error, unless rule 0 had it
    if (start_known_)
      start_error(r, u);
    else
      start_error_above(inf);
  }
  if (!std::isfinite(best_err_) && !start_known_) start_error_above(inf);  // NLGS's first stage gave no finite error
  if (!std::isfinite(best_err_)) return finish();
  sweep_cost();  // the slices weigh NLGS's sweeps

  // 2. Slices that double, to the member expected to finish first; under the floor for a
  // problem given with W (floor.hpp). In a time step, as before the floor: there it cost
  // brick_wall_2d 26 % and box_tower_3d 90 % more solve time over 300 steps at 1e-3 (the
  // own runs and factorisations it pays for in the steps that reach the slices).
  while (best_err_ > tol_) {
    if (!in_step()) {
      if (!floor_slice(m)) break;
      continue;
    }
    const int who = next_member(m, work_);
    if (who < 0) break;
    slice(m, who, probe_share(m, who) * work_, true);
  }
  return finish();
}

/// MOREAU_AUTO_TRACE: one line per solve (after its slices): the solve's index, its size,
/// each member's work in it, the answer's error, and the memory after learn().
void Auto::trace_solve(const std::array<MemberState, member_count>& m, const SolverReport& rep) const {
  std::fprintf(stderr, "auto: solve %ld, contacts %.0f, work %.4g (", solve_index_, nc_, rep.work);
  for (int k = 0; k < member_count; ++k)
    if (m[k].slices > 0) std::fprintf(stderr, " %s %.4g", member_name[k], m[k].spent);
  std::fprintf(stderr, " ), error %.2e%s, memory", rep.error, rep.converged ? "" : " MISSED");
  for (int k = 0; k < member_count; ++k)
    if (memory_[k].cost > 0) std::fprintf(stderr, " %s %.4g", member_name[k], memory_[k].cost);
  std::fprintf(stderr, "\n");
}

/// x becomes the best iterate when its error e is the lowest so far (see auto.hpp).
void Auto::keep(const Eigen::VectorXd& x, double e, const Eigen::VectorXd* u) {
  if (e < best_err_ && x.allFinite()) {
    best_u_ok_ = u != nullptr;
    if (u) copy(best_u_, *u);
    best_err_ = e;
    copy(best_, x);
    best_by_ = current_;
  }
}

[[gnu::noinline]] void Auto::copy(Eigen::VectorXd& to, const Eigen::VectorXd& from) { to = from; }

}  // namespace moreau::auto_solver
