#include "element_geometry.hpp"

#include <Eigen/LU>

namespace moreau::fem::detail {

void ElementGeometry::bind(const Mesh& mesh, int e) {
  type = mesh.elements.type[e];
  const ElementInfo& info = element_info(type);
  const auto cell = mesh.elements[e];
  nodes = info.nodes;
  dim = mesh.dim;
  X.resize(nodes, dim);
  for (int a = 0; a < nodes; ++a) X.row(a) = mesh.x.col(cell[a]).transpose();
  N.resize(nodes);
  dNdx.resize(nodes, dim);
}

double ElementGeometry::evaluate(const double* xi) {
  double dN[max_nodes * 3];
  shape_functions(type, xi, N.data());
  shape_derivatives(type, xi, dN);
  const Eigen::Map<const NodeMatrix> dNdxi(dN, nodes, dim);
  if (dim == 2) {
    const Eigen::Matrix2d J = X.transpose() * dNdxi;  // J(i, k) = ∂x_i/∂ξ_k
    det = J.determinant();
    dNdx = dNdxi * J.inverse();
  } else {
    const Eigen::Matrix3d J = X.transpose() * dNdxi;
    det = J.determinant();
    dNdx = dNdxi * J.inverse();
  }
  return det;
}

Eigen::Vector3d ElementGeometry::point() const {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  p.head(dim) = X.transpose() * N;
  return p;
}

}  // namespace moreau::fem::detail
