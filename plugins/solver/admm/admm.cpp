// `admm`: the alternating direction method of multipliers on the De Saxcé-shifted local
// problem (admm_core.hpp), with one sparse LDLᵀ of W + ρD per value of the penalty and
// residual balancing on ρ. Stopping test: the DESIGN §1 error, recomputed from r.
#include <moreau/solver.hpp>

#include "../work.hpp"
#include "admm_core.hpp"

namespace {
using namespace moreau;

class AdmmSolver : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum ADMM iterations").min(1).fallback(10000);
    s.number("rho", "initial penalty, relative to each contact's mean diagonal of W (0: automatic, 0.03 times the largest scaled row sum of |W|)").min(0).fallback(0.0);
    s.boolean("adaptive", "adapt the penalty by residual balancing (refactorises W + rho D on each change)").fallback(true);
    s.number("balance", "the penalty changes when one residual exceeds this many times the other").gt(1).fallback(5.0);
    s.number("factor", "factor by which the penalty grows or shrinks").gt(1).fallback(2.0);
    s.boolean("acceleration", "Nesterov extrapolation of the iterates, restarted when the residual grows").fallback(true);
    s.number("restart", "extrapolate while the residual is below this fraction of the previous one").gt(0).max(1).fallback(0.999);
    return s;
  }
  static constexpr const char* doc = "ADMM with De Saxce shift, sparse LDLT of W + rho D and adaptive penalty";

  AdmmSolver(const Params& p, const BuildContext&) {
    o_.tolerance = p.number("tolerance");
    o_.max_iterations = p.integer("max_iterations");
    o_.rho = p.number("rho");
    o_.adaptive = p.boolean("adaptive");
    o_.balance = p.number("balance");
    o_.factor = p.number("factor");
    o_.acceleration = p.boolean("acceleration");
    o_.restart = p.number("restart");
  }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    return counted(o_, [&] { return admm_.solve(P, o_, r, u); });  // work counted as inside `auto`
  }

 private:
  admm::Options o_;
  admm::Admm admm_;
};
MOREAU_REGISTER(AdmmSolver, "admm")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_admm")
