#pragma once
// Simple structured meshes, so an example needs no external mesher. Deterministic: the same
// arguments give the same nodes and elements in the same order. `size` is the target
// element edge length; the number of divisions along a length ℓ is ⌈ℓ/size⌉ (at least 1).
//
// Named sets (node sets and boundary sets of the same names, plus the element set "all"):
//   rectangle: xmin, xmax, ymin, ymax, boundary
//   box:       xmin, xmax, ymin, ymax, zmin, zmax, boundary
//   disk:      boundary; node set "centre" (the node at the centre)
// Errors (non-positive or non-finite lengths, a type of the wrong dimension, more than
// 10⁷ elements) throw MeshError.
#include <array>

#include "mesh.hpp"

namespace moreau::fem {

/// [origin, origin + extent] in 2D, of T3 (each cell split along the same diagonal) or Q4.
Mesh rectangle_mesh(std::array<double, 2> origin, std::array<double, 2> extent, double size, ElementType type);

/// A disk of T3 or Q4: a square core and four blocks out to the circle (boundary nodes on
/// the circle, straight edges between them, so the area is slightly below πR²).
Mesh disk_mesh(std::array<double, 2> centre, double radius, double size, ElementType type);

/// [origin, origin + extent] in 3D, of H8 or T4 (each cell cut into 6 tetrahedra around
/// its main diagonal, which conforms across cells).
Mesh box_mesh(std::array<double, 3> origin, std::array<double, 3> extent, double size, ElementType type);

}  // namespace moreau::fem
