#pragma once
// A contact law: what the solver needs of each contact, besides geometry. Every law here
// reduces to a Signorini–Coulomb problem on a shifted normal velocity: the solver sees
// `u_n + shift ≥ 0 ⊥ r_n ≥ 0` with Coulomb friction `mu` on the tangential part, where
// the law chooses `shift` (DESIGN §1):
//  - inelastic (LMGC90 IQS_CLB): shift = max(0, g)/h, g the gap at the predicted
//    configuration q⁻ + (1−θ)h v⁻ (from which bodies move by θh v⁺: an approaching contact
//    ends the step at (1−θ)g and its next predicted gap is 0), so a resting contact neither
//    drifts into its partner nor is pushed apart, and a fast one does not tunnel;
//  - Newton restitution (RST_CLB): shift = e·u_n⁻ for a contact that is closed or closes
//    during the step (impact), max(0, g)/h otherwise.
#include <moreau/plugin.hpp>

namespace moreau {

struct LawInput {
  double gap = 0;           ///< signed gap at the detection configuration (m)
  double normal_velocity_begin = 0;  ///< u_n⁻: relative normal velocity at the start of the step (m/s)
  double h = 0;             ///< time step (s)
};

class MOREAU_API Law : public Plugin {
 public:
  static constexpr Kind kind = Kind::law;
  /// Coulomb friction coefficient μ ≥ 0.
  virtual double friction() const = 0;
  /// The shift added to the normal component of the free local velocity.
  virtual double normal_shift(const LawInput& in) const = 0;
};

}  // namespace moreau
