#pragma once
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
// (rest_probe()); a challenger that wins at its first check is learnt (learn()); a member
// that finishes a step the incumbent led is tried first at the next solve (learn()).
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
//
// This header (private to the plugin) declares the solver; its member functions are defined
// by concern in this directory: register.cpp (parameters, saved state, registration),
// solve.cpp (one solve: rules 0–3 in order), starts.cpp (the warm start's checks: rule 0 and
// a step at rest), memory.cpp (what is remembered over a run: the incumbent, challengers),
// slices.cpp (rule 2: which member gets the next slice, and its bookkeeping),
// floor_slices.cpp (the floor's slices, floor.hpp, and rule 2b), members.cpp (one slice of
// each member method: NLGS, APGD, Newton, ADMM) and records.cpp (NLGS's body records and
// the products through them). The short functions called at every iteration or slice stay
// inline here: a step of a light scene takes 1–6 µs, where each call counts.
#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <moreau/field_cache.hpp>
#include <moreau/solver.hpp>
#include <vector>

#include "../lu_fill.hpp"
#include "../work.hpp"
#include "floor.hpp"
#include "start_check.hpp"
#include "admm_core.hpp"
#include "apgd_core.hpp"
#include "newton_core.hpp"
#include "nlgs_body_sweep.hpp"
#include "nlgs_sweep.hpp"
#include "sweep_order.hpp"

namespace moreau::auto_solver {

// Newton twice: on its own run from the warm start (what `newton` alone does), and from the
// best iterate so far (often close: NLGS's or APGD's).
enum Member { nlgs_member, apgd_member, newton_start_member, newton_member, admm_member, member_count };
inline constexpr const char* member_name[member_count] = {"nlgs", "apgd", "newton", "newton from the best", "admm"};

inline constexpr double inf = std::numeric_limits<double>::infinity();

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

inline double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

class Auto : public Solver {
 public:
  static Schema schema();
  static constexpr const char* doc =
      "portfolio: the member cheapest on earlier solves (NLGS at first), then NLGS, APGD, Newton, ADMM in slices chosen by measured progress";

  Auto(const Params& p, const BuildContext&);

  bool reads_matrix_with_factor() const override { return false; }

  // register.cpp: the saved state (the memory over the solves of a run).
  std::vector<FieldSpec> state_fields(int) const override;
  void save_state(EntitySet& set) const override;
  void load_state(const EntitySet& set) override;
  // solve.cpp: one solve, from the start to the answer.
  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override;

