// `nlgs`: non-linear Gauss–Seidel over contacts (Moreau, Jean; LMGC90's default). Each
// sweep solves every contact's one-contact Coulomb problem (by default exactly,
// local_coulomb.hpp; or by one of the iterative local solvers of local_solvers.hpp) with the
// others' impulses frozen (nlgs_sweep.hpp). The sweep's hot data is packed per
// contact: the diagonal blocks of W, contiguous; the off-diagonal part is read row by row from W.
// With the time-stepper's factored W (`exchange`), contacts see each other through body
// velocities instead (nlgs_body_sweep.hpp), a fixed cost per contact.
// Stopping test: the DESIGN §1 error, recomputed from r.
#include <algorithm>
#include <moreau/contact_error.hpp>
#include <moreau/solver.hpp>
#include <numeric>
#include <random>

#include "../work.hpp"
#include "nlgs_body_sweep.hpp"
#include "nlgs_sweep.hpp"
#include "sweep_order.hpp"

namespace {
using namespace moreau;

class Nlgs : public Solver {
 public:
  static Schema schema() {
    Schema s;
    s.number("tolerance", "target DESIGN §1 error").gt(0).fallback(1e-6);
    s.integer("max_iterations", "maximum sweeps").min(1).fallback(1000);
    s.number("relaxation", "relaxation factor omega").gt(0).lt(2).fallback(1.0);
    s.string("ordering", "contact order in a sweep: \"fixed_last\" (the given order with the contacts against fixed bodies "
                         "last; as given for FCLib files), \"given\", \"reverse\", \"shuffle\" (seeded)")
        .one_of({"fixed_last", "given", "reverse", "shuffle"})
        .fallback("fixed_last");
    s.integer("seed", "seed of the shuffled order").min(0).fallback(1);
    s.integer("check_every", "sweeps between two evaluations of the error (each costs about one sweep)").min(1).fallback(5);
    s.string("exchange", "how contacts see each other: through W's blocks (\"w\"), through body velocities "
                         "(\"bodies\", needs the time-stepper's W = H M⁻¹ Hᵀ), or \"auto\": bodies when available")
        .one_of({"auto", "w", "bodies"})
        .fallback("auto");
    s.string("local_solver", "one-contact solver: \"exact\" (case enumeration), \"projection\" (projection on the cone "
                             "iterated to convergence), \"desaxce\" (De Saxcé's prediction/correction), "
                             "\"alart_curnier\" (local semismooth Newton)")
        .one_of(nlgs::local_method_names())
        .fallback("exact");
    s.integer("local_iterations", "steps per contact visit of the iterative local solvers (0: projection 100, desaxce 1, "
                                  "alart_curnier 20)").min(0).fallback(0);
    s.number("local_tolerance", "relative change (projection) or Alart–Curnier residual that ends a contact visit")
        .gt(0).fallback(1e-14);
    return s;
  }
  static constexpr const char* doc = "non-linear Gauss-Seidel over contacts (exact or iterative one-contact Coulomb solves)";

  Nlgs(const Params& p, const BuildContext&)
      : tol_(p.number("tolerance")), max_it_(p.integer("max_iterations")), omega_(p.number("relaxation")),
        ordering_(p.string("ordering")), seed_(static_cast<unsigned>(p.integer("seed"))),
        check_every_(p.integer("check_every")), exchange_(p.string("exchange")) {
    nlgs::LocalOptions local;
    local.method = nlgs::local_method_named(p.string("local_solver"));
    local.iterations = static_cast<int>(p.integer("local_iterations"));
    local.tolerance = p.number("local_tolerance");
    sweeper_.set_local(local);
    body_sweeper_.set_local(local);
  }

  bool reads_matrix_with_factor() const override { return exchange_ == "w"; }

  SolverReport solve(const LocalProblem& P, Eigen::VectorXd& r, Eigen::VectorXd& u) override {
    const int d = P.dim;
    const Eigen::Index nc = P.contacts();
    SolverReport rep;
    if (r.size() != d * nc) r = Eigen::VectorXd::Zero(d * nc);
    if (nc == 0) {
      u = P.q;
      rep.converged = true;
      return rep;
    }
    const bool bodies = exchange_ == "bodies" || (exchange_ == "auto" && P.factor.present());
    if (bodies)
      body_sweeper_.prepare(P, r);
    else
      sweeper_.prepare(P);
    order_.resize(nc);
    std::iota(order_.begin(), order_.end(), 0);
    if (ordering_ == "fixed_last") nlgs::fixed_last_order(P, order_);
    if (ordering_ == "reverse") std::reverse(order_.begin(), order_.end());
    // Counted work (plugins/solver/work.hpp), as `auto` counts its NLGS sweeps and checks.
    WorkCosts cost = WorkCosts::of(P, bodies);
    if (bodies)
      cost.sweep = WorkCosts::body_sweep(P, static_cast<double>(body_sweeper_.record_size()), body_sweeper_.dense_inverse_mass());
    std::mt19937 rng(seed_);
    for (long it = 1; it <= max_it_; ++it) {
      if (ordering_ == "shuffle") std::shuffle(order_.begin(), order_.end(), rng);
      if (bodies)
        body_sweeper_.sweep(r, omega_, order_);
      else
        sweeper_.sweep(P, r, omega_, order_);
      rep.iterations = it;
      rep.work += cost.sweep;
      if (it != 1 && it % check_every_ != 0 && it != max_it_) continue;
      rep.work += cost.product + cost.error;
      if (bodies)
        body_sweeper_.velocities(r, u);
      else
        u = P.W * r + P.q;
      rep.error = natural_map_error(P, r, u);
      if (rep.error <= tol_) {
        rep.converged = true;
        return rep;
      }
    }
    return rep;
  }

 private:
  double tol_;
  long max_it_;
  double omega_;
  std::string ordering_;
  unsigned seed_;
  long check_every_;
  std::string exchange_;
  nlgs::Sweeper sweeper_;
  nlgs::BodySweeper body_sweeper_;
  std::vector<Eigen::Index> order_;
};
MOREAU_REGISTER(Nlgs, "nlgs")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_solver_nlgs")
