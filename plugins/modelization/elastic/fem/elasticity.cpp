#include "elasticity.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "element_geometry.hpp"

namespace moreau::fem {
namespace {

/// λ′ of σ = λ′ tr(ε) I + 2μ ε in the mesh's dimension (plane stress: 2λμ/(λ + 2μ)).
double effective_lambda(const Material& m) {
  return m.hypothesis == Hypothesis::plane_stress ? m.young * m.poisson / (1 - m.poisson * m.poisson)
                                                  : lame_lambda(m);
}

/// The pattern of a global matrix: DOF blocks of every pair of nodes sharing an element,
/// in compressed columns (rows sorted), so element matrices are added in place.
class BlockPattern {
 public:
  explicit BlockPattern(const Mesh& mesh) : dim_(mesh.dim) {
    const int n = mesh.node_count();
    std::vector<int> count(n + 1, 0);
    for (int e = 0; e < mesh.element_count(); ++e) {
      const auto cell = mesh.elements[e];
      for (int a : cell) count[a + 1] += static_cast<int>(cell.size());
    }
    for (int i = 0; i < n; ++i) count[i + 1] += count[i];
    std::vector<int> all(count[n]);
    std::vector<int> fill(count.begin(), count.end() - 1);
    for (int e = 0; e < mesh.element_count(); ++e) {
      const auto cell = mesh.elements[e];
      for (int a : cell)
        for (int b : cell) all[fill[a]++] = b;
    }
    start_.assign(n + 1, 0);
    for (int i = 0; i < n; ++i) {
      auto first = all.begin() + count[i], last = all.begin() + count[i + 1];
      std::sort(first, last);
      last = std::unique(first, last);
      neighbours_.insert(neighbours_.end(), first, last);
      start_[i + 1] = static_cast<int>(neighbours_.size());
    }
  }

  /// A zero matrix with the full pattern.
  SparseMatrix matrix() const {
    const int n = static_cast<int>(start_.size()) - 1, dofs = dim_ * n;
    SparseMatrix A(dofs, dofs);
    std::vector<int> per_column(dofs);
    for (int b = 0; b < n; ++b)
      for (int j = 0; j < dim_; ++j) per_column[dim_ * b + j] = dim_ * (start_[b + 1] - start_[b]);
    A.reserve(per_column);
    for (int b = 0; b < n; ++b)
      for (int j = 0; j < dim_; ++j)
        for (int k = start_[b]; k < start_[b + 1]; ++k)
          for (int i = 0; i < dim_; ++i) A.insert(dim_ * neighbours_[k] + i, dim_ * b + j) = 0.0;
    A.makeCompressed();
    return A;
  }

  /// Adds an element matrix (element node order) into A.
  void add(SparseMatrix& A, std::span<const int> cell, const Eigen::MatrixXd& Ae) const {
    const int nn = static_cast<int>(cell.size());
    double* values = A.valuePtr();
    const int* outer = A.outerIndexPtr();
    for (int b = 0; b < nn; ++b) {
      const int nb = cell[b];
      const int* first = neighbours_.data() + start_[nb];
      const int* last = neighbours_.data() + start_[nb + 1];
      for (int a = 0; a < nn; ++a) {
        const int slot = static_cast<int>(std::lower_bound(first, last, cell[a]) - first);
        for (int j = 0; j < dim_; ++j) {
          double* column = values + outer[dim_ * nb + j] + dim_ * slot;
          for (int i = 0; i < dim_; ++i) column[i] += Ae(dim_ * a + i, dim_ * b + j);
        }
      }
    }
  }

 private:
  int dim_;
  std::vector<int> start_, neighbours_;
};

void require_size(const char* function, const char* what, Eigen::Index size, Eigen::Index expected) {
  if (size != expected)
    throw std::invalid_argument(std::string(function) + ": " + what + " has " + std::to_string(size) +
                                " components, expected " + std::to_string(expected));
}

}  // namespace

void element_stiffness(const Mesh& mesh, int e, const Material& material, Eigen::MatrixXd& Ke) {
  detail::ElementGeometry g;
  g.bind(mesh, e);
  const int d = g.dim, nn = g.nodes;
  const double lambda = effective_lambda(material), mu = shear_modulus(material);
  Ke.setZero(d * nn, d * nn);
  for (const QuadraturePoint& q : element_info(g.type).rule) {
    const double w = g.evaluate(q.xi.data()) * q.weight;
    // K_(a i)(b j) = ∫ λ′ ∂iNa ∂jNb + μ ∂jNa ∂iNb + μ δij ∇Na·∇Nb
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b) {
        const double dot = g.dNdx.row(a).dot(g.dNdx.row(b));
        for (int i = 0; i < d; ++i)
          for (int j = 0; j < d; ++j)
            Ke(d * a + i, d * b + j) +=
                w * (lambda * g.dNdx(a, i) * g.dNdx(b, j) + mu * g.dNdx(a, j) * g.dNdx(b, i) + (i == j ? mu * dot : 0.0));
      }
  }
}

