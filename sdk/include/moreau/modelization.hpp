#pragma once
// A modelization describes the bulk behaviour of a family of bodies (rigid bodies now,
// finite elements later) and the kinematics of the points its bodies carry (the seed's
// Modelization, DESIGN §5, docs/architecture.md). It declares its sets and fields, fills
// each body's rows from the scene, computes the bulk terms of each step, and, for the
// contact side, tells how a point on one of its bodies moves with its unknowns (the rows
// of H). It knows nothing of contacts, of time-stepping (its integrator's) or of the
// solver. Several modelizations share one run; each is paired with its integrator.
#include <array>
#include <moreau/plugin.hpp>
#include <moreau/state.hpp>
#include <moreau/step.hpp>
#include <optional>
#include <string>

namespace moreau {

struct LinearBulk;  // linear_bulk.hpp

/// Mass properties of a body's contactors at unit density, in the body frame, each
/// contactor at its placement (2D: per unit thickness; only the [0,1] components of
/// `center` are used).
struct MassProperties {
  double volume = 0;                       ///< m³ (2D: m² per unit thickness)
  std::array<double, 3> center{0, 0, 0};   ///< centre of volume in the body frame (m)
  std::array<double, 9> inertia{};         ///< second moment about `center`, row-major 3×3 (m⁵; 2D: [8] = polar, m⁴)
};

/// How many rows a body takes in its modelization's sets.
struct BodySize {
  std::size_t nodes = 1;
  std::size_t elements = 0;
};

/// Which generalised velocity the contact side asks for.
enum class Velocity {
  begin,  ///< v⁻, at the start of the step
  free,   ///< v_free, at the end of the step without contact impulses (after free_velocity)
};

/// A contact point on one body, as the contact side hands it to the body's modelization.
/// The point is supported by `count` nodes of the body (rows of the modelization's node
/// set) with weights (a contactor on one node: one node, weight 1; a point on a mesh
/// facet: the facet's 2 to 4 nodes and its interpolation weights, summing to 1).
struct PointOnBody {
  std::size_t body = 0;
  const std::size_t* nodes = nullptr;
  const double* weights = nullptr;
  int count = 0;
  double point[3] = {0, 0, 0};  ///< world, at the detection configuration (2D: z = 0)
  /// d rows of d values, row-major: the contact's local frame n, t[, s] (world).
  const double* frame = nullptr;
};

/// The element topology a viewer draws (docs/output.md): an XDMF Mixed connectivity of
/// the element set over the node set (each cell: its XDMF type, for polylines (2) and
/// polygons (3) its node count, then its node rows). Empty: nodes only.
struct Topology {
  std::vector<int> cells;
  std::size_t count = 0;  ///< number of cells (= rows of the element set)
};

class MOREAU_API Modelization : public Plugin {
 public:
  static constexpr Kind kind = Kind::modelization;

  // ---- Its sets and fields --------------------------------------------------------------
  /// Its node set, "<name>.nodes" (a rigid body is one node of `rigid.nodes`).
  virtual std::string node_set() const = 0;
  /// Its element set, "" when it has none.
  virtual std::string element_set() const { return {}; }
  /// Unknowns per node, k (rigid: 3 in 2D, vx vy ω; 6 in 3D, v then ω).
  virtual int node_dofs(int dim) const = 0;
  /// The table of the fields it stores, on its sets (FieldSpec::set).
  virtual std::vector<FieldSpec> fields(int dim) const = 0;
  /// The integrator it is paired with unless the scene says otherwise (`models`).
  virtual std::string default_integrator() const = 0;

  // ---- Bodies ---------------------------------------------------------------------------
  /// Keys a body object of this model accepts, besides the kernel's own
  /// (`name`, `model`, `contactors`).
  virtual Schema body_schema(int dim) const = 0;
  /// Rows the body needs in its sets (called before any row exists, to allocate them all at once).
  virtual BodySize body_size(const Params&, int dim) const {
    (void)dim;
    return {};
  }
  /// Fills the rows of `body` (`state.body(body)`) from its validated JSON, and records
  /// its named groups (State::set_groups) if it has any: contactors on a `boundary` and
  /// drivers or forces on `nodes` find them there. `contactors` holds the unit-density mass
  /// properties of its contactors on nodes when it has any (placements included);
  /// `material` the scene material the body names (`materials`: `density`, and `young`,
  /// `poisson` when given; errors at its pointer), null when it names none. Returns the
  /// point of the scene's body frame that the modelization took as the body's origin
  /// (`rigid`: the centre of mass of a moving body whose inertia comes from its
  /// contactors); the kernel re-expresses the contactor placements about it, so contactors
  /// stay where the scene put them. Zeros: the origin is the one the scene wrote.
  virtual std::array<double, 3> init_body(State& state, std::size_t body, const Params& params,
                                          const std::optional<MassProperties>& contactors, const Params* material) = 0;
  /// The topology of its element set, for the viewer; called once after every body is built.
  virtual Topology topology(const State&) const { return {}; }

  // ---- Bulk -----------------------------------------------------------------------------
  /// Stage `bulk`: bulk forces of the step (internal forces of deformable bodies…).
  virtual void bulk(StepContext& ctx) = 0;
  /// False when bulk() has nothing to do (rigid bodies: gravity and gyroscopic terms are
  /// the integrator's), so the stage is skipped.
  virtual bool has_bulk() const { return true; }

  /// A linear modelization (the seed's eq. 3 with F = −K q − C q̇, constant matrices) gives
  /// its integrator the bulk of one body: M, C, K over its nodes × k unknowns, its constant
  /// loads and its fixed unknowns (linear_bulk.hpp). Returns false when it is not linear
  /// (the default). Called once per body when the integrator prepares.
  virtual bool linear_bulk(const State& state, std::size_t body, LinearBulk& out) const {
    (void)state;
    (void)body;
    (void)out;
    return false;
  }
  /// Fields derived from the unknowns (stresses, for the output) from the values at `depth` (where the
  /// last update's ⁺ values are), only when read: before a frame is written (the first one included) and
  /// before a hook looks at the state, once per update at most; steps between frames do not pay for them,
  /// and nothing in a step may depend on them (nor restarts). Skipped unless has_derived_fields().
  virtual void derived_fields(State& state, Depth depth) {
    (void)state;
    (void)depth;
  }
  virtual bool has_derived_fields() const { return false; }

  // ---- Kinematics, for the contact side ---------------------------------------------------
  /// The generalised velocity of node `node` (a row of its node set): k values.
  virtual void generalised_velocity(const State& state, Velocity which, std::size_t node, double* out) const = 0;
  /// The rows of H for a point on one of its bodies: for each support node j, the d × k
  /// block (row-major) with u_local = Σ_j block_j v_node(j), u_local the velocity of the
  /// material point written in the contact's frame, at the detection configuration
  /// (node fields detection_position, detection_rotation). `blocks`: count × d × k.
  virtual void contact_jacobian(const State& state, const PointOnBody& p, double* blocks) const = 0;
};

}  // namespace moreau
