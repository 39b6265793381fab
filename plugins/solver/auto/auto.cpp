// `auto`: the solver to use when one does not know which. A portfolio of member methods
// (NLGS, APGD; regularised semismooth Newton, twice, and ADMM when a factorisation of W
// fits) that shares counted work between them (plugins/solver/work.hpp: a deterministic
// cost model in nanosecond-equivalents, so decisions are the same on every run).
//
// 0. The start: given W, a warm start within the tolerance is the answer (one product and
//    one error evaluation); from r = 0, r = 0 is the answer when no contact approaches.
// With `remember` (on by default), over the solves of a run it remembers each member's
// work per contact to converge from the warm start: the member with the lowest
// remembered work (the incumbent) goes first (NLGS when nothing is known); every few solves
// (4, doubling after each loss, at most 256) another member is tried first with the
// incumbent's work as its budget: if it converges within that, it takes over. A member
// that goes on with its own run past its budget is learnt at what it took (a memory rises
// at most twofold a solve: remembered()); after a step at rest the warm start's error is
// checked first, by APGD's start, and a warm start within the tolerance is the answer
// (rest_probe()); a challenger that wins at its first check is learnt (learn()).
// 1. NLGS runs on exactly the `nlgs` schedule (error at sweep 1, then every `check_every`
//    sweeps; through body velocities in the time-stepper), so a step that NLGS finishes
//    costs what `nlgs` costs. It keeps going while its measured rate says it finishes
//    within twice the work spent so far (or another member's remembered work). Another
//    incumbent gets three times its remembered work.
// 2. Otherwise the members take turns in slices that double: the member whose last
//    measured rate finishes soonest (the least work left from where it would go on) gets
//    the work spent so far; while it would not finish within that, an untried member
//    (cheapest iteration first: APGD, then Newton's own run, Newton from the best iterate,
//    ADMM; Newton's 4-step probe once the work spent reaches its cost (ski rental), or
//    sooner when the others' rates say they need more than it), or one that has had under
//    a fifth of the work, gets a quarter of it to measure its rate (APGD's first probe on
//    an FCLib problem from r = 0: all of it). Newton from the best starts from the best
//    iterate (in a time step NLGS and APGD too); Newton's own run and ADMM continue their
//    own runs from the warm start as each would alone (Newton with its line search's
//    memory), since Newton from NLGS's iterate can crawl; given W, so do NLGS and APGD
//    (floor.hpp: every slice of theirs is a slice of their own run).
//    Given W, a warm start within 1e-3 of the answer: Newton's own run takes one step first
//    once NLGS's first stage says it needs more than a step, and goes on while each step
//    gains 10× (newton_first(); docs/solvers.md, rule 2b).
//    In a time step a factorisation always waits for the work spent to reach its
//    (measured) cost and for NLGS and APGD to have had a fifth of it, and APGD's slices
//    keep their rate when its error rises (docs/solvers.md, rule 2c).
// 3. The answer is the best iterate of all; the solve ends at the tolerance, when every
//    member has used `max_iterations` of its own (Newton at most `newton_max_iterations`),
//    or (in a time step) had three slices in a row that gained less than 1 %. For a problem
//    given with W, a floor under the slices (floor.hpp) bounds auto's work by K times the
//    least member's (K = 4.5 for NLGS and APGD, 8 for Newton and ADMM, 4 without a
//    factorisation; + one of its iterations, one slice and rule 2b's Newton steps) and gives
//    up no member's own run before its cap, so auto reaches whatever a member reaches alone.
// docs/solvers.md states the rule and the guarantee measured on the corpus.
#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <moreau/contact_error.hpp>
#include <moreau/factor_matrix.hpp>
#include <moreau/solver.hpp>
#include <vector>

#include "../work.hpp"
#include "floor.hpp"
#include "start_check.hpp"
#include "admm_core.hpp"
#include "apgd_core.hpp"
#include "newton_core.hpp"
#include "nlgs_body_sweep.hpp"
#include "nlgs_sweep.hpp"
#include "sweep_order.hpp"

