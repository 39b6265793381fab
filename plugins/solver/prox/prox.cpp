// `prox`: the proximal point method around an inner solver (Rockafellar; in Siconos as
// fc3d_proximal). Each outer iteration solves the regularised problem
//   u = (W + σ I) r + (q − σ r_k),   r ∈ K_μ, Coulomb law,
// whose fixed point r = r_k is the original problem's solution, and whose matrix is
// positive definite even when W is singular (redundant contacts, hyperstatic stacks): the
// inner NLGS converges faster on it, and the inner Newton's Jacobian is well posed.
// Newton needs little regularisation (σ₀ = 1e-3: its Jacobian only has to be invertible),
// NLGS more (0.1: the regularisation is what speeds it up; measured on the shared FCLib
// problems, docs/solvers.md). σ starts at `sigma` × the mean diagonal of W and follows the error: σ = σ₀ √(err/err₀)
// (at most σ₀), so the steps lengthen as the answer nears (superlinear when W is regular)
// while a rising error, which the natural map can show on the way, does not stall them.
// The best iterate is the one returned.
// Each inner solve stops at a tenth of the current outer error (in absolute terms), so
// early iterations are cheap. `iterations` counts inner sweeps / Newton steps.
// Stopping test: the DESIGN §1 error of the original problem, recomputed from r.
#include <algorithm>
#include <cmath>
#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>

#include "newton_core.hpp"
#include "nlgs_sweep.hpp"

namespace {
using namespace moreau;

class Prox : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum inner iterations in all (NLGS sweeps or Newton steps)").min(1).fallback(20000);
    s.string("inner", "solver of the regularised problems").one_of({"newton", "nlgs"}).fallback("newton");
    s.number("sigma", "initial σ, relative to the mean diagonal of W (0: 1e-3 with newton, 0.1 with nlgs)").min(0).fallback(0.0);
    s.integer("inner_iterations", "maximum iterations of one inner solve").min(1).fallback(200);
    s.integer("max_outer", "maximum proximal (outer) iterations").min(1).fallback(1000);
    return s;
  }
  static constexpr const char* doc = "proximal point: NLGS or Newton on (W + σI) r + q − σ r_k, σ adapted";

  Prox(const Params& p, const BuildContext&)
      : tol_(p.number("tolerance")), max_it_(p.integer("max_iterations")), inner_(p.string("inner")),
        sigma0_(p.number("sigma") > 0 ? p.number("sigma") : (p.string("inner") == "newton" ? 1e-3 : 0.1)), inner_it_(p.integer("inner_iterations")), max_outer_(p.integer("max_outer")) {}

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    const int d = P.dim;
    const Eigen::Index n = d * P.contacts();
    SolverReport rep;
    if (r.size() != n || !r.allFinite()) r = Eigen::VectorXd::Zero(n);
    u = P.W * r + P.q;
    if (n == 0) {
      rep.converged = true;
      return rep;
    }
    double err = natural_map_error(P, r, u);
    double best_err = err;
    Eigen::VectorXd best = r;
    double sigma_start = sigma0_ * std::max(P.W.diagonal().cwiseAbs().mean(), 1e-300);
    const double err_start = err;
    double sigma = sigma_start, last_err = err;
    double built_sigma = -1;
    LocalProblem R;  // the regularised problem; W rebuilt only when σ changes
    R.dim = d;
    R.mu = P.mu;
    R.error_scale = error_denominator(P);  // inner errors in the outer problem's normalisation
    long total = 0;
    for (long outer = 0; outer < max_outer_ && total < max_it_ && best_err > tol_; ++outer) {
      if (sigma != built_sigma) {
        Eigen::SparseMatrix<double, Eigen::RowMajor> I(n, n);
        I.setIdentity();
        R.W = P.W + sigma * I;
        built_sigma = sigma;
        if (inner_ == "nlgs") sweeper_.prepare(R);
      }
      R.q = P.q - sigma * r;
      // Inner target: a tenth of the outer error (both measured with the same denominator).
      const double inner_tol = std::max(0.1 * last_err, 0.1 * tol_);
      total += inner_solve(R, r, inner_tol, std::min<long>(inner_it_, max_it_ - total));
      u = P.W * r + P.q;
      err = natural_map_error(P, r, u);
      // The prox step is taken whether the error fell or not: the natural-map error is not
      // a merit function (it can rise on the way to the answer), and going back to the best
      // iterate would stall there. Only a blow-up goes back, with a larger σ.
      if (!std::isfinite(err) || err > 1e3 * best_err) {
        r = best;
        sigma_start *= 4;
        sigma = sigma_start;
        continue;
      }
      sigma = sigma_start * std::clamp(std::sqrt(err / err_start), 1e-12, 1.0);
      last_err = err;
      if (err < best_err) {
        best_err = err;
        best = r;
      }
    }
    r = best;
    u = P.W * r + P.q;
    rep.iterations = total;
    rep.error = natural_map_error(P, r, u);
    rep.converged = rep.error <= tol_;
    return rep;
  }

 private:
  /// Solves R from r to `tol` (R's own normalisation) in at most `budget` iterations; returns those used.
  long inner_solve(const LocalProblem& R, Eigen::VectorXd& r, double tol, long budget) {
    if (budget <= 0) return 0;
    if (inner_ == "newton") {
      newton::Options o;
      o.tolerance = tol;
      o.max_iterations = budget;
      Eigen::VectorXd v;
      return newton_.solve(R, o, r, v).iterations;
    }
    constexpr long check_every = 5;
    for (long it = 1; it <= budget; ++it) {
      sweeper_.sweep(R, r);
      if (it % check_every == 0 || it == budget) {
        if (natural_map_error(R, r) <= tol) return it;
      }
    }
    return budget;
  }

  double tol_;
  long max_it_;
  std::string inner_;
  double sigma0_;
  long inner_it_, max_outer_;
  nlgs::Sweeper sweeper_;
  newton::Newton newton_;
};
MOREAU_REGISTER(Prox, "prox")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_prox")
