#pragma once
// An external force: adds to the `force` and `torque` fields (world frame) at stage
// external_forces. Forces are evaluated at the θ-point of the step, so a force that is
// constant over the step is integrated exactly.
#include <moreau/plugin.hpp>
#include <moreau/step.hpp>

namespace moreau {

class MOREAU_API Force : public Plugin {
 public:
  static constexpr Kind kind = Kind::force;
  virtual void apply(StepContext& ctx) = 0;
};

}  // namespace moreau
