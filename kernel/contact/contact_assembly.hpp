#pragma once
// The local contact problem u = W r + q built from the modelizations' pieces (DESIGN §5,
// docs/architecture.md), never knowing what kind of body is behind a contact:
//  - H: for each contact side, the body's modelization gives the rows of H over the
//    unknowns of the nodes that support the point (Modelization::contact_jacobian): one
//    node, or a mesh facet's nodes with their interpolation weights;
//  - LHS⁻¹: the body's integrator applies it (Integrator::apply_inverse), or gives it as one
//    k × k block (compact_inverse: rigid bodies);
//  - W = H LHS⁻¹ Hᵀ, summed body by body: contacts on one deformable body are coupled
//    through its LHS⁻¹ (a dense block among its contact rows), which its integrator gives
//    as the blocks of LHS⁻¹ among the nodes the contacts sit on (inverse_blocks);
//  - q = H v_free, and back from the solver: the generalised impulses Hᵀ r, added into each
//    modelization's node field `reaction`.
// When every moving body of the problem gives a compact inverse of one size k (rigid-only
// scenes, and mixed scenes whose other bodies touch nothing this step), the problem also
// carries the factored form (BodyFactor: H blocks and k × k inverses), which the
// body-velocity NLGS and APGD use, and W is assembled only for solvers that read it; the
// numbers are then those of the rigid-only assembly before modelizations had their say
// (same blocks, same sums in the same order). Otherwise W is always given.
#include <Eigen/SparseCore>
#include <cstddef>
#include <cstdint>
#include <moreau/contact_problem.hpp>
#include <moreau/integrator.hpp>
#include <moreau/modelization.hpp>
#include <vector>

#include "../fclib/fclib.hpp"

namespace moreau::kernel {

/// A modelization of the scene with its integrator, as the contact side uses them.
struct ContactModel {
  const Modelization* model = nullptr;
  const Integrator* integrator = nullptr;
  std::string nodes;  ///< its node set
  int k = 0;          ///< unknowns per node
};

/// The contacts of a step as the contact side hands them over: two sides each. A side's
/// point sits on one node (`node`), or on several with interpolation weights (a mesh
/// facet: `count`, `nodes`, `weights`, filled only when some side has several; empty
/// `count` means one node of weight 1 for every side).
struct ContactSides {
  std::vector<int> body;          ///< nc × 2, scene bodies
  std::vector<int> model;         ///< nc × 2, indices into the models
  std::vector<std::size_t> node;  ///< nc × 2, the (first) node supporting the point (row of its model's node set)
  std::vector<int> count;         ///< nc × 2 or empty: support nodes of each side (1 to 4)
  std::vector<std::size_t> nodes; ///< nc × 2 × 4: the support nodes
  std::vector<double> weights;    ///< nc × 2 × 4: their weights (summing to 1)
  std::vector<double> point;      ///< nc × 3, world, detection configuration
  std::vector<double> frame;      ///< nc × d × d, rows n, t[, s]
  std::size_t size() const { return body.size() / 2; }
  int support_count(std::size_t side) const { return count.empty() ? 1 : count[side]; }
  std::size_t support_node(std::size_t side, int j) const { return count.empty() ? node[side] : nodes[4 * side + j]; }
  double support_weight(std::size_t side, int j) const { return count.empty() ? 1.0 : weights[4 * side + j]; }
  void clear() {
    body.clear();
    model.clear();
    node.clear();
    count.clear();
    nodes.clear();
    weights.clear();
    point.clear();
    frame.clear();
  }
};

class ContactAssembly {
 public:
  /// H for these contacts, the inverses, and W unless `with_W` is false and the factored
  /// form is possible (then problem.W is left empty and problem.factor filled). Fills
  /// problem.dim, W and factor; q and μ are the caller's (free_local_velocity).
  void build(const State& state, const std::vector<ContactModel>& models, const ContactSides& contacts, bool with_W,
             LocalProblem& problem);
  /// H v for v⁻ or v_free, from each node's generalised velocity (its modelization's).
  Eigen::VectorXd local_velocity(const State& state, Velocity which) const;
  /// Whether the last build gave the factored form.
  bool factored() const { return factored_; }
  /// Hands H to the problem's factor for the solve (moved, not copied: it is the biggest
  /// array of a step); `take_back` returns it, which store_reactions needs.
  void lend(LocalProblem& problem);
  void take_back(LocalProblem& problem);
  /// Zeroes every model's node field `reaction` and adds Hᵀ r into it.
  void store_reactions(State& state, const Eigen::VectorXd& r) const;
  /// The last problem in FCLib's global form, M v = H r + f, u = Hᵀ v + w (DESIGN §3.5),
  /// over the free unknowns of the moving bodies its contacts touch, in body order: M
  /// block-diagonal (a body's LHS: its integrator's lhs_entries, or the inverse of its
  /// compact inverse on its free components), f = M v_free, w = q − Hᵀ v_free, so that
  /// reducing it gives back W and q. `q` and `mu` are the local problem's. An integrator
  /// that can give neither form is an error (RunError naming it).
  fclib::GlobalProblem global_problem(const State& state, const Eigen::VectorXd& q, const Eigen::VectorXd& mu) const;

 private:
  void general_w(const State& state, LocalProblem& problem) const;
  int dim_ = 3;
  const std::vector<ContactModel>* models_ = nullptr;
  const ContactSides* contacts_ = nullptr;
  std::vector<std::size_t> offset_;  ///< per side (2·nc + 1): where its H blocks start in H_
  std::vector<double> H_;            ///< per contact, per side, per support node: d × k of its model (side 1 negated)
  bool factored_ = false;
  /// Per touched body: −1 not touched, else an index into inverse_ (k² values each).
  std::vector<long> compact_;
  std::vector<double> inverse_;
  std::vector<char> compact_ok_;  ///< per body: its integrator gave a compact inverse
  /// local_velocity's scratch, kept over the calls (a mesh's node table is not cleared for
  /// a few contacts each call): per model and node, the call that asked its velocity and
  /// where that is in velocity_seen_ (a slot of an earlier call is stale).
  struct VelocitySlot {
    std::uint64_t call = 0;
    std::size_t at = 0;
  };
  mutable std::vector<std::vector<VelocitySlot>> velocity_slot_;
  mutable std::vector<double> velocity_seen_;
  mutable std::uint64_t velocity_call_ = 0;
};

}  // namespace moreau::kernel
