#pragma once
// A test-only second modelization (tests/mixed): chains (or small lattices) of point masses
// joined by linear springs. A body owns several nodes (k = d unknowns each: a point has no
// rotation) and elements (its springs), and its LHS = M + h²θ²K couples its nodes, so W
// has coupled blocks between contacts on one body: what a finite-element body will do,
// with numbers a test can check by hand. Stiffness is linearised about the rest
// configuration (small displacements), so K is constant and LHS is factorised once.
#include <moreau/node_fields.hpp>
#include <moreau/state.hpp>
#include <vector>

namespace moreau_test::chain {

using moreau::FieldOutput;
using moreau::FieldSpec;
using moreau::FileType;
using moreau::Needed;

inline constexpr const char* model = "chain";
inline constexpr const char* nodes = "chain.nodes";
inline constexpr const char* springs = "chain.springs";

inline constexpr const char* rest_position = "rest_position";
inline constexpr const char* velocity = "velocity";
inline constexpr const char* free_velocity = "free_velocity";
inline constexpr const char* mass = "mass";
inline constexpr const char* ends = "ends";
inline constexpr const char* stiffness = "stiffness";
inline constexpr const char* tension = "tension";

inline std::vector<FieldSpec> fields() {
  using moreau::field_spec;
  namespace N = moreau::node_fields;
  using O = FieldOutput;
  return {
      field_spec(nodes, N::position, 2, 3, 2, "m", O::frame, true, "node position"),
      field_spec(nodes, velocity, 2, 3, 2, "m/s", O::frame, true, "node velocity"),
      field_spec(nodes, rest_position, 2, 3, 1, "m", O::once, false, "position at rest (springs unstretched)"),
      field_spec(nodes, mass, 1, 1, 1, "kg", O::once, false, "node mass"),
      field_spec(nodes, free_velocity, 2, 3, 1, "m/s", O::none, false, "velocity at the end of the step without contact impulses"),
      field_spec(nodes, N::force, 2, 3, 1, "N", O::none, false, "external force of the step", FileType::real, Needed::forces),
      field_spec(nodes, N::reaction, 2, 3, 1, "N s", O::none, false, "contact impulse of the step (H^T r)", FileType::real,
        Needed::contacts),
      field_spec(nodes, N::detection_position, 2, 3, 1, "m", O::none, false, "position at q + (1-theta) h v", FileType::real,
        Needed::contacts),
      field_spec(nodes, N::travel, 2, 2, 1, "m, rad", O::none, false, "distance bound 2h|v| + h^2|g|; no rotation",
        FileType::real, Needed::contacts),
      field_spec(springs, ends, 2, 2, 1, "1", O::once, false, "its two nodes (rows of chain.nodes)", FileType::int32),
      field_spec(springs, stiffness, 1, 1, 1, "N/m", O::once, false, "spring constant"),
      field_spec(springs, tension, 1, 1, 1, "N", O::frame, false, "tension k e.(u_b - u_a) (linearised)"),
  };
}

}  // namespace moreau_test::chain