void element_mass(const Mesh& mesh, int e, double density, MassKind kind, Eigen::MatrixXd& Me) {
  detail::ElementGeometry g;
  g.bind(mesh, e);
  const int d = g.dim, nn = g.nodes;
  Eigen::MatrixXd scalar = Eigen::MatrixXd::Zero(nn, nn);
  for (const QuadraturePoint& q : element_info(g.type).rule) {
    const double w = g.evaluate(q.xi.data()) * q.weight * density;
    scalar.noalias() += w * g.N * g.N.transpose();
  }
  if (kind == MassKind::lumped) {
    // HRZ: the consistent diagonal scaled to the element's mass.
    const double total = scalar.sum(), diagonal = scalar.diagonal().sum();
    const Eigen::VectorXd lumped = scalar.diagonal() * (diagonal > 0 ? total / diagonal : 0.0);
    scalar.setZero();
    scalar.diagonal() = lumped;
  }
  Me.setZero(d * nn, d * nn);
  for (int a = 0; a < nn; ++a)
    for (int b = 0; b < nn; ++b)
      for (int i = 0; i < d; ++i) Me(d * a + i, d * b + i) = scalar(a, b);
}

SparseMatrix stiffness_matrix(const Mesh& mesh, const Material& material) {
  const BlockPattern pattern(mesh);
  SparseMatrix K = pattern.matrix();
  Eigen::MatrixXd Ke;
  for (int e = 0; e < mesh.element_count(); ++e) {
    element_stiffness(mesh, e, material, Ke);
    pattern.add(K, mesh.elements[e], Ke);
  }
  return K;
}

Eigen::VectorXd lumped_mass(const Mesh& mesh, double density) {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(mesh.dof_count());
  Eigen::MatrixXd Me;
  for (int e = 0; e < mesh.element_count(); ++e) {
    element_mass(mesh, e, density, MassKind::lumped, Me);
    const auto cell = mesh.elements[e];
    for (int a = 0; a < static_cast<int>(cell.size()); ++a)
      for (int i = 0; i < mesh.dim; ++i) m[mesh.dim * cell[a] + i] += Me(mesh.dim * a + i, mesh.dim * a + i);
  }
  return m;
}

SparseMatrix mass_matrix(const Mesh& mesh, double density, MassKind kind) {
  if (kind == MassKind::lumped) {
    const Eigen::VectorXd m = lumped_mass(mesh, density);
    SparseMatrix M(m.size(), m.size());
    M.reserve(Eigen::VectorXi::Ones(m.size()));
    for (Eigen::Index i = 0; i < m.size(); ++i) M.insert(i, i) = m[i];
    M.makeCompressed();
    return M;
  }
  const BlockPattern pattern(mesh);
  SparseMatrix M = pattern.matrix();
  Eigen::MatrixXd Me;
  for (int e = 0; e < mesh.element_count(); ++e) {
    element_mass(mesh, e, density, kind, Me);
    pattern.add(M, mesh.elements[e], Me);
  }
  return M;
}

SparseMatrix rayleigh_damping(const SparseMatrix& M, const SparseMatrix& K, double alpha, double beta) {
  SparseMatrix C = alpha * M + beta * K;
  C.makeCompressed();
  return C;
}

SparseMatrix theta_lhs(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K, double h, double theta) {
  SparseMatrix A = M + (h * theta) * C + (h * h * theta * theta) * K;
  A.makeCompressed();
  return A;
}

Eigen::VectorXd gravity_load(const Mesh& mesh, double density, const Eigen::VectorXd& gravity) {
  require_size("gravity_load", "gravity", gravity.size(), mesh.dim);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  detail::ElementGeometry g;
  for (int e = 0; e < mesh.element_count(); ++e) {
    g.bind(mesh, e);
    const auto cell = mesh.elements[e];
    for (const QuadraturePoint& q : element_info(g.type).rule) {
      const double w = g.evaluate(q.xi.data()) * q.weight * density;
      for (int a = 0; a < g.nodes; ++a)
        for (int i = 0; i < mesh.dim; ++i) f[mesh.dim * cell[a] + i] += w * g.N[a] * gravity[i];
    }
  }
  return f;
}

Eigen::VectorXd nodal_load(const Mesh& mesh, const std::vector<int>& nodes, const Eigen::VectorXd& force) {
  require_size("nodal_load", "the force", force.size(), mesh.dim);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int n : nodes) f.segment(mesh.dim * n, mesh.dim) += force.head(mesh.dim);
  return f;
}

