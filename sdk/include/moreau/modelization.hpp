#pragma once
// A modelization describes the bulk behaviour of a family of bodies (rigid bodies now,
// finite elements later). It declares its fields, fills each body's rows from the scene,
// and computes the bulk terms (gravity, gyroscopic and internal forces) of each step.
// It knows nothing of contacts.
#include <moreau/plugin.hpp>
#include <moreau/state.hpp>
#include <moreau/step.hpp>
#include <optional>
#include <array>

namespace moreau {

/// Mass properties of a body's contactors at unit density, in the body frame, each
/// contactor at its placement (2D: per unit thickness; only the [0,1] components of
/// `center` are used).
struct MassProperties {
  double volume = 0;                       ///< m³ (2D: m² per unit thickness)
  std::array<double, 3> center{0, 0, 0};   ///< centre of volume in the body frame (m)
  std::array<double, 9> inertia{};         ///< second moment about `center`, row-major 3×3 (m⁵; 2D: [8] = polar, m⁴)
};

class MOREAU_API Modelization : public Plugin {
 public:
  static constexpr Kind kind = Kind::modelization;

  /// The table of fields this modelization stores per body.
  virtual std::vector<FieldSpec> fields(int dim) const = 0;
  /// Keys a body object of this model accepts, besides the kernel's own
  /// (`name`, `model`, `contactors`).
  virtual Schema body_schema(int dim) const = 0;
  /// Fills the rows of `body` from its validated JSON. `contactors` holds the unit-density
  /// mass properties of its contactors when it has any (placements included); `density`
  /// the material's, if any. Returns the point of the scene's body frame that the
  /// modelization took as the body's origin (`rigid`: the centre of mass of a moving body
  /// whose inertia comes from its contactors); the kernel re-expresses the contactor
  /// placements about it, so contactors stay where the scene put them. Zeros: the origin
  /// is the one the scene wrote.
  virtual std::array<double, 3> init_body(State& state, std::size_t body, const Params& params,
                                          const std::optional<MassProperties>& contactors,
                                          std::optional<double> density) = 0;
  /// Stage `bulk`: bulk forces of the step (internal forces of deformable bodies…).
  virtual void bulk(StepContext& ctx) = 0;
  /// False when bulk() has nothing to do (rigid bodies: gravity and gyroscopic terms are
  /// the integrator's), so the stage is skipped.
  virtual bool has_bulk() const { return true; }
};

}  // namespace moreau