namespace {
using namespace moreau;

// Newton twice: on its own run from the warm start (what `newton` alone does), and from the
// best iterate so far (often close: NLGS's or APGD's).
enum Member { nlgs_member, apgd_member, newton_start_member, newton_member, admm_member, member_count };
constexpr const char* member_name[member_count] = {"nlgs", "apgd", "newton", "newton from the best", "admm"};

constexpr double inf = std::numeric_limits<double>::infinity();

/// What auto knows of one member during a solve.
struct MemberState {
  bool available = false;
  double spent = 0;         ///< work of this solve (plugins/solver/work.hpp)
  double rate = -1;         ///< ln(error) gained per unit of work in its last slice; −1: not tried
  int slices = 0;
  long iterations = 0;      ///< its own iterations (each member has `max_iterations`)
  double per_iteration = 0; ///< measured work of one of its iterations
  int fruitless = 0;        ///< consecutive slices without gain
  bool own_run = false;     ///< continues its own iterate instead of starting from the best
  bool clean = true;        ///< all its work so far was from the warm start (a fair measure of its cost)
  Eigen::VectorXd own;      ///< its own iterate (own_run)
  double own_err = inf;
  double need = 0;          ///< its work to converge extrapolated at its rate (0: unknown)
  double unfloored = 0;     ///< Newton's own run: the work of its rule-2b steps, left out of the floor's total
};

/// What auto remembers of a member over the solves of a run.
struct Memory {
  double cost = 0;        ///< work per contact to converge from the warm start (0: unknown)
  double step = 0;        ///< work per contact of one of its iterations (0: unknown)
  long next_probe = 0;    ///< the solve from which it may be tried first again
  long interval = 4;      ///< solves between two such tries (doubles after each loss)
};

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

class Auto : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target error (DESIGN §1; in a time step normalised by the approaching contacts)").gt(0).fallback(1e-3);
    s.integer("max_iterations", "maximum iterations of each member (NLGS sweeps, APGD, Newton or ADMM steps)").min(1).fallback(20000);
    s.integer("newton_max_iterations", "maximum steps of each of its Newton runs (as `newton`'s max_iterations; each step is a factorisation)").min(1).fallback(200);
    s.integer("nlgs_sweeps", "maximum sweeps of the first NLGS stage (0: start with the other members)").min(0).fallback(100000);
    s.integer("check_every", "NLGS sweeps between two evaluations of the error (as nlgs)").min(1).fallback(5);
    s.integer("direct_max_contacts", "above this many contacts, no sparse factorisation (Newton, ADMM)").min(0).fallback(1000);
    s.boolean("remember", "over the solves of a run, start with the member that was cheapest on the earlier ones (the memory is saved with every frame and restored on restart)").fallback(true);
    return s;
  }
  static constexpr const char* doc =
      "portfolio: the member cheapest on earlier solves (NLGS at first), then NLGS, APGD, Newton, ADMM in slices chosen by measured progress";

  Auto(const Params& p, const BuildContext&)
      : tol_(p.number("tolerance")), max_it_(p.integer("max_iterations")), nlgs_sweeps_(p.integer("nlgs_sweeps")),
        check_(p.integer("check_every")), direct_max_contacts_(p.integer("direct_max_contacts")),
        newton_max_it_(p.integer("newton_max_iterations")),
        remember_(p.boolean("remember")) {}

  bool reads_matrix_with_factor() const override { return false; }

  // With `remember`, the memory is part of the run's state (docs/output.md, "The solver's
  // state"): written with every frame and restored by `--restart`, so a continuation is
  // bit-identical. Per member, in the order nlgs, apgd, newton, newton from the best, admm.
  std::vector<FieldSpec> state_fields(int) const override {
    if (!remember_) return {};
    auto f = [](const char* name, int n, const char* units, const char* doc, FileType t) {
      return field_spec(sets::solver, name, n, n, 1, units, FieldOutput::frame, true, doc, t);
    };
    return {f("solves", 1, "1", "auto: solves of the run with contacts", FileType::int32),
            f("member_cost", member_count, "1", "auto: each member's remembered work per contact to converge from the warm start (0: unknown)", FileType::real),
            f("member_iteration", member_count, "1", "auto: each member's remembered work per contact of one iteration (0: unknown)", FileType::real),
            f("member_next_try", member_count, "1", "auto: the solve from which each member may be tried first again", FileType::int32),
            f("member_try_interval", member_count, "1", "auto: solves between two such tries", FileType::int32),
            f("at_rest", 1, "1", "auto: 1 when the last solve's warm start met the tolerance at its first check (a step at rest), else 0", FileType::int32)};
  }
  // Called after every step's solve: the six fields are found by their index in the set
  // (state_data()), not looked up by name at each step (a map of strings each, two of the
  // names beyond the short-string buffer: about 2·10³ instructions a step, more than a
  // light solve's own bookkeeping on cannonball_3d).
  void save_state(EntitySet& set) const override {
    if (!remember_) return;
    std::array<double*, 6> f;
    state_data(set, f);
    f[0][0] = static_cast<double>(solve_index_);
    double *cost = f[1], *step = f[2], *next = f[3], *interval = f[4];
    for (int k = 0; k < member_count; ++k) {
      cost[k] = memory_[k].cost;
      step[k] = memory_[k].step;
      next[k] = static_cast<double>(memory_[k].next_probe);
      interval[k] = static_cast<double>(memory_[k].interval);
    }
    f[5][0] = at_rest_ ? 1.0 : 0.0;
  }
  void load_state(const EntitySet& set) override {
    if (!remember_) return;
    std::array<const double*, 6> f;
    state_data(set, f);
    solve_index_ = static_cast<long>(f[0][0]);
    const double *cost = f[1], *step = f[2], *next = f[3], *interval = f[4];
    for (int k = 0; k < member_count; ++k) {
      memory_[k].cost = cost[k];
      memory_[k].step = step[k];
      memory_[k].next_probe = static_cast<long>(next[k]);
      memory_[k].interval = std::max(1L, static_cast<long>(interval[k]));
    }
    at_rest_ = f[5][0] != 0;
  }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    const int d = P.dim;
    sweep_costed_ = false;  // NLGS's preparations, each when first needed in this solve (sweep_cost())
    nlgs_ready_ = false;
    rest_checked_ = false;
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
    // 0. The start: given W (an FCLib problem), a warm start that already meets the
    // tolerance is the answer, for one product and one error evaluation (less than a
    // sweep); from r = 0 the answer is r = 0 exactly when no contact approaches (every
    // q_n ≥ 0: u = q lies in the dual cone), checked without a product. `newton` and
    // `prox` check their start too.
    double start_err = inf;
    start_known_ = true;
    start_check_work_ = -1;  // (a product and an error when the start's error is known)
    if ((r.array() == 0).all()) {
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
      velocities(r, u);
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
    start_ = r;
    cold_ = (r.array() == 0).all();
    best_ = r;
    best_err_ = start_err;  // ∞ when not evaluated (r = 0 with approaching contacts)
    best_by_ = -1;
    winner_ = -1;
    challenger_ = -1;
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
    floor_k_ = {auto_floor::member_k(direct, false), auto_floor::member_k(direct, true)};
    // Problems given with W (FCLib): the floor from the first stage on. In a time step (W
    // through the bodies) NLGS's first stage or the incumbent's slice is the first slice,
    // the floor acting from the slices on (a step that NLGS finishes costs what `nlgs` costs).
    first_stage_cap_ = in_step() ? inf : first_stage_cap(direct);

    auto finish = [&]() {
      if (!std::isfinite(best_err_)) best_ = start_;  // no iterate was ever evaluated
      r = best_;
      rep.iterations = total_;
      rep.work = work_;
      if (best_u_ok_ && std::isfinite(best_err_)) {  // u and the error of the best iterate, as its member computed them
        u = best_u_;
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
      Eigen::VectorXd x = challenged ? start_ : best_;
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

 private:
  /// The floor's view of the members (floor.hpp): NLGS's and APGD's own runs (OwnRun),
  /// Newton's own run and ADMM (theirs are their slices of the rule too).
  std::array<auto_floor::Run, member_count> floor_runs(const std::array<MemberState, member_count>& m) const {
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
  double first_stage_cap(bool direct) const {
    double s = (direct ? 5.0 : floor_k_[0]) * iteration_work(apgd_member, 0);
    if (direct) s = std::min(s, floor_k_[1] * iteration_work(admm_member, 0));  // (Newton's probe is 4 of them)
    return 8 * s;
  }
  /// The work of one iteration of member k: `measured` on this problem when known, else its
  /// estimate (an NLGS sweep; an APGD step, a product and an error; a Newton or ADMM step,
  /// a factorisation).
  double iteration_work(int k, double measured) const {
    if (measured > 0) return measured;
    if (k == nlgs_member) return costs_.sweep;
    if (k == apgd_member) return costs_.product + costs_.error;
    return newton_step_estimate();
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
  bool floor_slice(std::array<MemberState, member_count>& m) {
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
  bool newton_first(const std::array<MemberState, member_count>& m) {
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
  void own_slice(int k, double budget, MemberState* ms = nullptr) {
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

  /// Newton's steps are capped at newton_max_iterations too: each costs a factorisation.
  long member_max(int k) const {
    return k == newton_member || k == newton_start_member ? std::min(max_it_, newton_max_it_) : max_it_;
  }
  /// A member is given up after three slices in a row without a gain of 1 %; APGD in a time
  /// step after four: its error is not monotone and its slices keep their rate there
  /// (book_slice()), so one more doubling of its run (wet_pile_3d, a step of 650 contacts:
  /// APGD given up after 649 steps at 1.04e-3, Newton then took 1.5·10⁹ units; APGD alone
  /// converges there in 662 steps).
  bool excluded(const MemberState& s, int k) const {
    const int fruitless = bodies_ && k == apgd_member ? 4 : 3;
    return !s.available || s.iterations >= member_max(k) || (s.slices >= fruitless && s.fruitless >= fruitless);
  }

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
  bool rest_probe(Eigen::VectorXd& u) {
    if (!(at_rest_ && bodies_ && records_fit_)) return false;
    const double w0 = work_;
    if (rest_checked_) {  // rest_check() made it: its outcome, as start_error() keeps it
      current_ = apgd_member;
      ++apgd_slices_;
      work_ += rest_work_;
      keep(start_x_, rest_err_, &u);
    } else {
      start_error(start_, u);
    }
    if (trace_) std::fprintf(stderr, "auto: rest check %.3g work, warm start at %.2e\n", work_ - w0, best_err_);
    return best_err_ <= tol_;
  }
  /// rest_probe()'s check made before the rest of the set-up (a warm start that is not
  /// r = 0): a step still at rest is then the whole solve, without the members' states, the
  /// copies of the start and the memory's bookkeeping, which learn() would leave as they
  /// are (on block_on_incline_2d, every solve but two: ~880 instructions of `auto`'s own
  /// around APGD's check, which took 2.8·10³). True when it is the answer: r, u and `rep`
  /// are the solve's; else rest_probe() takes its outcome (the same numbers as before).
  bool rest_check(Eigen::VectorXd& r, Eigen::VectorXd& u, SolverReport& rep) {
    rest_work_ = 0;
    Eigen::VectorXd& x = start_x_;
    x = r;
    const SolverReport s = apgd::solve(*P_, start_options(&rest_work_), x, u);
    rest_err_ = s.error;
    rest_checked_ = true;
    if (!(s.error <= tol_ && x.allFinite())) return false;
    ++solve_index_;
    r = x;
    rep.error = s.error;
    rep.converged = true;
    rep.work = rest_work_;
    if (trace_) {
      std::fprintf(stderr, "auto: rest check %.3g work, warm start at %.2e\n", rest_work_, s.error);
      trace_solve({}, rep);
    }
    return true;
  }

  /// Whether a slice of `who` from the best iterate goes on with its own run from the warm
  /// start: APGD resumes its run while it holds the best iterate (run_member()), and NLGS's
  /// sweeps from its own best iterate are the sweeps it would have gone on with. Its work
  /// then still measures its cost from the warm start: a remembered member that needed more
  /// than its budget is learnt at what it took (else the memory learns only the solves that
  /// fit in the budget, and stays too low: on the issue-15 silo APGD's stayed at half its
  /// cost, and each step over it paid for Newton probes).
  bool continues_own_run(int who) const {
    return best_by_ == who && (who == nlgs_member || (who == apgd_member && apgd_slices_ > 0));
  }

  /// With `remember`: whether this solve starts with a member other than NLGS (the
  /// incumbent() of the members available on a problem of this size).
  bool starts_with_another_member(bool direct) const {
    if (!remember_) return false;
    int best = -1;
    for (int k = 0; k < member_count; ++k)
      if ((k == nlgs_member || k == apgd_member || direct) && memory_[k].cost > 0 && (best < 0 || memory_[k].cost < memory_[best].cost))
        best = k;
    return best > nlgs_member;
  }

  /// u = W x + q, through the bodies when only the factor was given: by NLGS's records
  /// when packed, else by APGD's packed product when APGD ran in this solve, else through
  /// the factor.
  void velocities(const Eigen::VectorXd& x, Eigen::VectorXd& v) {
    if (!bodies_) {
      v = P_->W * x + P_->q;
    } else if (records_packed_ || pack_due_) {
      if (!records_packed_) pack_records(x);
      body_sweeper_.velocities(x, v);
    } else if (!(apgd_slices_ > 0 && apgd::velocities(apgd_state_, *P_, x, v))) {
      multiply_w(P_->dim, P_->factor, x, v, impulse_, dv_);
      v += P_->q;
    }
  }
  /// NLGS's body records: their layout (record_size()) always, the records themselves now
  /// only while they fit in 4× the cache. Beyond that NLGS does not run first (see solve())
  /// and they are packed when it first runs, if ever: at 10⁴ spheres the packing cost about
  /// 3 ms a step (5 % of APGD's warm solve), for nothing.
  /// `pack`: false when the solve starts with another remembered member (NLGS may not run).
  /// Without packing, while the largest record a layout can give fits (records_fit_ is then
  /// true whatever the layout), the layout waits for lay_out_records(): a solve that ends at
  /// the rest probe never needs it, and its per-body isotropy check was the whole of `auto`'s
  /// cost above `apgd`'s on cannonball_3d (0.19 µs of 1.7 µs a solve).
  /// `pack` (the records' product serves velocities() from the start) is kept as due
  /// (pack_due_), and the records are packed when first used (pack_records(), run_nlgs()):
  /// a solve whose challenger finishes it never packs them (cannonball_3d's second solve:
  /// 2.7·10⁴ instructions of 1.2·10⁵). Every product then goes the same way as when they
  /// were packed here (the same records; Δv is set from the iterate at each use).
  void records(const LocalProblem& P, bool pack) {
    // APGD's error at every step there too (branch i15-10k): every 3 steps missed the dips
    // of APGD's error, which is not monotone, and ran on (10⁴ spheres, 50 steps, with the
    // cheaper products: 8.4 steps a warm step against 4.7, 14.1–14.3 ms against 12.0–12.1).
    apgd_check_every_ = 1;
    records_laid_out_ = false;
    records_packed_ = false;
    const int d = P.dim, k = P.factor.k;
    if (nlgs::BodySweeper::supports(d, k) &&  // (else layout() says why not)
        records_would_fit(static_cast<double>(nlgs::BodySweeper::largest_record_size(d, k)))) {
      records_fit_ = true;
      pack_due_ = pack;
      return;
    }
    lay_out_records();
    pack_due_ = records_fit_ && pack;
  }
  /// NLGS's records packed now (they were due: records()), Δv from x.
  void pack_records(const Eigen::VectorXd& x) {
    lay_out_records();
    body_sweeper_.pack(*P_, x);
    records_packed_ = true;
  }
  /// NLGS's sweep cost (costs_.sweep), through the body records: their layout, once per solve
  /// and only when NLGS may run or be weighed (a solve that its remembered APGD finishes
  /// never needs it: the layout's per-body isotropy check was 2.4·10³ instructions of such a
  /// solve's 3.7·10⁴ on cannonball_3d). Through W's rows of() has it already.
  void sweep_cost() {
    if (sweep_costed_ || !bodies_) return;
    sweep_costed_ = true;
    lay_out_records();
    const double record = static_cast<double>(body_sweeper_.record_size());
    // memory-bound beyond the caches; records with M⁻¹Hᵀ blocks count more (work.hpp)
    costs_.sweep = WorkCosts::body_sweep(*P_, record, body_sweeper_.dense_inverse_mass());
  }
  /// What NLGS needs before its first sweep of a solve: its cost, its order, W's rows.
  void prepare_nlgs() {
    if (nlgs_ready_) return;
    nlgs_ready_ = true;
    sweep_cost();
    if (!bodies_) sweeper_.prepare(*P_);
    nlgs::fixed_last_order(*P_, order_);
  }
  /// NLGS's record layout for this solve (once) and whether its records fit.
  void lay_out_records() {
    if (records_laid_out_) return;
    body_sweeper_.layout(*P_);
    records_fit_ = records_would_fit(static_cast<double>(body_sweeper_.record_size()));
    records_laid_out_ = true;
  }
  /// Whether this problem's NLGS records of `record` doubles fit in 4× the cache.
  bool records_would_fit(double record) const { return WorkCosts::record_bytes(*P_, record) < 4 * WorkCosts::cache_bytes; }
  /// APGD's step scaling (apgd_core.hpp): per direction (normal, tangential) where NLGS's
  /// records exceed the caches (there APGD does the work; measured faster on 10⁴ and 10⁵
  /// spheres, docs/solvers.md "Large problems"), one scalar per contact elsewhere: on the
  /// example scenes and the FCLib corpus it was faster on some and slower on others.
  apgd::Scaling apgd_scaling() const { return beyond_caches() ? apgd::Scaling::normal_tangent : apgd::Scaling::contact; }
  /// APGD's options for a slice of one of auto's APGD runs (the rule's, or the floor's own
  /// run): its caps, the solve's work counter, and the error taken from the iteration
  /// (finish() recomputes the answer's).
  apgd::Options apgd_options(long max_iterations, double units, apgd::State& state, bool same_problem, bool resume) {
    apgd::Options a;
    a.tolerance = tol_;
    a.max_iterations = max_iterations;
    a.max_work = units;
    a.work = &work_;
    a.state = &state;
    a.same_problem = same_problem;
    a.resume = resume;
    a.check_every = apgd_check_every_;
    a.scaling = apgd_scaling();
    a.recompute_error = false;
    // Outside a time step a slice's u is not used (run_member() keeps it in a step only): a
    // slice ending on an earlier best iterate then pays no product for it.
    a.velocities = in_step();
    return a;
  }
  /// A time step whose NLGS records exceed 4× the cache (about 2·10⁴ contacts of spheres):
  /// APGD does the work there, and `auto` adds nothing to what `apgd` alone would do on a
  /// warm-started step. NLGS's first stage is skipped (solve()); NLGS is not a challenger
  /// (challenger(): its rate shows only after ~10 memory-bound sweeps, and its first budget
  /// is the cold step's remembered work: at 10⁵ spheres its challenge at step 2 took 0.92 s
  /// for 65 sweeps that missed, against 0.3–0.4 s for APGD's whole warm solve); and a warm
  /// start that APGD accepts is the answer, as with `apgd` alone (before branch i15-light
  /// elsewhere NLGS swept such a warm start; here its records were packed, 9 MB at 10⁴
  /// spheres, and up to `check_every` sweeps: 10⁴ spheres, 50 steps, warm step 22.9 → 18.7
  /// ms without them). NLGS stays a member of the slices.
  bool beyond_caches() const { return bodies_ && !records_fit_; }
  /// A time step: through the bodies, or given with W by the time-stepper (finite-element
  /// bodies; LocalProblem::error_scale is set there, never for FCLib problems). There the
  /// floor (floor.hpp) does not act: its own runs are the guarantee's on problems given
  /// with W outside a time step; in time steps they cost 1.3–1.5× `apgd` on the
  /// finite-element scenes (elastic_block_hit_by_spheres_3d, docs/solvers.md).
  bool in_step() const { return bodies_ || P_->error_scale > 0; }
  /// The start's error before the slices (nlgs_sweeps = 0, or records beyond the caches).
  /// Without NLGS's records APGD measures it (it packs its product for its first slice
  /// anyway; that slice then continues from it): one product instead of two.
  void start_error(Eigen::VectorXd& r, Eigen::VectorXd& u) {
    if (bodies_ && !records_packed_ && !pack_due_) {
      Eigen::VectorXd& x = start_x_;  // kept over the solves: no allocation at each step
      x = r;
      current_ = apgd_member;
      const SolverReport s = apgd::solve(*P_, start_options(&work_), x, u);
      ++apgd_slices_;
      keep(x, s.error, &u);  // its u = W x + q: the answer's when x is (finish())
      return;
    }
    velocities(r, u);
    keep(r, natural_map_error(*P_, r, u));
    work_ += costs_.product + costs_.error;
  }
  /// APGD's options for the start's error only (its products packed and kept in apgd_state_
  /// for a slice of APGD that follows), the work counted into *work.
  apgd::Options start_options(double* work) {
    apgd::Options o;
    o.tolerance = tol_;
    o.max_iterations = 0;  // the start only
    o.work = work;
    o.state = &apgd_state_;
    o.recompute_error = false;
    o.scaling = apgd_scaling();
    return o;
  }
  /// x becomes the best iterate when its error e is the lowest so far. `u`: its W x + q as
  /// the member computed it (the same product finish() would take: it is then not
  /// recomputed; in a time step an NLGS-finished solve paid it twice, a quarter of a step
  /// at rest on mortar_wall_2d).
  void keep(const Eigen::VectorXd& x, double e, const Eigen::VectorXd* u = nullptr) {
    if (e < best_err_ && x.allFinite()) {
      best_u_ok_ = u != nullptr;
      if (u) best_u_ = *u;
      best_err_ = e;
      best_ = x;
      best_by_ = current_;
    }
  }
  /// Whether the warm start's error exceeds `bound`, its check (rule 0, start_check.hpp)
  /// going on from where it stopped only as far as that needs: for a problem given with W
  /// outside a time step, where rule 0 stopped at the first contacts whose error exceeded
  /// the tolerance (on the reduced corpus that check, a product and an error, half a sweep,
  /// was the whole of auto's work above NLGS's on the pairs NLGS finishes in one sweep:
  /// docs/solvers.md, rule 0). Once complete, the start is kept as an iterate when it is the
  /// best (as rule 0 kept it). Rule 2b asks with 1e-3 (newton_first()).
  bool start_error_above(double bound) {
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
  static double start_work(const LocalProblem& P, const Eigen::VectorXd& r) {
    const WorkCosts c = WorkCosts::of(P, false);
    return c.error + ((r.array() == 0).all() ? 0.0 : c.product);
  }

  /// The problem with W, assembled from the factor the first time a member needs it.
  const LocalProblem& with_w() {
    const LocalProblem& P = *P_;
    if (P.W.rows() == P.dim * P.contacts()) return P;
    if (!assembled_ready_) {
      assembled_.dim = P.dim;
      assembled_.W = assemble_w(P.dim, P.factor);
      assembled_.q = P.q;
      assembled_.mu = P.mu;
      assembled_.error_scale = P.error_scale;
      assembled_ready_ = true;
      // Counted as the cost model's assembly of W (what Newton's step estimate counts): "two
      // products" left a Newton or ADMM slice of a 40-contact step of box_tower_3d at a tenth
      // of its time (6.4e3 units for 32 µs), so they stayed remembered as cheap.
      work_ += WorkCosts::assembly(static_cast<double>(assembled_.W.nonZeros()), static_cast<double>(assembled_.W.rows()));
    }
    return assembled_;
  }

  /// The member with the lowest remembered work per contact among those available; −1 when
  /// none is known yet.
  int incumbent(const std::array<MemberState, member_count>& m) const {
    int best = -1;
    for (int k = 0; k < member_count; ++k)
      if (m[k].available && memory_[k].cost > 0 && (best < 0 || memory_[k].cost < memory_[best].cost)) best = k;
    return best;
  }

  /// A member to try before the incumbent on this solve: one whose turn has come (untried
  /// ones first, then the lowest remembered work) and whose first iterations fit in the
  /// incumbent's work. −1: none.
  int challenger(const std::array<MemberState, member_count>& m, int inc) {
    const double budget = memory_[inc].cost;
    int best = -1;
    for (int k = 0; k < member_count; ++k) {
      if (k == inc || !m[k].available || memory_[k].next_probe > solve_index_) continue;
      if (k == nlgs_member && beyond_caches()) continue;  // its rate shows after ~10 sweeps (beyond_caches())
      if (k == newton_member) continue;  // from the best iterate: only useful after another member
      // Its first iterations' work per contact: remembered, or estimated for one not yet
      // tried (Newton and ADMM: a factorisation each; on light steps more than a whole solve).
      const bool factors = k == newton_start_member || k == admm_member;
      const double step = memory_[k].step > 0 ? memory_[k].step
                          : factors           ? newton_step_estimate() / nc_
                          : k == apgd_member  ? (costs_.product + costs_.error) / nc_
                                              : costs_.sweep / nc_;
      const double first_steps = (factors ? 2.0 : 5.0) * step;
      if (first_steps > budget) {  // cannot show anything within the budget
        memory_[k].interval = std::min<long>(2 * memory_[k].interval, 256);
        memory_[k].next_probe = solve_index_ + memory_[k].interval;
        continue;
      }
      if (best < 0 || memory_[k].cost < memory_[best].cost) best = k;
    }
    return best;
  }

  /// One slice of `who`, at most `budget` work (0: none), then the bookkeeping. `later`: in
  /// the slices stage (a Newton probe is 4 steps whatever their work).
  void slice(std::array<MemberState, member_count>& m, int who, double budget, bool later) {
    MemberState& ms = m[who];
    const bool newton = who == newton_member || who == newton_start_member;
    if (later) budget = std::max({budget, 5 * ms.per_iteration, costs_.sweep});
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
    Eigen::VectorXd x = ms.own_run ? ms.own : best_;
    const double from = ms.own_run ? ms.own_err : best_err_;
    if (!ms.own_run && (x - start_).squaredNorm() != 0 && !continues_own_run(who)) ms.clean = false;
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

  /// NLGS sweeps from x (error at the first sweep, then every check_): until converged,
  /// `max_sweeps`, the work budget (`units` > 0), or, for the first stage (`first`), until
  /// its measured rate says another member would finish sooner. Returns its last measured
  /// rate (ln of the error per unit of work; 0 when unknown); `reached`: its lowest error.
  double run_nlgs(Eigen::VectorXd& x, long max_sweeps, double units, bool first, double* reached) {
    const LocalProblem& P = *P_;
    prepare_nlgs();
    if (bodies_ && !records_packed_) {  // packed when NLGS first runs (records beyond the caches)
      body_sweeper_.pack(P, x);
      records_packed_ = true;
    } else if (bodies_ && !first) {
      body_sweeper_.reset_velocities(x);  // the first stage starts where records() set Δv
    }
    const double w0 = work_;
    Eigen::VectorXd v;
    hist_.clear();
    double own_best = inf, rate = 0;
    *reached = own_best;
    for (long it = 1; it <= max_sweeps; ++it) {
      if (bodies_)
        body_sweeper_.sweep(x, 1.0, order_);
      else
        sweeper_.sweep(P, x, 1.0, order_);
      ++total_;
      ++nlgs_run_sweeps_;
      work_ += costs_.sweep;
      // The error at its run's first sweep and every check_ (as `nlgs` alone, over slices).
      if (nlgs_run_sweeps_ != 1 && nlgs_run_sweeps_ % check_ != 0) continue;
      velocities(x, v);
      work_ += costs_.product + costs_.error;
      const double e = natural_map_error(P, x, v);
      if (!std::isfinite(e)) break;
      // Its u is the answer's when it is the best (with W given v = W x + q exactly: a solve
      // that NLGS finishes then costs what `nlgs` costs; before, 1.5–2.1× on one sweep).
      keep(x, e, &v);
      own_best = std::min(own_best, e);
      *reached = own_best;
      if (best_err_ <= tol_) return rate;
      const double now = work_ - w0;
      hist_.push_back({now, own_best});
      if (units > 0 && now >= units) return rate;
      // The rate over the last window (about 4 checks, at least 2): ln(error) per unit of work.
      const std::size_t h = hist_.size();
      if (h < 3) continue;
      const auto& a = hist_[h > 5 ? h - 5 : 1];
      const auto& b = hist_[h - 1];
      rate = b.t > a.t ? std::log(a.err / b.err) / (b.t - a.t) : 0;
      const double remaining = rate > 0 ? std::log(b.err / tol_) / rate : inf;
      if (first && work_ >= first_stage_cap_) return rate;  // the floor (floor.hpp): another member is due
      if (first) {
        // Stay while finishing costs less than twice what has been spent (a switch could
        // not save more than that) or twice another member's remembered work: the factor
        // keeps warm-started steps that NLGS finishes from paying for a switch.
        if (remaining > 2 * std::max(work_, other_cost())) return rate;
      } else if (h >= 6 && !(b.err < 0.9 * hist_[h - 6].err)) {
        return rate;  // a later slice that stalls gives its work back
      }
    }
    return rate;
  }

  /// The lowest remembered work of a member other than NLGS, for this problem's size.
  double other_cost() const {
    double c = 0;
    for (int k = 1; k < member_count; ++k)
      if (memory_[k].cost > 0 && (c == 0 || memory_[k].cost < c)) c = memory_[k].cost;
    return remember_ ? c * nc_ : 0;
  }

  /// One slice of `who` from x (its iterate on exit), at most `units` of work. `reached`: the
  /// lowest error of the slice; returns NLGS's window rate (0 for the others).
  double run_member(Member who, Eigen::VectorXd& x, double units, long budget, double* reached) {
    Eigen::VectorXd v;
    SolverReport s;
    auto limits = [&](auto& o) {  // the members' Options share these four
      o.tolerance = tol_;
      o.max_iterations = budget;
      o.max_work = units;
      o.work = &work_;
    };
    current_ = who;
    switch (who) {
      case nlgs_member:
        nlgs_run_sweeps_ = 0;  // a run from the best iterate: its error at its first sweep
        return run_nlgs(x, budget, units, false, reached);
      case newton_member:
      case newton_start_member: {
        newton::Options o;
        limits(o);
        o.last = &last_;
        if (who == newton_start_member) o.merits = &newton_merits_;  // its own run goes on as one run
        s = newton_.solve(with_w(), o, x, v);
        work_ += newton_call() * static_cast<double>(s.iterations);  // work.hpp
        break;
      }
      case admm_member: {
        admm::Options o;
        limits(o);
        o.resume = admm_slices_++ > 0;  // its own run goes on where its last slice stopped
        s = admm_.solve(with_w(), o, x, v);
        if (!bodies_ && P_->error_scale > 0) work_ += WorkCosts::admm_step_with_w * static_cast<double>(s.iterations);  // work.hpp
        break;
      }
      case apgd_member: {
        // Its packed products are kept over the slices of a solve; its run goes on while it
        // holds the best iterate.
        const bool later = apgd_slices_++ > 0;
        s = apgd::solve(*P_, apgd_options(budget, units, apgd_state_, later, later && best_by_ == apgd_member), x, v);  // through the factor when W was not given
        break;
      }
      default:
        *reached = best_err_;
        return 0;
    }
    total_ += std::max<long>(s.iterations, 1);
    const double before = best_err_;
    keep(x, s.error);
    // In a time step its u = W x + q is the one the time-stepper would get from APGD alone
    // (through the bodies, or from W: the same W.apply as its recomputation): finish() need
    // not recompute it. Problems given with W outside a time step (FCLib) recompute it, as
    // the guarantee's counts have it.
    if (in_step() && who == apgd_member && best_err_ < before) {
      best_u_ = v;
      best_u_ok_ = true;
    }
    *reached = s.error;
    return 0;
  }

  /// Books a slice: its work and the rate it showed (ln of the error gained per unit of work).
  static void account(MemberState& ms, double took, double rate) {
    ms.spent += took;
    ++ms.slices;
    ms.rate = std::max(rate, 0.0);
  }
  /// Books a slice of rule 2 (slice(), or own_slice() when the rule picked the member) that
  /// took `took` from error `from` to `reached`: its rate (NLGS's over its last checks,
  /// `window_rate`; the others' over the slice), whether it was fruitless, and its work to
  /// converge extrapolated at that rate, or the winner when the tolerance is met.
  void book_slice(MemberState& ms, int who, double took, double from, double reached, double window_rate) {
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
  int next_member(const std::array<MemberState, member_count>& m, double elapsed) {
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
  std::array<int, 5> probe_order() const {
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
  double probe_share(const std::array<MemberState, member_count>& m, int who) const {
    if (who != exploring_) return 1.0;
    return who == apgd_member && m[who].slices == 0 && cold_ && !in_step() ? 1.0 : 0.25;
  }

  /// The work a member still needs at its last rate, from where it would go on: the best
  /// iterate, or ADMM's own run's iterate, which can be far behind (ranking by rate alone
  /// gave ADMM, at 2.6e-5, the last slice of dense disks at 1e-8 where NLGS, at 1.1e-8,
  /// needed a twentieth of it). Newton's own run is ranked from the best error, as by its
  /// rate alone: its rate grows as it converges, and ranking it from its own, slower start
  /// measured worse (polygons at 1e-8: 2.2 → 3.4× the least member's work). ∞ when the rate
  /// is unknown or nil.
  double work_left(const MemberState& s, int k) const {
    const double from = k == admm_member && s.own.size() ? s.own_err : best_err_;
    return s.rate > 0 ? std::log(std::max(from, tol_) / tol_) / s.rate : inf;
  }

  /// A Newton step's cost per call in a time step, beyond its sizes (work.hpp): through the
  /// bodies (W assembled from the factor) or given with W (finite elements); 0 outside one.
  double newton_call() const {
    return bodies_ ? WorkCosts::newton_step_call : P_->error_scale > 0 ? WorkCosts::newton_step_call_with_w : 0.0;
  }

  /// The work of one Newton step on this problem: remembered, or from W's fill (its LU
  /// has 1.1 to 5 nnz(W) entries on the corpus, 1.5 typically: 2 taken here).
  double newton_step_estimate() const {
    if (newton_step_ > 0) return newton_step_;  // measured in this solve
    if (memory_[newton_start_member].step > 0) return memory_[newton_start_member].step * nc_;
    const double nnz = bodies_ && P_->W.rows() == 0 ? 12.0 * P_->dim * P_->dim * nc_ : static_cast<double>(P_->W.nonZeros());
    const double n = P_->dim * nc_;
    const double estimate = WorkCosts::assembly(nnz, n) + WorkCosts::factorisation(nnz, nnz, n) + 3 * costs_.product +
                            newton_call();
    // In a time step, ADMM's step remembered from earlier solves (its first one factorises the
    // same W) bounds it from below: a 3D LU fills in far beyond W's size (wet_pile_3d: ADMM's
    // first step 1.1e7 units, Newton's 3e7, the estimate from the size a few 10⁶).
    return bodies_ ? std::max(estimate, memory_[admm_member].step * nc_) : estimate;
  }

  /// After a solve: each member's remembered work per contact follows what this solve showed
  /// (exponential average): the work of the member that converged, or the work extrapolated
  /// at its rate for one that did not; only for runs from the warm start (a fair measure),
  /// and for a winner not yet remembered (at its own work) also when it finished from
  /// another member's iterate.
  void learn(const std::array<MemberState, member_count>& m) {
    at_rest_ = best_err_ <= tol_ && total_ <= 2;  // the warm start (after at most one sweep) was the answer
    // A solve that its first member finished at its first check (a warm start that was
    // already the answer, or no contact closing) says nothing of the members' costs.
    // But a challenger that wins at its first check is learnt at what it took: it was tried
    // on the incumbent's budget and did the step for less (block_on_incline_3d: APGD won
    // every 4th step at its check, 895 units against NLGS's sweep, 1972, and NLGS stayed
    // remembered at its cold first step's 4010 a contact, so it was tried again and again).
    if (winner_ >= 0 && winner_ != challenger_ && m[winner_].iterations <= 1 && m[winner_].slices <= 1) return;
    for (int k = 0; k < member_count; ++k) {
      const MemberState& s = m[k];
      if (s.slices == 0) continue;
      Memory& mem = memory_[k];
      if (s.per_iteration > 0 && std::isfinite(s.per_iteration)) mem.step = s.per_iteration / nc_;
      // The winner also when it finished from another member's iterate, if it has no
      // memory yet, at its own work (below what it takes from the warm start: as the
      // remembered member it then goes on past its budget and is learnt at what it took;
      // one already remembered keeps its memory, as before: learnt so after hard steps too,
      // masonry_arch_2d at 1e-8 took 6 % more work over its 6000 steps). Before, it was not learnt: on
      // mortar_wall_2d at 1e-8 the cold step's winner APGD finished from NLGS's iterate and
      // only ADMM, which failed (its own run, clean), was remembered, at its bounded need
      // 1.3·10⁸ a contact; that was the next step's challenger's budget, and NLGS ran it
      // alone for 1430 sweeps (12 ms) where APGD takes 386 iterations. (At the solve's work
      // less the lost own runs instead, 1.6·10⁴ a contact there against 1.1·10⁴, the lost
      // challenges of Newton and ADMM on that budget left the 300 steps' work 8 % above main.)
      if (!s.clean && (k != winner_ || mem.cost > 0)) continue;
      const double c = (k != winner_ ? bounded_need(s, k) : s.spent) / nc_;
      if (c > 0 && std::isfinite(c)) mem.cost = remembered(mem.cost, c);
    }
  }

  /// The work a member that did not converge is remembered at: its need extrapolated at its
  /// last rate, but at most what its run would take to its iteration cap from where it
  /// stopped (a slice that gained next to nothing, ADMM's first step on a 650-contact step
  /// of wet_pile_3d, extrapolated to 7·10²⁰ units a contact).
  double bounded_need(const MemberState& s, int k) const {
    if (!(s.per_iteration > 0)) return s.need;
    const double cap = s.spent + static_cast<double>(std::max<long>(0, member_max(k) - s.iterations)) * s.per_iteration;
    return std::min(s.need, cap);
  }

  /// MOREAU_AUTO_TRACE: one line per solve (after its slices): the solve's index, its size,
  /// each member's work in it, the answer's error, and the memory after learn().
  void trace_solve(const std::array<MemberState, member_count>& m, const SolverReport& rep) const {
    std::fprintf(stderr, "auto: solve %ld, contacts %.0f, work %.4g (", solve_index_, nc_, rep.work);
    for (int k = 0; k < member_count; ++k)
      if (m[k].slices > 0) std::fprintf(stderr, " %s %.4g", member_name[k], m[k].spent);
    std::fprintf(stderr, " ), error %.2e%s, memory", rep.error, rep.converged ? "" : " MISSED");
    for (int k = 0; k < member_count; ++k)
      if (memory_[k].cost > 0) std::fprintf(stderr, " %s %.4g", member_name[k], memory_[k].cost);
    std::fprintf(stderr, "\n");
  }

  /// A member's remembered work after a solve that showed `c` (work per contact): the
  /// exponential average of the two, but one solve raises it at most twofold. Without the
  /// cap one hard step left a member's memory 20× above its usual cost for hundreds of
  /// solves (shear_flow_2d: NLGS's extrapolated need, then APGD's, stale while ADMM ran 450
  /// steps). (A won challenge setting the winner's memory to its work instead made members
  /// take turns on brick_wall_2d's settled steps, where any challenger wins: 1.08 → 1.43.)
  static double remembered(double old, double c) {
    if (!(old > 0)) return c;
    return 0.5 * old + 0.5 * std::min(c, 3 * old);
  }

  int winner_ = -1;             ///< the member whose run reached the tolerance (−1: none)
  int challenger_ = -1;         ///< the member tried first on the incumbent's budget in this solve (−1: none)
  long nlgs_run_sweeps_ = 0;    ///< sweeps of NLGS's own run in this solve (its checks' schedule)
  std::array<double, 2> floor_k_{4.5, 8};  ///< the floor's K (floor.hpp): NLGS's and APGD's, Newton's and ADMM's
  double start_err_ = inf;      ///< the start's error (∞: not evaluated, r = 0)
  bool start_known_ = true;     ///< start_err_ evaluated, or r = 0 (else start_check_ goes on: start_error_above())
  auto_start::StartCheck start_check_;  ///< rule 0's check of a warm start given with W (FCLib), where it stopped
  double start_check_work_ = -1;        ///< its counted work in step 0 (−1: not used)
  bool newton_led_ = false;     ///< Newton's own run goes on step by step (newton_first)
  double newton_step_ = 0;      ///< the work of a Newton step measured in this solve (0: none yet)
  /// NLGS's or APGD's own run for the floor (floor.hpp), beside the slices of the rule.
  struct OwnRun {
    Eigen::VectorXd x;         ///< its iterate (empty: the warm start)
    double spent = 0;          ///< its work in this solve
    long iterations = 0;
    double per_iteration = 0;  ///< the work of one of its iterations
    long sweeps = 0;           ///< NLGS: sweeps of the run (the schedule of its checks)
    int slices = 0;            ///< APGD: its slices (the later ones resume its state)
    double err = inf;          ///< its lowest error
  };
  std::array<OwnRun, 2> own_;   ///< NLGS's and APGD's (indices nlgs_member, apgd_member)
  apgd::State own_apgd_state_;
  double first_stage_cap_ = 0;  ///< the work at which the floor ends NLGS's first stage
  mutable int exploring_ = -1;  ///< the member next_member() picked to measure, not for its rate
  bool trace_ = std::getenv("MOREAU_AUTO_TRACE") != nullptr;
  double tol_;
  long max_it_, nlgs_sweeps_, check_, direct_max_contacts_, newton_max_it_;
  bool remember_;
  // Per solve.
  const LocalProblem* P_ = nullptr;
  double nc_ = 0;
  bool bodies_ = false;
  bool records_packed_ = false;  ///< NLGS's body records are packed for this solve (pack_records(), run_nlgs())
  bool pack_due_ = false;        ///< records() would have them packed: velocities() packs them at its first call
  bool sweep_costed_ = false;    ///< costs_.sweep is NLGS's through the records (sweep_cost())
  bool nlgs_ready_ = false;      ///< prepare_nlgs() was done for this solve
  bool rest_checked_ = false;    ///< rest_check() ran in this solve: its error rest_err_, its work rest_work_
  double rest_err_ = inf, rest_work_ = 0;
  long apgd_check_every_ = 1;    ///< APGD's steps between two errors
  std::vector<double> impulse_, dv_;  ///< scratch of products through the factor
  WorkCosts costs_;
  Eigen::VectorXd start_, best_;
  bool cold_ = false;     ///< the solve starts from r = 0
  double best_err_ = 0;
  long total_ = 0;
  double work_ = 0;       ///< work of this solve (plugins/solver/work.hpp)
  Eigen::VectorXd last_;  ///< Newton's last iterate of its last slice
  std::deque<double> newton_merits_;  ///< the line search's memory of Newton's own run
  int admm_slices_ = 0;   ///< ADMM slices of this solve (the later ones resume its run)
  int apgd_slices_ = 0;   ///< APGD slices of this solve
  apgd::State apgd_state_;
  int current_ = -1;      ///< the member running
  int best_by_ = -1;      ///< the member whose iterate is best_
  LocalProblem assembled_;
  bool assembled_ready_ = false;
  bool records_fit_ = false;     ///< NLGS's records fit in 4× the cache (records())
  bool records_laid_out_ = false;  ///< body_sweeper_.layout() was done for this solve
  Eigen::VectorXd start_x_;  ///< start_error()'s iterate (APGD's check of the start)
  Eigen::VectorXd best_u_;      ///< W best_ + q, when its member gave it (best_u_ok_)
  bool best_u_ok_ = false;
  std::vector<Eigen::Index> order_;
  struct Check {
    double t, err;
  };
  std::vector<Check> hist_;
  /// The solver set's fields of the saved state by their index in the set, found by name
  /// once and checked by name at each use (a set at the address of a destroyed one may
  /// hold other fields: no pointer is kept).
  static constexpr const char* state_names[6] = {"solves", "member_cost", "member_iteration", "member_next_try", "member_try_interval", "at_rest"};
  mutable std::array<std::size_t, 6> state_index_{};
  /// The six fields' data, in state_names' order.
  template <class Set, class Data>
  void state_data(Set& set, std::array<Data*, 6>& data) const {
    auto& fields = set.fields();
    for (std::size_t i = 0; i < 6; ++i) {
      std::size_t& at = state_index_[i];
      if (at >= fields.size() || fields[at].name() != state_names[i]) {
        const Field& f = set.field(state_names[i]);  // (throws when the set lacks it, as the lookups by name did)
        for (at = 0; &fields[at] != &f;) ++at;
      }
      data[i] = fields[at].data();
    }
  }
  // Kept over the solves of a run.
  long solve_index_ = 0;
  std::array<Memory, member_count> memory_;
  bool at_rest_ = false;  ///< the last solve's warm start met the tolerance at its first check (learn())
  nlgs::Sweeper sweeper_;
  nlgs::BodySweeper body_sweeper_;
  admm::Admm admm_;
  newton::Newton newton_;
};
MOREAU_REGISTER(Auto, "auto")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_auto")
