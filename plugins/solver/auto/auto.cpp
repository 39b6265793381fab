// `auto`: the solver to use when one does not know which. It starts cheap, with NLGS sweeps
// (nlgs_sweep.hpp), which finish easy problems (few contacts, well conditioned) in a few
// sweeps. When the error stops falling fast (stagnation: the best error has not halved over
// the last `stall_sweeps` sweeps), it moves on from the best iterate so far to the
// regularised semismooth Newton method (newton_core.hpp), and when Newton stalls in turn,
// to ADMM (admm_core.hpp), then back to Newton (with another Alart–Curnier parameter), and
// so on until the tolerance or the iteration budget is reached, or four stages in a row
// did not improve the error. Above `direct_max_contacts`, where factorising W costs more
// than many sweeps, APGD and NLGS alternate instead. Every stage starts from the best iterate seen, and the one
// returned is the best; `iterations` counts all of them (sweeps, Newton and ADMM steps).
// Stopping test: the DESIGN §1 error, recomputed from r.
// From the time-stepper (factored W present), the NLGS stage goes through body velocities
// (nlgs_body_sweep.hpp) and W is assembled only if the later stages are needed, so easy
// steps never pay for it.
#include <algorithm>
#include <cmath>
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

class Auto : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum iterations of all stages together (NLGS sweeps, Newton and ADMM steps)").min(1).fallback(20000);
    s.integer("nlgs_sweeps", "maximum NLGS sweeps of the first stage").min(0).fallback(200);
    s.integer("stall_sweeps", "the NLGS stage ends when the best error has not halved over this many sweeps").min(1).fallback(10);
    s.integer("newton_iterations", "maximum iterations of one Newton stage").min(1).fallback(100);
    s.integer("newton_stall", "a Newton stage ends when the best error has not halved over this many iterations").min(1).fallback(20);
    s.integer("admm_iterations", "maximum iterations of one ADMM stage").min(1).fallback(5000);
    s.integer("admm_stall", "an ADMM stage ends when the best error has not halved over this many iterations").min(1).fallback(300);
    s.integer("direct_max_contacts", "above this many contacts, no Newton or ADMM (their sparse LU of W): APGD and NLGS in turn").min(0).fallback(1000);
    s.integer("apgd_iterations", "maximum iterations of one APGD stage (above direct_max_contacts)").min(1).fallback(500);
    return s;
  }
  static constexpr const char* doc = "NLGS sweeps, then regularised Newton and ADMM in turn from the best iterate, until converged";

  Auto(const Params& p, const BuildContext&)
      : tol_(p.number("tolerance")), max_it_(p.integer("max_iterations")), nlgs_sweeps_(p.integer("nlgs_sweeps")),
        stall_sweeps_(p.integer("stall_sweeps")), newton_it_(p.integer("newton_iterations")),
        newton_stall_(p.integer("newton_stall")), admm_it_(p.integer("admm_iterations")), admm_stall_(p.integer("admm_stall")),
        direct_max_contacts_(p.integer("direct_max_contacts")), apgd_it_(p.integer("apgd_iterations")) {}

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
    const bool bodies = P.factor.present();
    if (bodies) body_sweeper_.prepare(P, r);
    auto velocities = [&](const Eigen::VectorXd& x, Eigen::VectorXd& v) {
      if (bodies)
        body_sweeper_.velocities(x, v);
      else
        v = P.W * x + P.q;
    };
    velocities(r, u);
    double best_err = natural_map_error(P, r, u);
    Eigen::VectorXd best = r;
    long total = 0;
    auto finish = [&]() {
      r = best;
      velocities(r, u);
      rep.iterations = total;
      rep.error = natural_map_error(P, r, u);
      rep.converged = rep.error <= tol_;
      return rep;
    };
    auto keep = [&](const Eigen::VectorXd& x, double e) {
      if (e < best_err && x.allFinite()) {
        best_err = e;
        best = x;
      }
    };
    if (best_err <= tol_) return finish();

    // 1. NLGS sweeps from the best iterate, the error checked every few sweeps, until the
    // best error stops halving over `stall_sweeps`. True when converged.
    const long check = std::max<long>(1, std::min<long>(5, stall_sweeps_));
    if (!bodies) sweeper_.prepare(P);
    std::vector<Eigen::Index> given(static_cast<std::size_t>(nc));
    for (Eigen::Index a = 0; a < nc; ++a) given[static_cast<std::size_t>(a)] = a;
    bool first_nlgs = true;
    auto nlgs_stage = [&]() {
      if (!first_nlgs) {
        r = best;
        if (bodies) body_sweeper_.prepare(P, r);  // Δv from the restarting iterate
      }
      first_nlgs = false;
      std::vector<double> hist;  // best error at each check
      for (long it = 1; it <= nlgs_sweeps_ && total < max_it_; ++it) {
        if (bodies)
          body_sweeper_.sweep(r, 1.0, given);
        else
          sweeper_.sweep(P, r);
        ++total;
        if (it % check != 0) continue;
        velocities(r, u);
        const double e = natural_map_error(P, r, u);
        if (!std::isfinite(e)) break;
        keep(r, e);
        if (best_err <= tol_) return true;
        hist.push_back(best_err);
        const long back = stall_sweeps_ / check;
        const auto h = static_cast<long>(hist.size());
        if (h > back && best_err > 0.5 * hist[h - 1 - back]) break;  // stagnation
      }
      return false;
    };
    if (nlgs_stage()) return finish();

    int fruitless = 0;  // consecutive stages that did not improve the best error

    // 2a. Many contacts: no factorisation (Newton's and ADMM's sparse LU of W fill in like
    // a 3D grid's: 0.8 s per Newton step at 3200 sphere contacts, minutes at 10⁴). APGD
    // (a product by W per step, through the factor when W was not given) and NLGS in
    // turn, each from the best iterate.
    if (nc > direct_max_contacts_) {
      bool apgd_next = true;
      while (total < max_it_ && fruitless < 4 && best_err > tol_) {
        const double before = best_err;
        if (apgd_next) {
          Eigen::VectorXd x = best, v;
          apgd::Options o;
          o.tolerance = tol_;
          o.max_iterations = std::min(max_it_ - total, apgd_it_);
          const SolverReport s = apgd::solve(P, o, x, v);
          total += std::max<long>(s.iterations, 1);
          keep(x, s.error);
        } else if (nlgs_stage()) {
          break;
        }
        fruitless = best_err < 0.9 * before ? 0 : fruitless + 1;
        apgd_next = !apgd_next;
      }
      return finish();
    }

    // 2b. Newton and ADMM in turn, each from the best iterate, on W (assembled now if only
    // the factor was given).
    LocalProblem assembled;
    const LocalProblem& Q = P.W.rows() == n || total >= max_it_ ? P : assembled;
    if (&Q == &assembled) {
      assembled.dim = d;
      assembled.W = assemble_w(d, P.factor);
      assembled.q = P.q;
      assembled.mu = P.mu;
    }
    bool newton_next = true;
    int newton_stages = 0;
    while (total < max_it_ && fruitless < 4) {
      Eigen::VectorXd x = best, v;
      const long budget = std::min(max_it_ - total, newton_next ? newton_it_ : admm_it_);
      SolverReport s;
      if (newton_next) {
        newton::Options o;
        o.tolerance = tol_;
        o.max_iterations = budget;
        o.stall_window = newton_stall_;
        // Each Newton stage with another Alart–Curnier parameter: where one stalls (a
        // local minimum of its merit), another usually does not.
        static constexpr double scales[] = {3.0, 10.0, 1.0, 30.0, 0.3};
        o.rho_scale = scales[newton_stages++ % 5];
        s = newton_.solve(Q, o, x, v);
      } else {
        admm::Options o;
        o.tolerance = tol_;
        o.max_iterations = budget;
        o.stall_window = admm_stall_;
        s = admm_.solve(Q, o, x, v);
      }
      total += std::max<long>(s.iterations, 1);
      const double before = best_err;
      keep(x, s.error);
      if (best_err <= tol_) break;
      fruitless = best_err < 0.9 * before ? 0 : fruitless + 1;
      newton_next = !newton_next;
    }
    return finish();
  }

 private:
  double tol_;
  long max_it_, nlgs_sweeps_, stall_sweeps_, newton_it_, newton_stall_, admm_it_, admm_stall_, direct_max_contacts_, apgd_it_;
  nlgs::Sweeper sweeper_;
  nlgs::BodySweeper body_sweeper_;
  admm::Admm admm_;
  newton::Newton newton_;
};
MOREAU_REGISTER(Auto, "auto")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_auto")
