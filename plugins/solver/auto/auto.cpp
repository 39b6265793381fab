// `auto`: the solver to use when one does not know which. A portfolio of member methods
// (NLGS; regularised semismooth Newton and ADMM when a factorisation of W fits; APGD when
// it does not) that shares the time between them from what it measures while solving:
// each member's progress per second (decades of error gained per second of its own
// time), its cost per iteration, and the time a switch would cost.
//
// 1. NLGS first, on exactly the `nlgs` schedule (error at sweep 1, then every
//    `check_every` sweeps; through body velocities in the time-stepper): a warm-started
//    step that NLGS finishes costs what `nlgs` costs. NLGS keeps going while its measured
//    rate says it will finish within the time spent so far, or within what the best other
//    member took on earlier problems of this run (per contact), whichever is larger.
// 2. Otherwise the members take turns in time slices that double: each slice goes to the
//    member that, from its last measured rate, would finish soonest, except that a member
//    whose time is under a quarter of the total is tried first (so a member that looked
//    bad once gets another chance, with a budget that grows with the solve). A slice
//    starts from the best iterate so far; a member whose slice from the best gained
//    nothing continues its own run from the warm start instead (Newton from NLGS's best
//    can sit in a local minimum of its merit where Newton alone would not).
// 3. The answer is the best iterate of all; the solve ends at the tolerance, at
//    `max_iterations` (all members' iterations together), or when every member had two
//    slices in a row without gain.
// The time a member took to converge is remembered per contact, so in a run of many
// steps the switch from NLGS happens at once where another member was faster before, and
// never where it was not.
#include <algorithm>
#include <array>
#include <chrono>
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
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

enum Member { nlgs_member, newton_member, admm_member, apgd_member, member_count };

/// What auto knows of one member during a solve.
struct MemberState {
  bool available = false;
  double spent = 0;         ///< seconds of this solve
  double rate = -1;         ///< ln(error) gained per second in its last slice; −1: not tried
  int slices = 0;
  int fruitless = 0;        ///< consecutive slices without gain
  bool own_run = false;     ///< continues its own iterate instead of starting from the best
  Eigen::VectorXd own;      ///< its own iterate (own_run)
  double own_err = std::numeric_limits<double>::infinity();
  bool excluded() const { return !available || (slices >= 2 && fruitless >= 2); }
};

