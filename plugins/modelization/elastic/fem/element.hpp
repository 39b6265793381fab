#pragma once
// Reference elements: node orderings, faces, shape functions and integration rules.
// One table (element.cpp) describes every type; adding T6, Q8 or T10 means adding their
// rows, shape functions and rules there, nothing else.
//
// Node orderings are Gmsh's (and VTK's, which agree for these types), reference coordinates:
//   L2  segment       ξ ∈ [−1, 1]:        0: −1, 1: +1
//   T3  triangle      (0,0) (1,0) (0,1)                       counter-clockwise
//   Q4  quadrangle    (−1,−1) (1,−1) (1,1) (−1,1)             counter-clockwise
//   T4  tetrahedron   (0,0,0) (1,0,0) (0,1,0) (0,0,1)         positive volume
//   H8  hexahedron    bottom (ζ=−1) 0 1 2 3 counter-clockwise seen from +ζ, top 4 5 6 7 above
// A face lists its nodes so that, for an element of positive orientation, the face is
// counter-clockwise seen from outside (3D) or its outward normal is the edge direction
// turned by −90° (2D): boundary facets inherit an outward orientation from this table.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace moreau::fem {

enum class ElementType : std::uint8_t { L2, T3, Q4, T4, H8 };
inline constexpr int element_type_count = 5;

/// An integration point in reference coordinates with its weight.
struct QuadraturePoint {
  std::array<double, 3> xi;
  double weight;
};

/// A face of a reference element: its type and its local node numbers (outward order).
struct FaceInfo {
  ElementType type;
  std::array<std::uint8_t, 8> nodes;
};

struct ElementInfo {
  ElementType type;
  std::string_view name;      ///< "T3", "Q4", …
  int dim;                    ///< reference dimension (1, 2 or 3)
  int nodes;                  ///< number of nodes
  int corners;                ///< vertices among them (first `corners` nodes)
  int gmsh_type;              ///< Gmsh element type number
  int vtk_type;               ///< VTK cell type number (for output)
  std::span<const FaceInfo> faces;          ///< (dim−1)-dimensional faces, outward order
  std::span<const QuadraturePoint> rule;    ///< integrates the consistent mass exactly on affine elements
  std::array<double, 3> centre;             ///< reference centroid
  std::array<std::uint8_t, 27> mirror;      ///< a node order of the opposite orientation
};

/// Reverses the orientation of an element's nodes (a mirror image: clockwise ↔
/// counter-clockwise, negative ↔ positive volume).
void reverse_orientation(ElementType type, std::span<int> nodes);

const ElementInfo& element_info(ElementType type);

/// Shape functions at a reference point: N[i] for i < nodes.
void shape_functions(ElementType type, const double* xi, double* N);
/// Their reference derivatives: dN[i * dim + k] = ∂N_i/∂ξ_k.
void shape_derivatives(ElementType type, const double* xi, double* dN);

/// The element type whose Gmsh number is `gmsh_type`, or false when moreau has none.
bool element_type_from_gmsh(int gmsh_type, ElementType& type);

}  // namespace moreau::fem
