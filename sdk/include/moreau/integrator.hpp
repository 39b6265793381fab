#pragma once
// A time integrator: from the ⁻ state and the step's forces, the free velocity (stage
// free_velocity), and, once the contact impulses are known, the ⁺ velocities and
// positions (stage update_dofs). Works on the fields of the modelization it serves.
#include <moreau/plugin.hpp>
#include <moreau/step.hpp>

namespace moreau {

class MOREAU_API Integrator : public Plugin {
 public:
  static constexpr Kind kind = Kind::integrator;

  /// Called once after all bodies are built (e.g. to check the fields it needs exist).
  virtual void prepare(State& state) = 0;
  /// Stage free_velocity: velocities at the end of the step without contact impulses.
  virtual void free_velocity(StepContext& ctx) = 0;
  /// Stage update_dofs: ⁺ velocities (free velocity plus M⁻¹ times the contact impulses
  /// already stored in the state) and ⁺ positions and orientations.
  virtual void update_dofs(StepContext& ctx) = 0;

  /// For contacts: the generalised inverse mass of `body` that update_dofs applies to
  /// contact impulses, world frame, k×k row-major (k = 3 in 2D: vx vy ω; k = 6 in 3D:
  /// v then ω), zero for fixed bodies and imposed components; and the body's centre of
  /// mass (3 values, world). Valid after free_velocity of the current step.
  virtual void contact_inverse_mass(const State& state, std::size_t body, double* inverse_mass,
                                    double* center) const = 0;
};

}  // namespace moreau
