#pragma once
// Accelerated projected gradient (Nesterov; APGD of Mazhar et al. 2015) on the De
// Saxcé-shifted problem  min ½ rᵀWr + (q + s)ᵀr  over r ∈ K, the shift s = μ‖u_T‖ e_n
// recomputed at every step from the extrapolated point y, at the contacts whose iterate x
// is on the cone's boundary or apex (inside it, u = 0 at the answer: no shift needed, and
// with μ ≥ 1 it made the step expansive; apgd_core.cpp, projected_step):
//   g = W y + q + s(y),   x⁺ = P_K(y − (1/L) D⁻¹ g)
// with D diagonal per contact (Options::scaling: a scalar, its mean diagonal of W, or its
// normal entry and its mean tangential one; P_K is the exact projection in D's metric) and L found
// by backtracking on the quadratic bound ½dᵀWd ≤ (L/2) dᵀDd (L doubles; shrinks by 0.9
// after each step). Extrapolation y = x⁺ + β(x⁺ − x) with the Nesterov sequence, restarted
// (y = x⁺) when gᵀ(x⁺ − x) > 0 (O'Donoghue–Candès gradient restart). One product by W per
// step plus one per backtrack. Stopping test: the DESIGN §1 error at x⁺; the best finite
// iterate is returned. Without W (0 × 0) but with its factor, the products go through the
// factor: W x = H (M⁻¹ (Hᵀ x)).
#include <memory>
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>

namespace moreau::apgd {

class Products;  // the products by W of one problem, packed (apgd_core.cpp)

/// The diagonal scaling D of the gradient step, per contact.
enum class Scaling {
  contact,         ///< one scalar: the mean of the contact's diagonal entries of W
  normal_tangent,  ///< diag(W_nn, w_t, …, w_t), w_t the mean of the tangential entries
};

/// Where a run stopped, so that a later call can continue it (`auto` runs APGD in slices).
struct State {
  State();
  ~State();
  State(State&&) noexcept;
  State& operator=(State&&) noexcept;
  Eigen::VectorXd x, y, Wx, Wy;
  double L = 1, theta = 1;
  /// The error at x, as its step measured it (−1: not known, an unmeasured step): a resumed
  /// call starts from it instead of recomputing it.
  double err = -1;
  /// The last call's packed products by W (the factor folded with the inverse masses, the
  /// scaling D), kept for a later call on the same problem (Options::same_problem).
  std::unique_ptr<Products> products;
};

struct Options {
  double tolerance = 1e-6;
  long max_iterations = 10000;
  double shrink = 0.9;   ///< L ← shrink·L after each accepted step (1: never shrinks)
  bool restart = true;   ///< gradient restart of the extrapolation
  /// The error at x⁺ is evaluated at the first step and every `check_every` steps (1: at
  /// every step); an unmeasured x⁺ is not a candidate for the best iterate, and the run
  /// stops at a measured one. The error is a cone projection per contact, about a sixth
  /// of a step: at 10⁴ spheres, 3 gave 1.14× per step for 2 % more steps with the products
  /// of then; with the rigid frames' cheaper products it lost (`auto` takes 1 again).
  long check_every = 1;
  /// D per contact. `normal_tangent` scales the normal and the tangential directions apart
  /// (a sphere's tangential entry, with its rotation, is 3.5 times its normal one, so one
  /// scalar steps the normal 2.7 times shorter than it could); the projection on the cone
  /// in D's metric stays exact (apgd_core.cpp, projected_step).
  Scaling scaling = Scaling::contact;
  /// Work budget in products by W (0: none), checked after each iteration; the work done
  /// is added to *work when given (plugins/solver/work.hpp). Used by `auto`.
  double max_work = 0;
  double* work = nullptr;
  /// When given: the run is saved there on exit, and continued from it when `resume` is
  /// set and it holds a run of this problem's size (the start r is then ignored).
  State* state = nullptr;
  bool resume = false;
  /// The state's packed products are this problem's (a later slice of the same solve in
  /// `auto`): used as they are instead of packed again (at 10⁴ spheres the packing and
  /// the start's product cost about three APGD iterations a slice).
  bool same_problem = false;
  /// The error returned is recomputed from r with a fresh product (true), or, when r is
  /// the last iterate, the one the iteration measured (u from the updated W x, equal to
  /// rounding): for a caller that recomputes its answer's error itself (`auto`).
  bool recompute_error = true;
  /// u = W r + q is wanted on exit. False (with recompute_error false): u is not computed and
  /// the error returned is the one the iteration measured at r, even when r is an earlier
  /// iterate than the last (else a product by W for u): for a caller that uses only r and
  /// the error (`auto`'s slices outside a time step, which would pay that product at the end
  /// of every slice whose last step was not its best).
  bool velocities = true;
  /// A start the caller has already multiplied: W start_r (`start_wr`) and, when ≥ 0, the
  /// error of start_r with u = W start_r + q (`start_error`). Used instead of computing them
  /// again when the start (r projected on the cones) is start_r bit for bit; their work is
  /// counted as when computed, so the counts, and `auto`'s decisions, do not change.
  /// `auto` hands over its start check in a time step given with W (finite elements), where
  /// APGD's start recomputed it (about 2·10³ instructions a solve on
  /// elastic_block_hit_by_spheres_3d).
  const Eigen::VectorXd* start_r = nullptr;
  const Eigen::VectorXd* start_wr = nullptr;
  double start_error = -1;
};

SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u);

/// u = W x + q through the packed products the state keeps, when the caller knows they are
/// P's (a call on P with this state since P was given); false, u untouched, when the state
/// has none for P.
bool velocities(const State& state, const LocalProblem& P, const Eigen::VectorXd& x, Eigen::VectorXd& u);

}  // namespace moreau::apgd
