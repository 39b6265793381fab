// `newton`: semismooth Newton on the Alart–Curnier function with a sparse LU of the
// regularised generalized Jacobian and a non-monotone line search (newton_core.hpp). Quadratic near
// the solution; best started close to it (the `auto` solver does). Stopping test: the
// DESIGN §1 error, recomputed from r.
#include <moreau/solver.hpp>

#include "../work.hpp"
#include "newton_core.hpp"

namespace {
using namespace moreau;

class NewtonSolver : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum Newton iterations").min(1).fallback(200);
    s.number("rho_scale", "Alart-Curnier parameters rho = rho_scale / (diagonal of the contact's block of W)").gt(0).fallback(3.0);
    s.integer("nonmonotone", "the line search compares with the largest merit of this many last iterates (1: monotone)").min(1).fallback(5);
    s.integer("max_backtracks", "step halvings before the Newton direction counts as failed").min(0).fallback(20);
    s.number("min_regularisation", "lower bound of lambda in (J + lambda I) d = -Phi (lambda = |Phi|/|r| clamped)").min(0).fallback(1e-8);
    s.number("max_regularisation", "upper bound of lambda").gt(0).fallback(1e-2);
    s.integer("fallback_steps", "projected steps taken when the Newton direction fails").min(1).fallback(5);
    return s;
  }
  static constexpr const char* doc = "semismooth Newton on the Alart-Curnier function, sparse LU, non-monotone line search";

  NewtonSolver(const Params& p, const BuildContext&) {
    o_.tolerance = p.number("tolerance");
    o_.max_iterations = p.integer("max_iterations");
    o_.rho_scale = p.number("rho_scale");
    o_.nonmonotone = static_cast<int>(p.integer("nonmonotone"));
    o_.max_backtracks = static_cast<int>(p.integer("max_backtracks"));
    o_.min_regularisation = p.number("min_regularisation");
    o_.max_regularisation = p.number("max_regularisation");
    o_.fallback_steps = static_cast<int>(p.integer("fallback_steps"));
  }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    return counted(o_, [&] { return newton_.solve(P, o_, r, u); });  // work counted as inside `auto`
  }

 private:
  newton::Options o_;
  newton::Newton newton_;
};
MOREAU_REGISTER(NewtonSolver, "newton")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_newton")