Eigen::VectorXd traction_load(const Mesh& mesh, const Facets& facets,
                              const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& traction) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  detail::NodeVector N;
  double dN[detail::max_nodes * 3];
  for (int s = 0; s < facets.size(); ++s) {
    const ElementType type = facets.cells.type[s];
    const ElementInfo& info = element_info(type);
    const auto cell = facets.cells[s];
    N.resize(info.nodes);
    for (const QuadraturePoint& q : info.rule) {
      shape_functions(type, q.xi.data(), N.data());
      shape_derivatives(type, q.xi.data(), dN);
      // Tangents ∂x/∂ξ_k; the surface element is |t1| (edge) or |t1 × t2| (face).
      Eigen::Vector3d t[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}, x = Eigen::Vector3d::Zero();
      for (int a = 0; a < info.nodes; ++a) {
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        p.head(mesh.dim) = mesh.x.col(cell[a]);
        x += N[a] * p;
        for (int k = 0; k < info.dim; ++k) t[k] += dN[info.dim * a + k] * p;
      }
      const double jac = info.dim == 1 ? t[0].norm() : t[0].cross(t[1]).norm();
      const Eigen::Vector3d tr = traction(x) * (jac * q.weight);
      for (int a = 0; a < info.nodes; ++a)
        for (int i = 0; i < mesh.dim; ++i) f[mesh.dim * cell[a] + i] += N[a] * tr[i];
    }
  }
  return f;
}

StressField element_stress(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u) {
  require_size("element_stress", "the displacement", u.size(), mesh.dof_count());
  const double lambda = effective_lambda(material), mu = shear_modulus(material);
  StressField s(6, mesh.element_count());
  detail::ElementGeometry g;
  const int d = mesh.dim;
  for (int e = 0; e < mesh.element_count(); ++e) {
    g.bind(mesh, e);
    g.evaluate(element_info(g.type).centre.data());
    const auto cell = mesh.elements[e];
    Eigen::Matrix3d grad = Eigen::Matrix3d::Zero();  // ∂u_i/∂x_j
    for (int a = 0; a < g.nodes; ++a)
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) grad(i, j) += u[d * cell[a] + i] * g.dNdx(a, j);
    const Eigen::Matrix3d eps = 0.5 * (grad + grad.transpose());
    Eigen::Matrix3d sigma = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
    if (d == 2) sigma(2, 2) = material.hypothesis == Hypothesis::plane_strain ? lame_lambda(material) * eps.trace() : 0.0;
    s.col(e) << sigma(0, 0), sigma(1, 1), sigma(2, 2), sigma(0, 1), sigma(1, 2), sigma(0, 2);
  }
  return s;
}

StressField nodal_stress(const Mesh& mesh, const StressField& element_stress) {
  StressField s = StressField::Zero(6, mesh.node_count());
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(mesh.node_count());
  for (int e = 0; e < mesh.element_count(); ++e) {
    const double w = std::abs(element_measure(mesh, e));
    for (int n : mesh.elements[e]) {
      s.col(n) += w * element_stress.col(e);
      weight[n] += w;
    }
  }
  for (int n = 0; n < mesh.node_count(); ++n)
    if (weight[n] > 0) s.col(n) /= weight[n];
  return s;
}

Eigen::VectorXd von_mises(const StressField& s) {
  Eigen::VectorXd v(s.cols());
  for (Eigen::Index i = 0; i < s.cols(); ++i) {
    const auto c = s.col(i);
    v[i] = std::sqrt(0.5 * ((c[0] - c[1]) * (c[0] - c[1]) + (c[1] - c[2]) * (c[1] - c[2]) + (c[2] - c[0]) * (c[2] - c[0])) +
                     3 * (c[3] * c[3] + c[4] * c[4] + c[5] * c[5]));
  }
  return v;
}

Eigen::MatrixXd rigid_body_modes(const Mesh& mesh) {
  const int d = mesh.dim, n = mesh.node_count(), modes = d == 2 ? 3 : 6;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(mesh.dof_count(), modes);
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < d; ++i) R(d * a + i, i) = 1;
    const auto x = mesh.x.col(a);
    if (d == 2) {
      R(2 * a, 2) = -x[1];
      R(2 * a + 1, 2) = x[0];
    } else {
      // ω × x for ω = e_x, e_y, e_z.
      R(3 * a + 1, 3) = -x[2], R(3 * a + 2, 3) = x[1];
      R(3 * a + 0, 4) = x[2], R(3 * a + 2, 4) = -x[0];
      R(3 * a + 0, 5) = -x[1], R(3 * a + 1, 5) = x[0];
    }
  }
  return R;
}

}  // namespace moreau::fem