 private:
  // solve.cpp: the trace of a solve.
  void trace_solve(const std::array<MemberState, member_count>& m, const SolverReport& rep) const;
  // starts.cpp: the warm start's checks (rule 0; a step at rest).
  bool rest_probe(Eigen::VectorXd& u);
  bool rest_check(Eigen::VectorXd& r, Eigen::VectorXd& u, SolverReport& rep);
  void trace_rest_check(double work, double err) const;
  void start_error(Eigen::VectorXd& r, Eigen::VectorXd& u);
  SolverReport apgd_start_check(const Eigen::VectorXd& r, Eigen::VectorXd& u, double* work);
  void keep_start_check(double err, const Eigen::VectorXd& u);
  bool start_error_above(double bound);
  static double start_work(const LocalProblem& P, const Eigen::VectorXd& r);
  // memory.cpp: what is remembered over the solves of a run.
  bool starts_with_another_member(bool direct) const;
  int incumbent(const std::array<MemberState, member_count>& m) const;
  int challenger(const std::array<MemberState, member_count>& m, int inc);
  double other_cost() const;
  void learn(const std::array<MemberState, member_count>& m);
  double bounded_need(const MemberState& s, int k) const;
  // floor_slices.cpp: the floor's slices (floor.hpp) and rule 2b.
  std::array<auto_floor::Run, member_count> floor_runs(const std::array<MemberState, member_count>& m) const;
  double first_stage_cap(bool direct) const;
  bool floor_slice(std::array<MemberState, member_count>& m);
  bool newton_first(const std::array<MemberState, member_count>& m);
  void own_slice(int k, double budget, MemberState* ms = nullptr);
  // slices.cpp: rule 2: the slices and the choice of their member.
  void slice(std::array<MemberState, member_count>& m, int who, double budget, bool later);
  void book_slice(MemberState& ms, int who, double took, double from, double reached, double window_rate);
  int next_member(const std::array<MemberState, member_count>& m, double elapsed);
  std::array<int, 5> probe_order() const;
  double probe_share(const std::array<MemberState, member_count>& m, int who) const;
  // members.cpp: one slice of a member method.
  double run_member(Member who, Eigen::VectorXd& x, double units, long budget, double* reached);
  double run_nlgs(Eigen::VectorXd& x, long max_sweeps, double units, bool first, double* reached);
  apgd::Options apgd_options(long max_iterations, double units, apgd::State& state, bool same_problem, bool resume);
  const LocalProblem& with_w();
  double newton_step_estimate() const;
  bool refine_fill(const std::array<MemberState, member_count>& m);
  // records.cpp: NLGS's body records, and the products u = W x + q.
  void velocities(const Eigen::VectorXd& x, Eigen::VectorXd& v);
  void records(const LocalProblem& P, bool pack);
  void pack_records(const Eigen::VectorXd& x);
  void sweep_cost();
  void prepare_nlgs();
  void lay_out_records();
  // Short and called often: here, inline.
  /// The work of one iteration of member k: `measured` on this problem when known, else its
  /// estimate (an NLGS sweep; an APGD step, a product and an error; a Newton or ADMM step,
  /// a factorisation).
  double iteration_work(int k, double measured) const {
    if (measured > 0) return measured;
    if (k == nlgs_member) return costs_.sweep;
    if (k == apgd_member) return costs_.product + costs_.error;
    return newton_step_estimate();
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
  /// x becomes the best iterate when its error e is the lowest so far. `u`: its W x + q as
  /// the member computed it (the same product finish() would take: it is then not
  /// recomputed; in a time step an NLGS-finished solve paid it twice, a quarter of a step
  /// at rest on mortar_wall_2d). Out of line (solve.cpp), as copy().
  void keep(const Eigen::VectorXd& x, double e, const Eigen::VectorXd* u = nullptr);
  /// to = from, through one out-of-line copy (solve.cpp) shared by the copies of a solve's
  /// vectors: inlined, each copy site was about 3 cache lines of vectorised code, and each
  /// solve of a light scene starts with cold instruction caches (docs/solvers-history.md,
  /// branch i15-tidy).
  static void copy(Eigen::VectorXd& to, const Eigen::VectorXd& from);
  /// Books a slice: its work and the rate it showed (ln of the error gained per unit of work).
  static void account(MemberState& ms, double took, double rate) {
    ms.spent += took;
    ++ms.slices;
    ms.rate = std::max(rate, 0.0);
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
  /// Whether `who` is Newton's own run after one slice that gained under 10× (no sign of
  /// its quadratic convergence): its next slice is then at most the work it has had (one
  /// doubling), not the usual 5 steps. Its one-slice rate, applied to the best error (NLGS's,
  /// near the tolerance), made it look nearly done: dense disks μ 1, cold, 1e-4, its own run
  /// 3.2e-3 → 2.1e-3 in 2 steps got 5 steps (1.1e6, 1.3× what NLGS alone needs) and gained
  /// 4 % (docs/solvers-history.md, branch i15-onestep). Not after a 10× gain: blocks on the
  /// elastic slab at 1e-8 (0.94 → 1.7e-2) then converges in its next slices. Not in a time
  /// step: on silo_janssen_2d's whole run at 1e-4 it made the solve stage 1.24× slower
  /// (misses 1 → 7; solvers-history.md, i15-onestep, "Taken out of time steps").
  bool newton_slow_start(const MemberState& ms, int who) const {
    return !in_step() && who == newton_start_member && ms.slices == 1 && ms.rate * ms.spent < std::log(10.0);
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
  /// Whether this problem's NLGS records of `record` doubles fit in 4× the cache.
  bool records_would_fit(double record) const { return WorkCosts::record_bytes(*P_, record) < 4 * WorkCosts::cache_bytes; }
  /// APGD's step scaling (apgd_core.hpp): per direction (normal, tangential) where NLGS's
  /// records exceed the caches (there APGD does the work; measured faster on 10⁴ and 10⁵
  /// spheres, docs/solvers.md "Large problems"), one scalar per contact elsewhere: on the
  /// example scenes and the FCLib corpus it was faster on some and slower on others.
  apgd::Scaling apgd_scaling() const { return beyond_caches() ? apgd::Scaling::normal_tangent : apgd::Scaling::contact; }
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

  int winner_ = -1;             ///< the member whose run reached the tolerance (−1: none)
  int challenger_ = -1;         ///< the member tried first on the incumbent's budget in this solve (−1: none)
  int incumbent_ = -1;          ///< the remembered member that leads this solve (−1: none)
  long nlgs_run_sweeps_ = 0;    ///< sweeps of NLGS's own run in this solve (its checks' schedule)
  std::array<double, 2> floor_k_{4.5, 8};  ///< the floor's K (floor.hpp): NLGS's and APGD's, Newton's and ADMM's
  double start_err_ = inf;      ///< the start's error (∞: not evaluated, r = 0)
  bool start_known_ = true;     ///< start_err_ evaluated, or r = 0 (else start_check_ goes on: start_error_above())
  auto_start::StartCheck start_check_;  ///< rule 0's check of a warm start given with W (FCLib), where it stopped
  double start_check_work_ = -1;        ///< its counted work in step 0 (−1: not used)
  bool newton_led_ = false;     ///< Newton's own run goes on step by step (newton_first)
  double newton_step_ = 0;      ///< the work of a Newton step measured in this solve (0: none yet)
  LuFill fill_;                 ///< Newton's LU fill predicted on this problem's W (lu_fill.hpp), when fill_known_
  bool fill_known_ = false;     ///< the estimate uses fill_ (refine_fill())
  bool fill_analysed_ = false;  ///< refine_fill() ran in this solve
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
  /// rest_check()'s outcome, handed over to rest_probe() when the step is not at rest.
  struct RestCheck {
    bool made = false;  ///< rest_check() ran in this solve
    double err = inf;   ///< the warm start's error by APGD's check (its iterate: start_x_)
    double work = 0;    ///< the check's counted work
  };
  RestCheck rest_;
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
  Eigen::VectorXd start_x_;  ///< the start projected by APGD's check (apgd_start_check())
  Eigen::VectorXd start_wr_;  ///< W r of the start, in a time step given with W (start_wr_ok_): APGD's first slice takes it
  bool start_wr_ok_ = false;
  /// Scratch of a slice (its iterate), of NLGS's first stage, and a member's u = W x + q:
  /// kept over the solves so that a solve allocates nothing (an allocation and its free
  /// were about 190 instructions, each solve of a light step paid two to four).
  Eigen::VectorXd slice_x_, first_x_, member_u_;
  Eigen::VectorXd best_u_;      ///< W best_ + q, when its member gave it (best_u_ok_)
  bool best_u_ok_ = false;
  std::vector<Eigen::Index> order_;
  struct Check {
    double t, err;
  };
  std::vector<Check> hist_;
  /// The solver set's fields of the saved state, in this order.
  static constexpr const char* state_names[6] = {"solves", "member_cost", "member_iteration", "member_next_try", "member_try_interval", "at_rest"};
  /// They resolved once for the set save_state() writes (moreau/field_cache.hpp: again for
  /// another set, even at the address of a destroyed one, or when a field is declared since).
  struct StateFields {
    FieldCacheKey cache_key;
    std::array<Field*, 6> field{};
    static StateFields of(EntitySet& set);
  };
  mutable StateFields state_fields_;
  // Kept over the solves of a run.
  long solve_index_ = 0;
  std::array<Memory, member_count> memory_;
  bool at_rest_ = false;  ///< the last solve's warm start met the tolerance at its first check (learn())
  nlgs::Sweeper sweeper_;
  nlgs::BodySweeper body_sweeper_;
  admm::Admm admm_;
  newton::Newton newton_;
};

}  // namespace moreau::auto_solver
