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

namespace moreau {

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
};

}  // namespace moreau
