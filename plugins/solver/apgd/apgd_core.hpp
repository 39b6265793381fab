#pragma once
// Accelerated projected gradient (Nesterov; APGD of Mazhar et al. 2015) on the De
// Saxcé-shifted problem  min ½ rᵀWr + (q + s)ᵀr  over r ∈ K, the shift s = μ‖u_T‖ e_n
// recomputed at every step from the extrapolated point y:
//   g = W y + q + s(y),   x⁺ = P_K(y − (1/L) D⁻¹ g)
// with D a scalar per contact (its mean diagonal of W, which keeps P_K exact) and L found
// by backtracking on the quadratic bound ½dᵀWd ≤ (L/2) dᵀDd (L doubles; shrinks by 0.9
// after each step). Extrapolation y = x⁺ + β(x⁺ − x) with the Nesterov sequence, restarted
// (y = x⁺) when gᵀ(x⁺ − x) > 0 (O'Donoghue–Candès gradient restart). One product by W per
// step plus one per backtrack. Stopping test: the DESIGN §1 error at x⁺; the best finite
// iterate is returned. Without W (0 × 0) but with its factor, the products go through the
// factor: W x = H (M⁻¹ (Hᵀ x)).
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>

namespace moreau::apgd {

/// Where a run stopped, so that a later call can continue it (`auto` runs APGD in slices).
struct State {
  Eigen::VectorXd x, y, Wx, Wy;
  double L = 1, theta = 1;
};

struct Options {
  double tolerance = 1e-6;
  long max_iterations = 10000;
  double shrink = 0.9;   ///< L ← shrink·L after each accepted step (1: never shrinks)
  bool restart = true;   ///< gradient restart of the extrapolation
  /// Work budget in products by W (0: none), checked after each iteration; the work done
  /// is added to *work when given (plugins/solver/work.hpp). Used by `auto`.
  double max_work = 0;
  double* work = nullptr;
  /// When given: the run is saved there on exit, and continued from it when `resume` is
  /// set and it holds a run of this problem's size (the start r is then ignored).
  State* state = nullptr;
  bool resume = false;
};

SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u);

}  // namespace moreau::apgd
