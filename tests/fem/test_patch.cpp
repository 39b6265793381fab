// Patch tests (Irons): on irregular patches of every element type, a linear displacement
// field imposed on the boundary is reproduced exactly inside, with exactly constant stress;
// and the constant stress applied as a traction is reproduced the same way.
#include <gtest/gtest.h>

#include "dof_partition.hpp"
#include "fem_test_util.hpp"
#include "sparse_cholesky.hpp"

namespace moreau::fem {
namespace {

struct Patch {
  Mesh mesh;
  Material material;
};

std::vector<Patch> patches() {
  std::vector<Patch> p;
  for (ElementType t : {ElementType::T3, ElementType::Q4})
    for (Hypothesis h : {Hypothesis::plane_strain, Hypothesis::plane_stress}) {
      Mesh m = rectangle_mesh({0.2, -0.1}, {2, 1.5}, 0.5, t);
      test::distort_interior(m, 0.5, 0.25);
      p.push_back({std::move(m), test::steel(h)});
    }
  for (ElementType t : {ElementType::T4, ElementType::H8}) {
    Mesh m = box_mesh({0.1, 0, -0.2}, {1.5, 1, 1.2}, 0.4, t);
    test::distort_interior(m, 0.4, 0.25);
    p.push_back({std::move(m), test::steel(Hypothesis::solid)});
  }
  return p;
}

/// u(x) = a + B x with a general B (stretch, shear and rotation).
Eigen::VectorXd linear_field(const Mesh& m, Eigen::Matrix3d& B) {
  B << 1.0e-3, 2.0e-4, -3.0e-4, -4.0e-4, 0.5e-3, 1.0e-4, 2.5e-4, -1.5e-4, -0.8e-3;
  const Eigen::Vector3d a(1e-4, -2e-4, 3e-4);
  Eigen::VectorXd u(m.dof_count());
  for (int n = 0; n < m.node_count(); ++n) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x.head(m.dim) = m.x.col(n);
    u.segment(m.dim * n, m.dim) = (a + B * x).head(m.dim);
  }
  return u;
}

/// Solves K u = f with the DOFs of `fixed_nodes` imposed to the exact field's values.
Eigen::VectorXd solve_imposed(const Mesh& m, const Material& mat, const std::vector<int>& fixed_nodes,
                              const Eigen::VectorXd& f, const Eigen::VectorXd& exact) {
  const DofPartition dofs(m.dof_count(), node_dofs(m, fixed_nodes));
  const SparseMatrix K = stiffness_matrix(m, mat);
  SparseCholesky chol;
  chol.factorize(dofs.free_block(K));
  const Eigen::VectorXd uc = dofs.constrained_part(exact);
  return dofs.combine(chol.solve(Eigen::VectorXd(dofs.free_part(f) - dofs.coupling_block(K) * uc)), uc);
}

/// The exact stress of that field (VTK order), with σzz of the 2D hypotheses.
Eigen::Matrix<double, 6, 1> exact_stress(const Mesh& m, const Material& mat, const Eigen::Matrix3d& B) {
  const int d = m.dim;
  const Eigen::MatrixXd D = elasticity_matrix(mat);
  Eigen::VectorXd eps(d == 2 ? 3 : 6);
  const Eigen::Matrix3d e = 0.5 * (B + B.transpose());
  if (d == 2) eps << e(0, 0), e(1, 1), 2 * e(0, 1);
  else eps << e(0, 0), e(1, 1), e(2, 2), 2 * e(1, 2), 2 * e(0, 2), 2 * e(0, 1);
  const Eigen::VectorXd s = D * eps;
  Eigen::Matrix<double, 6, 1> out;
  if (d == 2) {
    const double nu = mat.poisson;
    out << s[0], s[1], mat.hypothesis == Hypothesis::plane_strain ? nu * (s[0] + s[1]) : 0.0, s[2], 0, 0;
  } else {
    out << s[0], s[1], s[2], s[5], s[3], s[4];
  }
  return out;
}

TEST(FemPatch, DisplacementPatchTestEveryElementType) {
  for (const Patch& p : patches()) {
    const Mesh& m = p.mesh;
    SCOPED_TRACE(std::string(element_info(m.elements.type[0]).name) + " " + test::hypothesis_name(p.material.hypothesis));
    Eigen::Matrix3d B;
    const Eigen::VectorXd exact = linear_field(m, B);
    ASSERT_LT(m.node_set("boundary").size(), static_cast<std::size_t>(m.node_count()));  // interior nodes exist
    const Eigen::VectorXd u =
        solve_imposed(m, p.material, m.node_set("boundary"), Eigen::VectorXd::Zero(m.dof_count()), exact);
    // Exact to rounding: errors of the order of the condition number times 1e-16.
    EXPECT_LT((u - exact).lpNorm<Eigen::Infinity>(), 1e-12 * exact.lpNorm<Eigen::Infinity>());
    const StressField s = element_stress(m, p.material, u);
    const Eigen::Matrix<double, 6, 1> expected = exact_stress(m, p.material, B);
    for (int e = 0; e < m.element_count(); ++e)
      ASSERT_LT((s.col(e) - expected).norm(), 1e-9 * expected.norm()) << "element " << e;
  }
}

TEST(FemPatch, TractionPatchTestEveryElementType) {
  for (const Patch& p : patches()) {
    const Mesh& m = p.mesh;
    SCOPED_TRACE(std::string(element_info(m.elements.type[0]).name) + " " + test::hypothesis_name(p.material.hypothesis));
    Eigen::Matrix3d B;
    const Eigen::VectorXd exact = linear_field(m, B);
    const Eigen::Matrix<double, 6, 1> s = exact_stress(m, p.material, B);
    Eigen::Matrix3d sigma;
    sigma << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    // Traction σ·n on the whole boundary (outward normals); the rigid motion is fixed by
    // imposing the exact field on the first element's nodes (no reaction: it is exact).
    const Facets& boundary = m.boundary_set("boundary");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m.dof_count());
    for (int i = 0; i < boundary.size(); ++i) {
      Facets one;
      one.cells.add(boundary.cells.type[i], boundary.cells[i]);
      const Eigen::Vector3d n = facet_normal(m, boundary, i);
      f += traction_load(m, one, [&](const Eigen::Vector3d&) { return Eigen::Vector3d(sigma * n); });
    }
    const auto first = m.elements[0];
    const Eigen::VectorXd u = solve_imposed(m, p.material, std::vector<int>(first.begin(), first.end()), f, exact);
    EXPECT_LT((u - exact).lpNorm<Eigen::Infinity>(), 1e-10 * exact.lpNorm<Eigen::Infinity>());
  }
}

}  // namespace
}  // namespace moreau::fem
