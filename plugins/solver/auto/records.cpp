// NLGS's body records in a time step (nlgs_body_sweep.hpp): their layout, their packing only
// when NLGS runs or their product is due, and NLGS's sweep cost through them (work.hpp); and
// velocities(), u = W x + q by the cheapest way available in the solve (the records, APGD's
// packed product, the factor, or W).
#include <moreau/factor_matrix.hpp>

#include "auto.hpp"

namespace moreau::auto_solver {

/// u = W x + q, through the bodies when only the factor was given: by NLGS's records
/// when packed, else by APGD's packed product when APGD ran in this solve, else through
/// the factor.
void Auto::velocities(const Eigen::VectorXd& x, Eigen::VectorXd& v) {
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
void Auto::records(const LocalProblem& P, bool pack) {
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
void Auto::pack_records(const Eigen::VectorXd& x) {
  lay_out_records();
  body_sweeper_.pack(*P_, x);
  records_packed_ = true;
}

/// NLGS's sweep cost (costs_.sweep), through the body records: their layout, once per solve
/// and only when NLGS may run or be weighed (a solve that its remembered APGD finishes
/// never needs it: the layout's per-body isotropy check was 2.4·10³ instructions of such a
/// solve's 3.7·10⁴ on cannonball_3d). Through W's rows of() has it already.
void Auto::sweep_cost() {
  if (sweep_costed_ || !bodies_) return;
  sweep_costed_ = true;
  lay_out_records();
  const double record = static_cast<double>(body_sweeper_.record_size());
  // memory-bound beyond the caches; records with M⁻¹Hᵀ blocks count more (work.hpp)
  costs_.sweep = WorkCosts::body_sweep(*P_, record, body_sweeper_.dense_inverse_mass());
}

/// What NLGS needs before its first sweep of a solve: its cost, its order, W's rows.
void Auto::prepare_nlgs() {
  if (nlgs_ready_) return;
  nlgs_ready_ = true;
  sweep_cost();
  if (!bodies_) sweeper_.prepare(*P_);
  nlgs::fixed_last_order(*P_, order_);
}

/// NLGS's record layout for this solve (once) and whether its records fit.
void Auto::lay_out_records() {
  if (records_laid_out_) return;
  body_sweeper_.layout(*P_);
  records_fit_ = records_would_fit(static_cast<double>(body_sweeper_.record_size()));
  records_laid_out_ = true;
}

}  // namespace moreau::auto_solver
