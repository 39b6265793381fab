// `auto`: the solver to use when one does not know which. A portfolio of member methods
// (NLGS; regularised semismooth Newton, twice, and ADMM when a factorisation of W fits;
// APGD when it does not) that shares the time between them from what it measures while
// solving: each member's progress per second (ln of the error gained per second of its
// own time) and the time the other members took on earlier problems of the run.
//
// 1. NLGS first, on exactly the `nlgs` schedule (error at sweep 1, then every
//    `check_every` sweeps; through body velocities in the time-stepper): a warm-started
//    step that NLGS finishes costs what `nlgs` costs. NLGS keeps going while its measured
//    rate says it will finish within the time spent so far, or within what the other
//    members took on earlier problems of this run (per contact), whichever is larger.
// 2. Otherwise the members take turns in time slices that double: the member whose last
//    rate finishes soonest gets the time spent so far; while it would not finish within
//    that, an untried member, or one that has had under a fifth of the time, gets a quarter
//    of it first, to measure its rate. NLGS, APGD and the first Newton start from the
//    best iterate; the second Newton and ADMM continue their own runs from the warm start,
//    as each would alone (Newton from NLGS's iterate can crawl where alone it converges).
// 3. The answer is the best iterate of all; the solve ends at the tolerance, when every
//    member has used `max_iterations` of its own (Newton at most 200), or had three slices
//    in a row that gained less than 1 %.
// docs/solvers.md states the rule and the guarantee measured on the corpus.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <moreau/contact_error.hpp>
#include <moreau/factor_matrix.hpp>
#include <moreau/solver.hpp>
#include <vector>

#include "admm_core.hpp"
#include "apgd_core.hpp"
#include "newton_core.hpp"
#include "nlgs_body_sweep.hpp"
#include "nlgs_sweep.hpp"

