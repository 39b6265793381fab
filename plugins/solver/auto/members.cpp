// One slice of a member method, each through its own core (nlgs_sweep.hpp,
// nlgs_body_sweep.hpp, apgd_core.hpp, newton_core.hpp, admm_core.hpp) counting its work into
// the solve's: run_member() for every member, run_nlgs() for NLGS's sweeps and its checks,
// the options of an APGD slice, W assembled for Newton and ADMM (with_w()) and the estimate
// of a Newton step that the rule weighs before one has run.
#include <moreau/contact_error.hpp>
#include <moreau/factor_matrix.hpp>

#include "auto.hpp"

namespace moreau::auto_solver {

/// One slice of `who` from x (its iterate on exit), at most `units` of work. `reached`: the
/// lowest error of the slice; returns NLGS's window rate (0 for the others).
double Auto::run_member(Member who, Eigen::VectorXd& x, double units, long budget, double* reached) {
  Eigen::VectorXd& v = member_u_;  // (kept over the solves: no allocation at each slice)
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
      work_ += costs_.newton_call * static_cast<double>(s.iterations);  // work.hpp: its extra per call
      break;
    }
    case admm_member: {
      admm::Options o;
      limits(o);
      o.resume = admm_slices_++ > 0;  // its own run goes on where its last slice stopped
      s = admm_.solve(with_w(), o, x, v);
      work_ += costs_.admm_call * static_cast<double>(s.iterations);  // work.hpp: its extra per call (0 but given with W in a time step)
      break;
    }
    case apgd_member: {
      // Its packed products are kept over the slices of a solve; its run goes on while it
      // holds the best iterate.
      const bool later = apgd_slices_++ > 0;
      apgd::Options a = apgd_options(budget, units, apgd_state_, later, later && best_by_ == apgd_member);
      if (!later && start_wr_ok_) {  // the start check's W r and error, used when x is the start
        a.start_r = &start_;
        a.start_wr = &start_wr_;
        a.start_error = start_err_;
      }
      s = apgd::solve(*P_, a, x, v);  // through the factor when W was not given
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
    best_u_.swap(v);  // (v is scratch: its values are not used after the slice)
    best_u_ok_ = true;
  }
  *reached = s.error;
  return 0;
}

