#pragma once
// The rigid-body state: the one table of fields (name, set, components in 2D and 3D, time
// depths, units, output, restart, doc) that drives the State's allocation, the HDF5
// output, restarts and the docs (`moreau plugins` prints it). Used by the `rigid`
// modelization, the `theta` integrator and hooks. A rigid body is one node of the set
// `rigid.nodes`: its row there is `state.body(b).first_node` (`state.node_values(b, name)`).
//
// Conventions: world frame unless said otherwise; `position` and `velocity` are those of
// the body-frame origin, which is the centre of mass (a cluster whose inertia comes from
// its contactors has its origin moved there when built: docs/scene.md); `angular_velocity`
// is in the world frame; inertia is in the body frame.
#include <moreau/node_fields.hpp>
#include <moreau/state.hpp>
#include <vector>

namespace moreau::rigid {

/// The modelization's name and its one set: a rigid body is one node.
inline constexpr const char* model = "rigid";
inline constexpr const char* nodes = "rigid.nodes";

inline constexpr const char* position = node_fields::position;
inline constexpr const char* angle = node_fields::angle;
inline constexpr const char* orientation = node_fields::orientation;
inline constexpr const char* velocity = "velocity";
inline constexpr const char* angular_velocity = "angular_velocity";
inline constexpr const char* mass = "mass";
inline constexpr const char* inverse_mass = "inverse_mass";
inline constexpr const char* inertia = "inertia";
inline constexpr const char* inverse_inertia = "inverse_inertia";
inline constexpr const char* fixed = "fixed";
inline constexpr const char* free_velocity = "free_velocity";
inline constexpr const char* free_angular_velocity = "free_angular_velocity";
inline constexpr const char* force = node_fields::force;
inline constexpr const char* torque = node_fields::torque;
/// Contact impulse of the step (Hᵀ r): linear then angular about the centre of mass, world.
inline constexpr const char* reaction = node_fields::reaction;
inline constexpr const char* imposed_velocity = node_fields::imposed_velocity;
inline constexpr const char* detection_position = node_fields::detection_position;
inline constexpr const char* detection_rotation = node_fields::detection_rotation;
inline constexpr const char* travel = node_fields::travel;

inline std::vector<FieldSpec> fields() {
  using O = FieldOutput;
  auto f = [](const char* name, int c2, int c3, int depths, const char* units, O out, bool restart, const char* doc,
              bool int8 = false, Needed needed = Needed::always) {
    return field_spec(nodes, name, c2, c3, depths, units, out, restart, doc, int8 ? FileType::int8 : FileType::real,
                      needed);
  };
  return {
      f(position, 2, 3, 2, "m", O::frame, true, "position of the body origin (= centre of mass)"),
      f(angle, 1, 0, 2, "rad", O::frame, true, "2D rotation angle, counter-clockwise"),
      f(orientation, 0, 4, 2, "1", O::frame, true, "3D orientation, unit quaternion w x y z (body to world)"),
      f(velocity, 2, 3, 2, "m/s", O::frame, true, "velocity of the body origin"),
      f(angular_velocity, 1, 3, 2, "rad/s", O::frame, true, "angular velocity, world frame"),
      f(mass, 1, 1, 1, "kg", O::once, false, "mass (2D: per unit thickness)"),
      f(fixed, 1, 1, 1, "1", O::once, false, "1 for bodies that never move", true),
      f(inertia, 1, 6, 1, "kg m2", O::once, false,
        "inertia about the centre of mass, body frame (3D: xx yy zz xy xz yz; 2D: polar)"),
      f(inverse_mass, 1, 1, 1, "1/kg", O::none, false, "1/mass, 0 for fixed bodies"),
      f(inverse_inertia, 1, 6, 1, "1/(kg m2)", O::none, false, "inverse inertia, body frame, 0 for fixed bodies"),
      f(free_velocity, 2, 3, 1, "m/s", O::none, false, "velocity at the end of the step without contact impulses"),
      f(free_angular_velocity, 1, 3, 1, "rad/s", O::none, false,
        "angular velocity at the end of the step without contact impulses, world axes at the start of the step"),
      f(force, 2, 3, 1, "N", O::none, false, "external force of the step (only with force plugins)", false, Needed::forces),
      f(torque, 1, 3, 1, "N m", O::none, false, "external torque about the centre of mass (only with force plugins)", false,
        Needed::forces),
      f(reaction, 3, 6, 1, "N s, N m s", O::none, false,
        "contact impulse of the step (H^T r): linear, then angular about the centre of mass; world frame", false,
        Needed::contacts),
      f(detection_position, 2, 3, 1, "m", O::none, false, "position at the detection configuration q + (1-theta) h v", false,
        Needed::contacts),
      f(detection_rotation, 1, 4, 1, "rad / 1", O::none, false, "angle / orientation at the detection configuration",
        false, Needed::contacts),
      f(travel, 2, 2, 1, "m, rad", O::none, false,
        "bounds on the distance travelled (2h|v| + h^2|g|) and the angle turned (2h|w|) in the step", false,
        Needed::contacts),
      f(imposed_velocity, 3, 6, 1, "m/s, rad/s", O::none, false,
        "velocity imposed at the end of the step, linear then angular (world frame); NaN = free", false,
        Needed::imposed),
  };
}

}  // namespace moreau::rigid
