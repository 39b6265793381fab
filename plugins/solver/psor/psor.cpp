// `psor`: projected successive over-relaxation on the Coulomb cone (psor_core.hpp): one
// projected step per contact and sweep, no one-contact solve. Stopping test: the DESIGN §1
// error, recomputed from r.
#include <moreau/solver.hpp>

#include "psor_core.hpp"

namespace {
using namespace moreau;

class PsorSolver : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum sweeps").min(1).fallback(10000);
    s.number("relaxation", "relaxation factor omega of the projected step omega / W_nn (1 can cycle on real problems)").gt(0).lt(2).fallback(0.5);
    s.integer("check_every", "sweeps between two evaluations of the error (each costs about one sweep)").min(1).fallback(5);
    return s;
  }
  static constexpr const char* doc = "projected SOR: one projected step per contact and sweep";

  PsorSolver(const Params& p, const BuildContext&) {
    o_.tolerance = p.number("tolerance");
    o_.max_iterations = p.integer("max_iterations");
    o_.relaxation = p.number("relaxation");
    o_.check_every = p.integer("check_every");
  }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    return psor::solve(P, o_, r, u);
  }

 private:
  psor::Options o_;
};
MOREAU_REGISTER(PsorSolver, "psor")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_psor")