/// NLGS sweeps from x (error at the first sweep, then every check_): until converged,
/// `max_sweeps`, the work budget (`units` > 0), or, for the first stage (`first`), until
/// its measured rate says another member would finish sooner. Returns its last measured
/// rate (ln of the error per unit of work; 0 when unknown); `reached`: its lowest error.
double Auto::run_nlgs(Eigen::VectorXd& x, long max_sweeps, double units, bool first, double* reached) {
  const LocalProblem& P = *P_;
  prepare_nlgs();
  if (bodies_ && !records_packed_) {  // packed when NLGS first runs (records beyond the caches)
    body_sweeper_.pack(P, x);
    records_packed_ = true;
  } else if (bodies_ && !first) {
    body_sweeper_.reset_velocities(x);  // the first stage starts where records() set Δv
  }
  const double w0 = work_;
  Eigen::VectorXd& v = member_u_;  // (kept over the solves: no allocation at each run)
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

/// APGD's options for a slice of one of auto's APGD runs (the rule's, or the floor's own
/// run): its caps, the solve's work counter, and the error taken from the iteration
/// (finish() recomputes the answer's).
apgd::Options Auto::apgd_options(long max_iterations, double units, apgd::State& state, bool same_problem, bool resume) {
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

/// The problem with W, assembled from the factor the first time a member needs it.
const LocalProblem& Auto::with_w() {
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

/// The work of one Newton step on this problem: remembered, or from its LU's fill: nnz(W)
/// for each factor (L + U hold 0.8 to 2.6 nnz(W) on the corpus, but 12 on wet_pile_3d's
/// 650 contacts), or the fill a symbolic analysis predicts where that raises the step by
/// over half (fill_known_, refine_fill(): 3D, a factorisation about to be paid for).
double Auto::newton_step_estimate() const {
  if (newton_step_ > 0) return newton_step_;  // measured in this solve
  if (memory_[newton_start_member].step > 0) return memory_[newton_start_member].step * nc_;
  const double nnz = bodies_ && P_->W.rows() == 0 ? 12.0 * P_->dim * P_->dim * nc_ : static_cast<double>(P_->W.nonZeros());
  const double n = P_->dim * nc_;
  const double fill_l = fill_known_ ? fill_.nnz_l : nnz, fill_u = fill_known_ ? fill_.nnz_u : nnz;
  const double estimate = WorkCosts::newton_step(nnz, n, fill_l, fill_u, costs_.product) + costs_.newton_call;
  // In a time step, ADMM's step remembered from earlier solves (its first one factorises the
  // same W) bounds it from below: a 3D LU fills in far beyond W's size (wet_pile_3d: ADMM's
  // first step 1.1e7 units, Newton's 3e7, the estimate from the size a few 10⁶).
  return bodies_ ? std::max(estimate, memory_[admm_member].step * nc_) : estimate;
}

/// Before the first factorisation of a solve given with W whose Newton step is estimated
/// from W's size: Newton's LU fill predicted by a symbolic analysis (lu_fill.hpp; counted,
/// 3–15 % of a step), and whether the estimate grew by over half. The slice that
/// would have paid the factorisation is then not taken and the rule decides again on the
/// new estimate (the floor's Newton slice on wet_pile_3d step 100: an estimate of 3.2·10⁶
/// units from W's size for a step of 2.94·10⁷, predicted 2.1·10⁷). Done only there: on
/// problems no factorisation is paid for, it would cost as much as tens of NLGS sweeps.
/// Only in 3D: in 2D (contact networks close to planar graphs, whose fill grows as n log n)
/// L + U held at most 2.6 nnz(W) on the corpus (up to 507 contacts), and the analysis
/// cost the pairs solved in a few factorisations up to 9 % (polygons step 400 warm at
/// 1e-4: 4.10 → 4.46 × NLGS's work). The prediction replaces W's size only when it raises
/// the step by over half: used whenever known, the small changes both ways moved the
/// floor's Newton and ADMM slices (guarantee study: dense disks μ 0.3 step 600 at 1e-8
/// 4.24 → 4.74, box tower step 100 warm at 1e-4 4.20 → 5.13 where L + U is 1.3 nnz(W)).
bool Auto::refine_fill(const std::array<MemberState, member_count>& m) {
  if (fill_analysed_ || P_->dim != 3 || bodies_ || P_->W.rows() == 0 || newton_step_ > 0 ||
      memory_[newton_start_member].step > 0)
    return false;
  for (int k : {newton_start_member, newton_member, admm_member})
    if (m[k].per_iteration > 0) return false;
  const double before = newton_step_estimate(), n = static_cast<double>(P_->W.rows());
  // Not where even a dense LU would not raise it by half (a few contacts).
  if (WorkCosts::newton_step(static_cast<double>(P_->W.nonZeros()), n, n * (n + 1) / 2, n * (n + 1) / 2, costs_.product) +
          costs_.newton_call <= 1.5 * before)
    return false;
  fill_analysed_ = true;
  fill_ = predicted_lu_fill(P_->W, P_->dim);
  work_ += fill_.work;
  fill_known_ = true;
  const double after = newton_step_estimate();
  fill_known_ = after > 1.5 * before;
  if (trace_)
    std::fprintf(stderr, "auto: fill predicted, L %.3g U %.3g (nnz W %ld), work %.3g, Newton step %.3g -> %.3g%s\n", fill_.nnz_l,
                 fill_.nnz_u, static_cast<long>(P_->W.nonZeros()), fill_.work, before, after, fill_known_ ? "" : " (not used)");
  return fill_known_;
}

}  // namespace moreau::auto_solver
