#pragma once
// Internal: an element's geometry at reference points (shape functions, their physical
// gradients, Jacobian determinant), with no allocation per element.
#include <Eigen/Core>

#include "mesh.hpp"

namespace moreau::fem::detail {

inline constexpr int max_nodes = 27;  // room for higher-order elements

using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor, max_nodes, 3>;
using NodeVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_nodes, 1>;

class ElementGeometry {
 public:
  /// Takes element e of the mesh (its type and node coordinates).
  void bind(const Mesh& mesh, int e);
  /// Evaluates at reference point xi: N, dNdx (physical gradients, [nodes, dim]) and the
  /// Jacobian determinant, which it returns. Only valid for elements of the mesh dimension.
  double evaluate(const double* xi);

  ElementType type = ElementType::T3;
  int nodes = 0, dim = 0;
  NodeMatrix X;     ///< [nodes, dim] node coordinates
  NodeVector N;     ///< [nodes]
  NodeMatrix dNdx;  ///< [nodes, dim]
  double det = 0;
  /// Position of the last evaluated point.
  Eigen::Vector3d point() const;
};

}  // namespace moreau::fem::detail