class Auto : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target error (DESIGN §1; in a time step normalised by the approaching contacts)").gt(0).fallback(1e-4);
    s.integer("max_iterations", "maximum iterations of all members together (NLGS sweeps, Newton, ADMM and APGD steps)").min(1).fallback(20000);
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
    const Clock::time_point t0 = Clock::now();
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
    m[admm_member].available = direct;
    m[apgd_member].available = !direct;
    // Newton and ADMM follow their own runs from the warm start, as each would alone:
    // started from NLGS's iterate, Newton can crawl for hundreds of steps where alone it
    // converges in tens (measured on spheres-in-a-box at 1e-8: 0.36 s alone, 3.9 s from
    // the best iterate). NLGS and APGD, first-order methods, start from the best.
    for (Member k : {newton_member, admm_member}) {
      m[k].own_run = true;
      m[k].own = r;
    }

    // 1. NLGS on the `nlgs` schedule, while its own rate says it finishes soon enough.
    if (nlgs_sweeps_ > 0) {
      const double before = seconds_since(t0);
      double first_err = 0;
      const double rate = run_nlgs(r, nlgs_sweeps_, 0, t0, true, &first_err);
      if (trace_) std::fprintf(stderr, "auto: first nlgs %.2es best %.2e rate %.2e it %ld\n", seconds_since(t0) - before, best_err_, rate, total_);
      if (best_err_ <= tol_) return finish();
      account(m[nlgs_member], seconds_since(t0) - before, rate);
    } else {
      velocities(r, u);
      keep(r, natural_map_error(P, r, u));
    }
    if (!std::isfinite(best_err_)) return finish();

    // 2. Slices that double, to the member expected to finish first.
    while (best_err_ > tol_ && total_ < max_it_) {
      const double elapsed = seconds_since(t0);
      const int who = next_member(m, elapsed);
      if (who < 0) break;
      MemberState& ms = m[who];
      // The member expected to finish first gets the time spent so far (slices double);
      // a member tried to measure its rate gets a quarter of it.
      const double slice = std::max((who == exploring_ ? 0.25 : 1.0) * elapsed, 1e-5);
      if (ms.own_run && !std::isfinite(ms.own_err)) {  // its start's error, once (hard problems only)
        Eigen::VectorXd v = with_w().W * ms.own + P.q;
        ms.own_err = natural_map_error(P, ms.own, v);
      }
      Eigen::VectorXd x = ms.own_run ? ms.own : best_;
      const double from = ms.own_run ? ms.own_err : best_err_;
      const double t_start = seconds_since(t0);
      double reached = 0;
      const double window_rate = run_member(static_cast<Member>(who), x, slice, &reached);
      const double took = seconds_since(t0) - t_start;
      if (best_err_ <= tol_) {
        remember_other(static_cast<Member>(who), took, nc, true);
        break;
      }
      remember_other(static_cast<Member>(who), took, nc, false);
      const double gain = reached < from ? std::log(from / reached) : 0.0;
      if (trace_) std::fprintf(stderr, "auto: %.4fs member %d slice %.2es took %.2es from %.2e reached %.2e best %.2e own %d it %ld\n",
                               seconds_since(t0), who, slice, took, from, reached, best_err_, int(ms.own_run), total_);
      account(ms, took, who == nlgs_member ? window_rate : gain / std::max(took, 1e-12));
      if (gain < std::log(1 / 0.9)) ++ms.fruitless;
      else ms.fruitless = 0;
      if (ms.own_run) {
        ms.own = x;
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
  /// `max_sweeps`, the deadline (`seconds` > 0), or, for the first stage (`first`), until
  /// its measured rate says another member would finish sooner. Returns its last measured
  /// rate (ln of the error per second; 0 when unknown); `reached`: its lowest error.
  double run_nlgs(Eigen::VectorXd& x, long max_sweeps, double seconds, Clock::time_point t0, bool first, double* reached) {
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
    const Clock::time_point s0 = Clock::now();
    Eigen::VectorXd v;
    struct Check {
      double t, err;
    };
    std::vector<Check> hist;
    double own_best = std::numeric_limits<double>::infinity(), rate = 0;
    *reached = own_best;
    for (long it = 1; it <= max_sweeps && total_ < max_it_; ++it) {
      if (bodies_)
        body_sweeper_.sweep(x, 1.0, order_);
      else
        sweeper_.sweep(P, x);
      ++total_;
      if (it != 1 && it % check_ != 0) continue;
      velocities(x, v);
      const double e = natural_map_error(P, x, v);
      if (!std::isfinite(e)) break;
      keep(x, e);
      own_best = std::min(own_best, e);
      *reached = own_best;
      if (best_err_ <= tol_) return rate;
      const double now = seconds_since(s0);
      hist.push_back({now, own_best});
      if (seconds > 0 && now >= seconds) return rate;
      // The rate over the last window (about 4 checks, at least 2): ln(error) per second.
      const std::size_t h = hist.size();
      if (h < 3) continue;
      const Check& a = hist[h > 5 ? h - 5 : 1];
      const Check& b = hist[h - 1];
      rate = b.t > a.t ? std::log(a.err / b.err) / (b.t - a.t) : 0;
      const double remaining = rate > 0 ? std::log(b.err / tol_) / rate : std::numeric_limits<double>::infinity();
      if (first) {
        // Stay while finishing costs less than what has been spent (a switch could not
        // save more than that) or than another member's remembered time.
        const double total_elapsed = seconds_since(t0);
        const double other = other_per_contact_ * static_cast<double>(nc);
        if (remaining > std::max(total_elapsed, other)) return rate;
      } else if (h >= 6 && !(b.err < 0.9 * hist[h - 6].err)) {
        return rate;  // a later slice that stalls gives its time back
      }
    }
    return rate;
  }

  /// One slice of `who` from x (its iterate on exit), at most `seconds`. `reached`: the
  /// lowest error of the slice; returns NLGS's window rate (0 for the others).
  double run_member(Member who, Eigen::VectorXd& x, double seconds, double* reached) {
    const long budget = std::max<long>(1, max_it_ - total_);
    Eigen::VectorXd v;
    SolverReport s;
    switch (who) {
      case nlgs_member:
        return run_nlgs(x, budget, seconds, Clock::now(), false, reached);
      case newton_member: {
        newton::Options o;
        o.tolerance = tol_;
        o.max_iterations = budget;
        o.max_seconds = seconds;
        s = newton_.solve(with_w(), o, x, v);
        break;
      }
      case admm_member: {
        admm::Options o;
        o.tolerance = tol_;
        o.max_iterations = budget;
        o.max_seconds = seconds;
        s = admm_.solve(with_w(), o, x, v);
        break;
      }
      case apgd_member: {
        apgd::Options o;
        o.tolerance = tol_;
        o.max_iterations = budget;
        o.max_seconds = seconds;
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
  /// had under a quarter of the time. −1 when every member is excluded (two slices in a
  /// row without gain).
  int next_member(const std::array<MemberState, member_count>& m, double elapsed) const {
    int best = -1;
    for (int k = 0; k < member_count; ++k) {
      if (m[k].excluded() || m[k].slices == 0) continue;
      if (best < 0 || m[k].rate > m[best].rate) best = k;
    }
    const double remaining = best >= 0 && m[best].rate > 0 ? std::log(best_err_ / tol_) / m[best].rate
                                                            : std::numeric_limits<double>::infinity();
    exploring_ = -1;
    if (remaining > elapsed) {
      for (int k = 0; k < member_count; ++k)
        if (!m[k].excluded() && m[k].slices == 0) return exploring_ = k;
      int least = -1;
      for (int k = 0; k < member_count; ++k)
        if (!m[k].excluded() && k != best && m[k].spent < 0.2 * elapsed && (least < 0 || m[k].spent < m[least].spent)) least = k;
      if (least >= 0) return exploring_ = least;
    }
    return best;
  }

  /// Seconds per contact the members other than NLGS take (exponential average of the
  /// times to converge; a slice that did not converge is a lower bound). The first NLGS
  /// stage of later solves stays as long as it finishes sooner than that.
  void remember_other(Member who, double seconds, Eigen::Index nc, bool converged) {
    if (who == nlgs_member) return;
    const double per = seconds / static_cast<double>(std::max<Eigen::Index>(nc, 1));
    if (converged)
      other_per_contact_ = other_per_contact_ > 0 ? 0.7 * other_per_contact_ + 0.3 * per : per;
    else
      other_per_contact_ = std::max(other_per_contact_, per);
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
  LocalProblem assembled_;
  bool assembled_ready_ = false;
  std::vector<Eigen::Index> order_;
  // Kept over the solves of a run.
  double other_per_contact_ = 0;
  nlgs::Sweeper sweeper_;
  nlgs::BodySweeper body_sweeper_;
  admm::Admm admm_;
  newton::Newton newton_;
};
MOREAU_REGISTER(Auto, "auto")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_auto")
