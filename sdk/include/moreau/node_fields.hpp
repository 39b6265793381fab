#pragma once
// Names of the node fields the kernel reads or writes in any modelization's node set
// (docs/architecture.md, sdk/README.md "Writing a modelization"). A modelization declares
// those it supports in its field table; the kernel finds them by these names.
//
//   position            [d]      m     frame   the node's position: drawn by the viewer, the
//                                            reference point of contactors placed on the node
//   reference_position  [d]      m     once    where it is at rest (deformable bodies: the mesh)
//   displacement        [k]      m     frame   q − q_ref of a deformable body's node (linear
//                                            modelizations: the unknowns' integral)
//   velocity            [k]      m/s   frame   its generalised velocity (linear modelizations)
//   free_velocity       [k]      m/s   none    velocity at the end of the step without contact
//                                            impulses (linear modelizations)
//   angle / orientation [1] / [4]        frame   optional rotation of the node frame (2D angle, 3D
//                                            unit quaternion w x y z); absent: no rotation
//   detection_position  [d]      m     none    where the node is at the detection configuration
//                                            (written by the integrator at detection_configuration)
//   detection_rotation  [1] / [4]        none    its rotation there (only for nodes with one)
//   travel              [2]      m, rad  none  bounds on how far the node moves and turns during the
//                                            step (contacts are looked for that much further)
//   reaction            [k]      N s   none    the generalised contact impulse of the step, Hᵀ r on
//                                            the node's k unknowns (written by the kernel at
//                                            store_reactions; read by the integrator's update)
//   imposed_velocity    [k]      m/s, rad/s  none  imposed generalised velocity (drivers, hooks);
//                                            NaN components are free
//   force / torque      [d] / [1|3]  N, N m  none  external loads of the step (force plugins;
//                                            zeroed at stage external_forces)
namespace moreau::node_fields {

inline constexpr const char* position = "position";
inline constexpr const char* reference_position = "reference_position";
inline constexpr const char* displacement = "displacement";
inline constexpr const char* velocity = "velocity";
inline constexpr const char* free_velocity = "free_velocity";
inline constexpr const char* angle = "angle";
inline constexpr const char* orientation = "orientation";
inline constexpr const char* detection_position = "detection_position";
inline constexpr const char* detection_rotation = "detection_rotation";
inline constexpr const char* travel = "travel";
inline constexpr const char* reaction = "reaction";
inline constexpr const char* imposed_velocity = "imposed_velocity";
inline constexpr const char* force = "force";
inline constexpr const char* torque = "torque";

}  // namespace moreau::node_fields
