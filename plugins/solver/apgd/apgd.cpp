// `apgd`: Nesterov-accelerated projected gradient with backtracking on the Lipschitz
// estimate and gradient restart, on the De Saxcé-shifted problem (apgd_core.hpp).
// Stopping test: the DESIGN §1 error, recomputed from r.
#include <moreau/solver.hpp>

#include "../work.hpp"
#include "apgd_core.hpp"

namespace {
using namespace moreau;

class ApgdSolver : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum gradient steps").min(1).fallback(10000);
    s.number("shrink", "the Lipschitz estimate is multiplied by this after each step (1: never shrinks)").gt(0).max(1).fallback(0.9);
    s.boolean("restart", "restart the extrapolation when a step goes uphill").fallback(true);
    s.integer("check_every", "steps between two evaluations of the error (the first step is always measured)").min(1).fallback(1);
    s.string("scaling", "diagonal scaling of the step per contact: \"contact\" (one scalar, the mean of its diagonal of W) or "
                        "\"normal_tangent\" (its normal diagonal entry and the mean of its tangential ones)")
        .one_of({"contact", "normal_tangent"})
        .fallback("contact");
    return s;
  }
  static constexpr const char* doc = "accelerated projected gradient with adaptive step and restart (De Saxce shift)";

  ApgdSolver(const Params& p, const BuildContext&) {
    o_.tolerance = p.number("tolerance");
    o_.max_iterations = p.integer("max_iterations");
    o_.shrink = p.number("shrink");
    o_.restart = p.boolean("restart");
    o_.check_every = p.integer("check_every");
    o_.scaling = p.string("scaling") == "normal_tangent" ? apgd::Scaling::normal_tangent : apgd::Scaling::contact;
  }

  /// From the time-stepper it multiplies through the factor W = H M⁻¹ Hᵀ: W is not built.
  bool reads_matrix_with_factor() const override { return false; }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    o_.state = &kept_;  // not resumed (o_.resume is false): only its arrays' memory is used again
    return counted(o_, [&] { return apgd::solve(P, o_, r, u); });  // work counted as inside `auto`
  }

 private:
  apgd::Options o_;
  /// The last solve's run and packed products: a time step's solve packs its problem into
  /// their arrays instead of fresh ones (at 10⁴ spheres H̃ is 9 MB).
  apgd::State kept_;
};
MOREAU_REGISTER(ApgdSolver, "apgd")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_apgd")
