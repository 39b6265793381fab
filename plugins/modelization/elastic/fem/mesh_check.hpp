#pragma once
// Validity of a mesh before it is assembled.
#include "mesh.hpp"

namespace moreau::fem {

/// Relative size below which an element counts as degenerate: |det J| ≤ this × ℓ^dim
/// at an integration point, ℓ the element's longest corner-to-corner distance.
inline constexpr double degenerate_tolerance = 1e-10;

/// Throws MeshError when the dimension is not 2 or 3, an element's type does not fit it or
/// refers to a node that does not exist, a node belongs to no element, a node coordinate
/// is not finite, or when an element is inverted
/// (Jacobian determinant < 0 at an integration point) or degenerate (see above). The
/// message lists up to 10 faulty elements with their numbers (and file and line when the
/// mesh was read from a file) and counts the rest; the exception's element() and line()
/// are those of the first.
void check_mesh(const Mesh& mesh);

}  // namespace moreau::fem
