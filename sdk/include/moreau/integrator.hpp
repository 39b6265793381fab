#pragma once
// A time integrator, paired with one modelization (the seed's ModelHandler pairs them;
// DESIGN §5, docs/architecture.md). From the ⁻ state and the step's forces it computes the
// free velocity (stage free_velocity) and, once the contact impulses are known (node field
// `reaction`, Hᵀ r), the ⁺ velocities and positions (stage update_dofs). For the contact
// side it gives the detection configuration of its nodes and the application of its own
// LHS⁻¹ (rigid: the inverse mass; deformable: a factorisation of M + hθC + h²θ²K), from
// which the kernel builds W = H LHS⁻¹ Hᵀ without knowing what kind of body is behind a
// contact.
#include <moreau/modelization.hpp>
#include <moreau/plugin.hpp>
#include <moreau/step.hpp>
#include <vector>

namespace moreau {

/// One entry of a body's LHS (Integrator::lhs_entries).
struct LhsEntry {
  int row, column;
  double value;
};

class MOREAU_API Integrator : public Plugin {
 public:
  static constexpr Kind kind = Kind::integrator;

  /// Called once after all bodies are built, with the modelization it serves (check the
  /// fields it needs, factorise a constant LHS…). Faults: InputError.
  virtual void prepare(State& state, const Modelization& model) = 0;
  /// Stage free_velocity: velocities at the end of the step without contact impulses.
  virtual void free_velocity(StepContext& ctx) = 0;
  /// Stage update_dofs: ⁺ velocities (free velocity plus LHS⁻¹ times the node field
  /// `reaction` when ctx.contact_impulses) and ⁺ positions.
  virtual void update_dofs(StepContext& ctx) = 0;

  /// Stage detection_configuration (scenes with contacts): the node fields
  /// detection_position (and detection_rotation for nodes that have one) at the
  /// configuration contacts are detected on (θ-methods: q⁻ + (1−θ)h v⁻), and `travel`.
  virtual void detection_configuration(StepContext& ctx) = 0;
  /// When body `body`'s LHS is one k × k block (one node, uncoupled from any other: rigid
  /// bodies), writes LHS⁻¹ there (row-major, world frame; zero rows and columns for fixed
  /// bodies and imposed components) and returns true; false otherwise. Valid after
  /// free_velocity of the current step.
  virtual bool compact_inverse(const State& state, std::size_t body, double* inverse) const = 0;
  /// out = LHS_b⁻¹ in for body `body`: `in` and `out` hold `columns` column vectors of its
  /// nodes × k unknowns each (column-major: column c starts at c × nodes × k). Every body
  /// supports it (for a compact one, the k × k product).
  virtual void apply_inverse(const State& state, std::size_t body, int columns, const double* in, double* out) const = 0;

  /// The blocks of LHS_b⁻¹ among `count` nodes of body `body` (rows of its node set, in
  /// that order): `out` is (count·k)², column-major, entry (i·k + a, j·k + c) the velocity
  /// of unknown a of node i per unit impulse on unknown c of node j. This is what W needs of
  /// a body whose LHS couples its nodes (W_b = H_b G H_bᵀ over the nodes its contacts sit
  /// on). The default applies apply_inverse to unit columns; an integrator with a constant
  /// LHS may keep columns between steps (linear_theta does), as long as the numbers do not
  /// depend on what it kept (restarts stay bit-identical).
  virtual void inverse_blocks(const State& state, std::size_t body, const std::size_t* nodes, int count,
                              double* out) const {
    const BodyRows rows = state.body(body);
    const int k = state.models()[static_cast<std::size_t>(rows.model)].node_dofs;
    const std::size_t n = rows.nodes * static_cast<std::size_t>(k), m = static_cast<std::size_t>(count) * k;
    std::vector<double> unit(n * m, 0.0), response(n * m);
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j)
      for (int c = 0; c < k; ++c) unit[(j * k + c) * n + (nodes[j] - rows.first_node) * k + c] = 1.0;
    apply_inverse(state, body, static_cast<int>(m), unit.data(), response.data());
    for (std::size_t col = 0; col < m; ++col)
      for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i)
        for (int a = 0; a < k; ++a) out[col * m + i * k + a] = response[col * n + (nodes[i] - rows.first_node) * k + a];
  }

  /// The body's LHS over its nodes × k unknowns, for the FCLib global form of the contact
  /// problem (M v = H r + f): its entries (row, column, value; both triangles), counting
  /// unknowns within the body, without the constrained unknowns (fixed, imposed), which
  /// are listed in `constrained`. False when the integrator cannot give it (the default);
  /// the kernel inverts compact inverses itself.
  virtual bool lhs_entries(const State& state, std::size_t body, std::vector<LhsEntry>& entries,
                           std::vector<int>& constrained) const {
    (void)state;
    (void)body;
    (void)entries;
    (void)constrained;
    return false;
  }
};

}  // namespace moreau
