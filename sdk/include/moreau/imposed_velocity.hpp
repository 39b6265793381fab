#pragma once
// The field through which velocities are imposed on bodies: the scene's `drivers`
// (filled by the kernel at stage begin_step) and user hooks steering a run. Declared
// only when a scene has drivers or hooks. NaN components are free.
#include <moreau/state.hpp>

namespace moreau {

inline FieldSpec imposed_velocity_field() {
  FieldSpec f;
  f.name = "imposed_velocity";
  f.components_2d = 3;  // vx vy ω
  f.components_3d = 6;  // vx vy vz ωx ωy ωz (world frame)
  f.depths = 1;
  f.units = "m/s, rad/s";
  f.doc = "velocity imposed at the end of the step, linear then angular (world frame); NaN = free";
  f.output = FieldOutput::none;
  f.restart = false;
  return f;
}

}  // namespace moreau
