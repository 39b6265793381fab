#pragma once
// The field table of the `elastic` modelization (docs/deformable.md): one node row per
// mesh node (set `elastic.nodes`, k = d unknowns: the velocity), one element row per
// element (`elastic.elements`). The `linear_theta` integrator reads and writes the node
// fields by their standard names (moreau/node_fields.hpp); stresses are derived when a
// frame is written (Modelization::derived_fields), for the output.
#include <moreau/node_fields.hpp>
#include <moreau/state.hpp>
#include <vector>

namespace moreau::elastic {

inline constexpr const char* model = "elastic";
inline constexpr const char* nodes = "elastic.nodes";
inline constexpr const char* elements = "elastic.elements";

inline constexpr const char* fixed = "fixed";
inline constexpr const char* mass = "mass";
inline constexpr const char* stress = "stress";
inline constexpr const char* von_mises = "von_mises";
inline constexpr const char* type = "type";

inline std::vector<FieldSpec> fields() {
  namespace N = moreau::node_fields;
  using O = FieldOutput;
  auto node = [](const char* name, int c2, int c3, int depths, const char* units, O out, bool restart, const char* doc,
                 FileType file = FileType::real, Needed needed = Needed::always) {
    return field_spec(nodes, name, c2, c3, depths, units, out, restart, doc, file, needed);
  };
  auto element = [](const char* name, int c, const char* units, O out, const char* doc, FileType file = FileType::real) {
    return field_spec(elements, name, c, c, 1, units, out, false, doc, file);
  };
  return {
      node(N::position, 2, 3, 2, "m", O::frame, true, "position of the node, reference + displacement"),
      node(N::displacement, 2, 3, 2, "m", O::frame, true, "displacement u from the reference position"),
      node(N::velocity, 2, 3, 2, "m/s", O::frame, true, "velocity"),
      node(N::reference_position, 2, 3, 1, "m", O::once, false, "position in the mesh (at rest)"),
      node(fixed, 1, 1, 1, "1", O::once, false, "1 for a node of a `fixed` group (all components held)", FileType::int8),
      node(mass, 1, 1, 1, "kg", O::once, false,
           "the node's share of the mass: column sum of M (momentum = sum of mass v; 2D: kg/m)"),
      node(stress, 6, 6, 1, "Pa", O::frame, false,
           "Cauchy stress averaged over the node's elements (weighted by their measure), xx yy zz xy yz xz"),
      node(von_mises, 1, 1, 1, "Pa", O::frame, false, "von Mises equivalent of the nodal stress"),
      node(N::free_velocity, 2, 3, 1, "m/s", O::none, false, "velocity at the end of the step without contact impulses"),
      node(N::force, 2, 3, 1, "N", O::none, false, "external force of the step on the node (force plugins; 2D: N/m)",
           FileType::real, Needed::forces),
      node(N::reaction, 2, 3, 1, "N s", O::none, false, "contact impulse of the step on the node (H^T r)", FileType::real,
           Needed::contacts),
      node(N::detection_position, 2, 3, 1, "m", O::none, false, "position at q + (1 - theta) h v", FileType::real,
           Needed::contacts),
      node(N::travel, 2, 2, 1, "m, rad", O::none, false, "distance bound 2h|v| + h^2|g|; no rotation", FileType::real,
           Needed::contacts),
      node(N::imposed_velocity, 2, 3, 1, "m/s", O::none, false, "imposed velocity (drivers on node groups); NaN: free",
           FileType::real, Needed::imposed),
      element(type, 1, "1", O::once, "element type: 2 T3, 3 Q4, 4 T4, 5 H8 (Gmsh's numbers)", FileType::int8),
      element(stress, 6, "Pa", O::frame, "Cauchy stress at the element's centre, xx yy zz xy yz xz"),
      element(von_mises, 1, "Pa", O::frame, "von Mises equivalent stress at the element's centre"),
  };
}

}  // namespace moreau::elastic