namespace {
using namespace moreau;


// Newton twice: from the best iterate (NLGS's, often close) and on its own run from the warm
// start (from NLGS's iterate it can crawl where alone it converges fast).
enum Member { nlgs_member, newton_member, newton_start_member, admm_member, apgd_member, member_count };

/// What auto knows of one member during a solve.
struct MemberState {
  bool available = false;
  double spent = 0;         ///< work of this solve (products by W, plugins/solver/work.hpp)
  double rate = -1;         ///< ln(error) gained per unit of work in its last slice; −1: not tried
  int slices = 0;
  long iterations = 0;      ///< its own iterations (each member has `max_iterations`)
  double per_iteration = 0; ///< measured work of one of its iterations
  int fruitless = 0;        ///< consecutive slices without gain
  bool own_run = false;     ///< continues its own iterate instead of starting from the best
  Eigen::VectorXd own;      ///< its own iterate (own_run)
  double own_err = std::numeric_limits<double>::infinity();
  bool excluded(long max_it) const { return !available || iterations >= max_it || (slices >= 3 && fruitless >= 3); }
};

class Auto : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target error (DESIGN §1; in a time step normalised by the approaching contacts)").gt(0).fallback(1e-3);
    s.integer("max_iterations", "maximum iterations of each member (NLGS sweeps, Newton, ADMM or APGD steps)").min(1).fallback(20000);
    s.integer("nlgs_sweeps", "maximum sweeps of the first NLGS stage (0: start with the other members)").min(0).fallback(100000);
    s.integer("check_every", "NLGS sweeps between two evaluations of the error (as nlgs)").min(1).fallback(5);
    s.integer("direct_max_contacts", "above this many contacts, no sparse factorisation (Newton, ADMM): APGD instead").min(0).fallback(1000);
    return s;
  }
  static constexpr const char* doc =
      "portfolio: NLGS first, then NLGS, Newton, ADMM (or APGD for large problems) in time slices chosen by measured progress";

  Auto(const Params& p, const BuildContext&)
      : tol_(p.number("tolerance")), max_it_(p.integer("max_iterations")), nlgs_sweeps_(p.integer("nlgs_sweeps")),
        check_(p.integer("check_every")), direct_max_contacts_(p.integer("direct_max_contacts")) {}

  bool reads_matrix_with_factor() const override { return false; }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    const int d = P.dim;
    const Eigen::Index nc = P.contacts(), n = d * nc;
    SolverReport rep;
    if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
    if (nc == 0) {
      u = P.q;
      rep.converged = true;
      return rep;
    }
    P_ = &P;
    bodies_ = P.factor.present();
    assembled_ready_ = false;
    if (bodies_) body_sweeper_.prepare(P, r);  // the records, once per solve
    const Eigen::VectorXd start = r;
    best_ = r;
    best_err_ = std::numeric_limits<double>::infinity();
    total_ = 0;
    work_ = 0;
    admm_slices_ = 0;
    auto finish = [&]() {
      if (!std::isfinite(best_err_)) best_ = start;  // no iterate was ever evaluated
      r = best_;
      velocities(r, u);
      rep.iterations = total_;
      rep.error = natural_map_error(P, r, u);
      rep.converged = rep.error <= tol_;
      return rep;
    };

    const bool direct = nc <= direct_max_contacts_;
    std::array<MemberState, member_count> m;
    m[nlgs_member].available = true;
    m[newton_member].available = direct;
    m[newton_start_member].available = direct;
    m[admm_member].available = direct;
    m[apgd_member].available = !direct;
    // Newton and ADMM follow their own runs from the warm start, as each would alone:
    // started from NLGS's iterate, Newton can crawl for hundreds of steps where alone it
    // converges in tens (measured on spheres-in-a-box at 1e-8: 0.36 s alone, 3.9 s from
    // the best iterate). NLGS and APGD, first-order methods, start from the best.
    for (Member k : {newton_start_member, admm_member}) {
      m[k].own_run = true;
      m[k].own = r;
    }

    // 1. NLGS on the `nlgs` schedule, while its own rate says it finishes soon enough.
    if (nlgs_sweeps_ > 0) {
      const double before = work_;
      double first_err = 0;
      const long before_it = total_;
      const double rate = run_nlgs(r, std::min(nlgs_sweeps_, max_it_), 0, true, &first_err);
      m[nlgs_member].iterations += total_ - before_it;
      if (trace_) std::fprintf(stderr, "auto: first nlgs %.1f units, best %.2e, rate %.2e, it %ld\n", work_ - before, best_err_, rate, total_);
      if (best_err_ <= tol_) return finish();
      account(m[nlgs_member], work_ - before, rate);
    } else {
      velocities(r, u);
      keep(r, natural_map_error(P, r, u));
    }
    if (!std::isfinite(best_err_)) return finish();

    // 2. Slices that double, to the member expected to finish first.
    while (best_err_ > tol_) {
      const double elapsed = work_;
      const int who = next_member(m, elapsed);
      if (who < 0) break;
      MemberState& ms = m[who];
      // The member expected to finish first gets the work spent so far (slices double);
      // a member tried to measure its rate gets a quarter of it.
      // Either way at least 5 of its iterations: Newton's progress shows after a few.
      const double slice = std::max({(who == exploring_ ? 0.25 : 1.0) * elapsed, 5 * ms.per_iteration, 4.0});
      if (ms.own_run && !std::isfinite(ms.own_err)) {  // its start's error, once (hard problems only)
        Eigen::VectorXd v = with_w().W * ms.own + P.q;
        ms.own_err = natural_map_error(P, ms.own, v);
        work_ += 1;
      }
      Eigen::VectorXd x = ms.own_run ? ms.own : best_;
      const double from = ms.own_run ? ms.own_err : best_err_;
      const double t_start = work_;
      double reached = 0;
      const long before_it = total_;
      // Newton's first probe: 4 steps whatever their work (its progress shows after a few).
      const bool newton = who == newton_member || who == newton_start_member;
      const bool newton_probe = newton && ms.slices == 0;
      const long member_max = newton ? std::min<long>(max_it_, 200) : max_it_;  // a Newton step costs a factorisation
      const double window_rate = run_member(static_cast<Member>(who), x, newton_probe ? 0.0 : slice,
                                            newton_probe ? std::min<long>(4, member_max - ms.iterations)
                                                         : std::max<long>(1, member_max - ms.iterations), &reached);
      ms.iterations += total_ - before_it;
      if (total_ > before_it) ms.per_iteration = (work_ - t_start) / static_cast<double>(total_ - before_it);
      const double took = work_ - t_start;
      if (best_err_ <= tol_) {
        remember_other(static_cast<Member>(who), took, nc, true);
        break;
      }
      // Not converged: its work to converge, extrapolated at the rate it showed, bounds it.
      const double need = reached < from && reached > tol_ ? took * std::log(from / tol_) / std::log(from / reached) : 4 * took;
      remember_other(static_cast<Member>(who), std::min(need, 4 * took), nc, false);
      const double gain = reached < from ? std::log(from / reached) : 0.0;
      if (trace_) std::fprintf(stderr, "auto: at %.1f units, member %d, slice %.1f took %.1f, from %.2e reached %.2e, best %.2e, own %d, it %ld\n",
                               work_, who, slice, took, from, reached, best_err_, int(ms.own_run), total_);
      account(ms, took, who == nlgs_member ? window_rate : gain / std::max(took, 1e-12));
      if (gain < std::log(1 / 0.99)) ++ms.fruitless;
      else ms.fruitless = 0;
      if (ms.own_run) {
        ms.own = who == newton_start_member ? last_ : x;  // Newton resumes from its last step, not its best
        ms.own_err = std::min(ms.own_err, reached);
      }
    }
    return finish();
  }

 private:
  /// u = W x + q, through the bodies when only the factor was given.
  void velocities(const Eigen::VectorXd& x, Eigen::VectorXd& v) {
    if (bodies_)
      body_sweeper_.velocities(x, v);
    else
      v = P_->W * x + P_->q;
  }
  void keep(const Eigen::VectorXd& x, double e) {
    if (e < best_err_ && x.allFinite()) {
      best_err_ = e;
      best_ = x;
    }
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
    }
    return assembled_;
  }

  /// NLGS sweeps from x (error at the first sweep, then every check_): until converged,
  /// `max_sweeps`, the work budget (`units` > 0), or, for the first stage (`first`), until
  /// its measured rate says another member would finish sooner. Returns its last measured
  /// rate (ln of the error per second; 0 when unknown); `reached`: its lowest error.
  double run_nlgs(Eigen::VectorXd& x, long max_sweeps, double units, bool first, double* reached) {
    const LocalProblem& P = *P_;
    const Eigen::Index nc = P.contacts();
    if (bodies_) {
      if (!first) body_sweeper_.reset_velocities(x);  // the first stage starts where prepare() set Δv
    } else {
      sweeper_.prepare(P);
    }
    if (static_cast<Eigen::Index>(order_.size()) != nc) {
      order_.resize(static_cast<std::size_t>(nc));
      for (Eigen::Index a = 0; a < nc; ++a) order_[static_cast<std::size_t>(a)] = a;
    }
    const double w0 = work_;
    Eigen::VectorXd v;
    struct Check {
      double t, err;
    };
    std::vector<Check> hist;
    double own_best = std::numeric_limits<double>::infinity(), rate = 0;
    *reached = own_best;
    for (long it = 1; it <= max_sweeps; ++it) {
      if (bodies_)
        body_sweeper_.sweep(x, 1.0, order_);
      else
        sweeper_.sweep(P, x);
      ++total_;
      work_ += 1;  // a sweep reads each contact's data once: about a product by W
      if (it != 1 && it % check_ != 0) continue;
      velocities(x, v);
      work_ += 1;
      const double e = natural_map_error(P, x, v);
      if (!std::isfinite(e)) break;
      keep(x, e);
      own_best = std::min(own_best, e);
      *reached = own_best;
      if (best_err_ <= tol_) return rate;
      const double now = work_ - w0;
      hist.push_back({now, own_best});
      if (units > 0 && now >= units) return rate;
      // The rate over the last window (about 4 checks, at least 2): ln(error) per second.
      const std::size_t h = hist.size();
      if (h < 3) continue;
      const Check& a = hist[h > 5 ? h - 5 : 1];
      const Check& b = hist[h - 1];
      rate = b.t > a.t ? std::log(a.err / b.err) / (b.t - a.t) : 0;
      const double remaining = rate > 0 ? std::log(b.err / tol_) / rate : std::numeric_limits<double>::infinity();
      if (first) {
        // Stay while finishing costs less than twice what has been spent (a switch could
        // not save more than that) or twice another member's remembered work: the factor
        // keeps warm-started steps that NLGS finishes from paying for a probe.
        const double total_elapsed = work_;
        const double other = other_work_;
        if (remaining > 2 * std::max(total_elapsed, other)) return rate;
      } else if (h >= 6 && !(b.err < 0.9 * hist[h - 6].err)) {
        return rate;  // a later slice that stalls gives its time back
      }
    }
    return rate;
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
    switch (who) {
      case nlgs_member:
        return run_nlgs(x, budget, units, false, reached);
      case newton_member:
      case newton_start_member: {
        newton::Options o;
        limits(o);
        o.last = &last_;
        s = newton_.solve(with_w(), o, x, v);
        break;
      }
      case admm_member: {
        admm::Options o;
        limits(o);
        o.resume = admm_slices_++ > 0;  // its own run goes on where its last slice stopped
        s = admm_.solve(with_w(), o, x, v);
        break;
      }
      case apgd_member: {
        apgd::Options o;
        limits(o);
        s = apgd::solve(*P_, o, x, v);  // through the factor when W was not given
        break;
      }
      default:
        *reached = best_err_;
        return 0;
    }
    total_ += std::max<long>(s.iterations, 1);
    keep(x, s.error);
    *reached = s.error;
    return 0;
  }

  /// Books a slice: its time and the rate it showed (ln of the error gained per second).
  static void account(MemberState& ms, double took, double rate) {
    ms.spent += took;
    ++ms.slices;
    ms.rate = std::max(rate, 0.0);
  }

  /// The next member: the one whose last rate finishes soonest; but while that one would
  /// not finish within the time already spent, an untried member first, then one that has
  /// had under a fifth of the time. −1 when every member is excluded (three slices in a
  /// row without gain).
  int next_member(const std::array<MemberState, member_count>& m, double elapsed) const {
    int best = -1;
    for (int k = 0; k < member_count; ++k) {
      if (m[k].excluded(k == newton_member || k == newton_start_member ? std::min<long>(max_it_, 200) : max_it_) || m[k].slices == 0) continue;
      if (best < 0 || m[k].rate > m[best].rate) best = k;
    }
    const double remaining = best >= 0 && m[best].rate > 0 ? std::log(best_err_ / tol_) / m[best].rate
                                                            : std::numeric_limits<double>::infinity();
    exploring_ = -1;
    if (remaining > elapsed) {
      for (int k = 0; k < member_count; ++k)
        if (!m[k].excluded(k == newton_member || k == newton_start_member ? std::min<long>(max_it_, 200) : max_it_) && m[k].slices == 0) return exploring_ = k;
      int least = -1;
      for (int k = 0; k < member_count; ++k)
        if (!m[k].excluded(k == newton_member || k == newton_start_member ? std::min<long>(max_it_, 200) : max_it_) && k != best && m[k].spent < 0.2 * elapsed && (least < 0 || m[k].spent < m[least].spent)) least = k;
      if (least >= 0) return exploring_ = least;
    }
    return best;
  }

  /// Work the members other than NLGS take to converge (exponential average; a slice that
  /// did not converge is a lower bound). The first NLGS stage of later solves stays as
  /// long as it finishes with less work than that.
  void remember_other(Member who, double units, Eigen::Index nc, bool converged) {
    if (who == nlgs_member) return;
    const double per = units;  // work units are already relative to the problem's size
    (void)nc;
    if (converged)
      other_work_ = other_work_ > 0 ? 0.7 * other_work_ + 0.3 * per : per;
    else
      other_work_ = std::max(other_work_, per);
  }

  mutable int exploring_ = -1;  ///< the member next_member() picked to measure, not for its rate
  bool trace_ = std::getenv("MOREAU_AUTO_TRACE") != nullptr;
  double tol_;
  long max_it_, nlgs_sweeps_, check_, direct_max_contacts_;
  // Per solve.
  const LocalProblem* P_ = nullptr;
  bool bodies_ = false;
  Eigen::VectorXd best_;
  double best_err_ = 0;
  long total_ = 0;
  double work_ = 0;
  Eigen::VectorXd last_;  ///< Newton's last iterate of its last slice
  int admm_slices_ = 0;   ///< ADMM slices of this solve (the later ones resume its run)  ///< work of this solve, in products by W (deterministic, plugins/solver/work.hpp)
  LocalProblem assembled_;
  bool assembled_ready_ = false;
  std::vector<Eigen::Index> order_;
  // Kept over the solves of a run.
  double other_work_ = 0;
  nlgs::Sweeper sweeper_;
  nlgs::BodySweeper body_sweeper_;
  admm::Admm admm_;
  newton::Newton newton_;
};
MOREAU_REGISTER(Auto, "auto")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_auto")
