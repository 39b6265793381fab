#pragma once
// Semismooth Newton on the Alart–Curnier formulation of the local problem (Alart, Curnier
// 1991; Siconos fc3d_nonsmooth_Newton_AlartCurnier). For each contact, with u = W r + q,
//   Φ_n = r_n − max(0, r_n − ρ_n u_n)
//   Φ_T = r_T − P_D(μ max(0, r_n − ρ_n u_n)) (r_T − ρ_t u_T)       (D(R): the disc of radius R)
// Φ(r) = 0 is the Coulomb law. An element of the generalized Jacobian is J = A + B W (A, B
// block diagonal); the direction solves (J + λI) d = −Φ by a sparse LU, with λ = ‖Φ‖/‖r‖
// clamped to [λ_min, λ_max] (W is often singular, and J with it), and the step length
// comes from a non-monotone Armijo line search on ½‖Φ‖². When the line search fails, λ
// grows (×100, twice); when it still fails, a few projected steps r ← P_K(r − D⁻¹ ũ).
// ρ_n, ρ_t are per contact, the inverses of the diagonal of the contact's block of W.
// Stopping test: the DESIGN §1 error (natural map), recomputed from r; the best finite
// iterate is the one returned.
#include <deque>
#include <Eigen/SparseLU>
#include <moreau/contact_problem.hpp>
#include <moreau/solver.hpp>

namespace moreau::newton {

struct Options {
  double tolerance = 1e-6;
  long max_iterations = 100;
  double rho_scale = 3.0;     ///< ρ = rho_scale / diagonal of W
  int nonmonotone = 5;        ///< the line search compares with the largest merit of the last few iterates
  int max_backtracks = 20;    ///< step halvings before the direction counts as failed
  double min_regularisation = 1e-8;  ///< λ of (J + λI) d = −Φ is ‖Φ‖/‖r‖ clamped to these bounds
  double max_regularisation = 1e-2;
  int fallback_steps = 5;     ///< projected steps taken when the direction fails
  /// Stop early (not converged) when the best error has not fallen below `stall_factor`
  /// times its value of `stall_window` iterations before (0: never). Used by `auto`.
  long stall_window = 0;
  double stall_factor = 0.5;
  /// Work budget in products by W (0: none), checked after each iteration; the work done
  /// is added to *work when given (plugins/solver/work.hpp). Used by `auto`.
  double max_work = 0;
  double* work = nullptr;
  /// When given, receives the last iterate (r receives the best): `auto` resumes a run from it.
  Eigen::VectorXd* last = nullptr;
  /// When given, the non-monotone line search's recent merits, kept across calls: `auto`'s
  /// slices of one run then step as one uninterrupted run would (restarted with an empty
  /// memory, a resumed run takes monotone steps and can crawl).
  std::deque<double>* merits = nullptr;
};

class Newton {
 public:
  /// `r`: warm start on entry (resized and zeroed if its size is wrong), on exit the best
  /// finite iterate seen; `u` = W r + q. error = natural-map error of the returned r.
  SolverReport solve(const LocalProblem& P, const Options& o, Eigen::VectorXd& r, Eigen::VectorXd& u);
  /// The last factorisation's entries (SparseLU's nnzL() + nnzU()); 0 before one.
  double factor_entries() const { return analysed_ ? static_cast<double>(lu_.nnzL() + lu_.nnzU()) : 0.0; }

 private:
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
  bool analysed_ = false;
};

}  // namespace moreau::newton
