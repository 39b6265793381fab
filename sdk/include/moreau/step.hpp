#pragma once
// What the stages of one step share.
#include <moreau/state.hpp>
#include <vector>

namespace moreau {

struct StepContext {
  State& state;
  long step = 0;          ///< index of the step being computed: from t⁻ = step·h to t⁺ = (step+1)·h
  double time = 0;        ///< t⁻ (computed as step·h, never accumulated: restarts stay bit-identical)
  double h = 0;           ///< time step (s)
  double theta = 0.5;     ///< θ of the θ-scheme
  std::vector<double> gravity;  ///< d components (m/s²)
  /// True when the scene has external-force plugins: the `force` and `torque` fields were
  /// zeroed and filled at stage external_forces. False: they hold nothing and are not read.
  bool external_forces = false;
  /// True when the contact stages wrote this step's contact impulses into the node field
  /// `reaction` (Hᵀ r) of every modelization. False: that field is not read.
  bool contact_impulses = false;
};

}  // namespace moreau
