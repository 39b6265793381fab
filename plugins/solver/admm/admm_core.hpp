#pragma once
// ADMM for the local frictional contact problem (Acary, Brémond, Huber 2018; Siconos
// fc3d_admm). With the De Saxcé shift s = μ‖u_T‖ e_n frozen, the problem is the convex
// program  min ½ rᵀWr + (q + s)ᵀr  over r ∈ K; ADMM splits r = z with z ∈ K:
//   s ← μ‖(W r + q)_T‖ e_n
//   r ← (W + ρD)⁻¹ (ρD (ẑ − ξ̂) − q − s)           (one factorisation per value of ρ)
//   z ← P_K(r + ξ̂),   ξ ← ξ̂ + r − z
//   ẑ, ξ̂ ← Nesterov extrapolation of z, ξ while the combined residual decreases,
//            otherwise a restart from the previous iterate (Goldstein et al. 2014)
// D is a scalar per contact (the mean of its diagonal block of W), which keeps the
// projection on K exact and makes the penalty insensitive to mass ratios. ρ adapts by
// residual balancing (primal ‖r − z‖ against dual ρ‖ẑ − z‖, both in the D^½-scaled
// variables). W + ρD is factorised by a sparse LDLᵀ when W is symmetric, by a sparse LU
// otherwise (real problem files are not always exactly symmetric: Capsules is off by 4e-4). The iterate returned is z (in K); its DESIGN §1 error is the
// stopping test.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>

namespace moreau::admm {

struct Options {
  double tolerance = 1e-6;
  long max_iterations = 10000;
  double rho = 0;                ///< initial penalty relative to D; 0: 0.03 ‖D^-½ W D^-½‖∞
  bool adaptive = true;          ///< residual balancing on ρ
  double balance = 5;            ///< ρ changes when one residual exceeds `balance` times the other
  double factor = 2;             ///< ρ is multiplied or divided by this
  bool acceleration = true;      ///< Nesterov extrapolation with restart
  double restart = 0.999;        ///< extrapolate while the residual falls below this fraction of the last
  /// Stop early (not converged) when the best error has not fallen below `stall_factor`
  /// times its value of `stall_window` iterations before (0: never). Used by `auto`.
  long stall_window = 0;
  double stall_factor = 0.5;
  /// Work budget in products by W (0: none), checked after each iteration; the work done
  /// is added to *work when given (plugins/solver/work.hpp). Used by `auto`.
  double max_work = 0;
  double* work = nullptr;
  /// Continue the last solve's run (same problem): its iterates, penalty and extrapolation,
  /// instead of starting from r. Used by `auto`, which runs ADMM in slices.
  bool resume = false;
};

class Admm {
 public:
  /// `r`: warm start on entry (resized and zeroed if its size is wrong), on exit the best
  /// finite iterate seen; `u` = W r + q. error = natural-map error of the returned r.
  SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u);
  /// Number of factorisations done by the last solve (ρ changes + 1).
  long factorisations() const { return factorisations_; }

 private:
  bool factorise(double rho);
  void solve_linear(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  Eigen::SparseMatrix<double> W_, D_;
  Eigen::VectorXd weights_;  ///< D's diagonal (a scalar per contact)
  bool symmetric_ = true;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
  bool analysed_ = false;
  long factorisations_ = 0;
  double factorisation_units_ = 0;  ///< work of the factorisations not yet counted
  double solve_units_ = 0;          ///< work of one solve with the current factor
  struct State {
    Eigen::VectorXd z, zk, zh, xi, xik, xih, x;
    double rho = 0, tau = 1, e = 0;
  } state_;  ///< where the last solve stopped (Options::resume)
};

}  // namespace moreau::admm
