// Global matrices and loads: mass sums to the body's mass, rigid-body modes span the null
// space of K exactly, loads sum to their resultants, and the θ-scheme's matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <numbers>

#include "fem_test_util.hpp"

namespace moreau::fem {
namespace {

struct Case {
  const char* name;
  Mesh mesh;
  double volume;  // analytic (disk: the inscribed polygon)
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"rectangle T3", rectangle_mesh({0, 0}, {2, 1}, 0.2, ElementType::T3), 2.0});
  c.push_back({"rectangle Q4", rectangle_mesh({0, 0}, {2, 1}, 0.2, ElementType::Q4), 2.0});
  c.push_back({"box T4", box_mesh({0, 0, 0}, {1, 0.5, 0.5}, 0.25, ElementType::T4), 0.25});
  c.push_back({"box H8", box_mesh({0, 0, 0}, {1, 0.5, 0.5}, 0.25, ElementType::H8), 0.25});
  for (ElementType t : {ElementType::T3, ElementType::Q4}) {
    Mesh d = disk_mesh({0, 0}, 1, 0.2, t);
    const int nb = d.boundary_set("boundary").size();
    c.push_back({t == ElementType::T3 ? "disk T3" : "disk Q4", std::move(d), 0.5 * nb * std::sin(2 * std::numbers::pi / nb)});
  }
  // Irregular elements too: interior nodes moved (the volume does not change).
  for (Case& k : std::vector<Case>(c.begin(), c.begin() + 4)) {
    test::distort_interior(k.mesh, 0.2, 0.2);
    c.push_back({"distorted", std::move(k.mesh), k.volume});
  }
  return c;
}

TEST(FemMatrices, MassSumsToTheBodyMassForEachComponent) {
  const double rho = 2500;
  for (const Case& k : cases()) {
    for (MassKind kind : {MassKind::consistent, MassKind::lumped}) {
      SCOPED_TRACE(std::string(k.name) + (kind == MassKind::lumped ? " lumped" : " consistent"));
      const SparseMatrix M = mass_matrix(k.mesh, rho, kind);
      const Eigen::MatrixXd R = rigid_body_modes(k.mesh);
      for (int i = 0; i < k.mesh.dim; ++i)  // translation i: tᵀ M t = total mass
        EXPECT_NEAR(R.col(i).dot(M * R.col(i)), rho * k.volume, 1e-12 * rho * k.volume);
      // No coupling between components.
      EXPECT_NEAR(R.col(0).dot(M * R.col(1)), 0, 1e-12 * rho * k.volume);
      if (kind == MassKind::lumped) {
        const Eigen::VectorXd m = lumped_mass(k.mesh, rho);
        EXPECT_GT(m.minCoeff(), 0);
        EXPECT_LT((Eigen::VectorXd(M.diagonal()) - m).norm(), 1e-12 * m.norm());
      }
    }
  }
}

TEST(FemMatrices, RigidBodyModesSpanTheNullSpace) {
  const Material mats[] = {test::steel(Hypothesis::plane_strain), test::steel(Hypothesis::plane_stress),
                           test::steel(Hypothesis::solid)};
  for (const Case& k : cases()) {
    SCOPED_TRACE(k.name);
    for (const Material& mat : mats) {
      if ((mat.hypothesis == Hypothesis::solid) != (k.mesh.dim == 3)) continue;
      const SparseMatrix K = stiffness_matrix(k.mesh, mat);
      const Eigen::MatrixXd R = rigid_body_modes(k.mesh);
      const double scale = Eigen::MatrixXd(K).norm() * R.norm();
      EXPECT_LT((K * R).norm(), 1e-13 * scale);
      EXPECT_LT((Eigen::MatrixXd(K) - Eigen::MatrixXd(K).transpose()).norm(), 1e-14 * Eigen::MatrixXd(K).norm());
    }
  }
  // …and nothing else: exactly 3 (2D) or 6 (3D) zero eigenvalues on small meshes, so full
  // integration leaves no spurious zero-energy (hourglass) mode.
  const std::pair<Mesh, int> small[] = {
      {rectangle_mesh({0, 0}, {2, 1}, 0.5, ElementType::Q4), 3}, {rectangle_mesh({0, 0}, {2, 1}, 0.5, ElementType::T3), 3},
      {box_mesh({0, 0, 0}, {1, 1, 1}, 0.5, ElementType::H8), 6},  {box_mesh({0, 0, 0}, {1, 1, 1}, 0.5, ElementType::T4), 6},
      {test::one_element(ElementType::H8), 6},                   {test::one_element(ElementType::Q4), 3}};
  for (const auto& [mesh, zeros] : small) {
    const Material mat = test::steel(mesh.dim == 3 ? Hypothesis::solid : Hypothesis::plane_strain);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(stiffness_matrix(mesh, mat))).eigenvalues();
    int count = 0;
    for (Eigen::Index i = 0; i < ev.size(); ++i) count += std::abs(ev[i]) < 1e-10 * ev.maxCoeff();
    EXPECT_EQ(count, zeros) << element_info(mesh.elements.type[0]).name;
    EXPECT_GT(ev[zeros], 1e-4 * ev.maxCoeff());  // the first non-zero one is well away from zero
  }
}

TEST(FemMatrices, LoadsSumToTheirResultants) {
  for (const Case& k : cases()) {
    SCOPED_TRACE(k.name);
    const int d = k.mesh.dim;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(d);
    g[d - 1] = -9.81;
    g[0] = 1.5;
    const Eigen::VectorXd f = gravity_load(k.mesh, 1000, g);
    const Eigen::MatrixXd R = rigid_body_modes(k.mesh);
    for (int i = 0; i < d; ++i) EXPECT_NEAR(R.col(i).dot(f), 1000 * k.volume * g[i], 1e-12 * 1000 * k.volume * 10);
    // Consistent gravity equals M_consistent times the uniform acceleration.
    Eigen::VectorXd a(k.mesh.dof_count());
    for (int n = 0; n < k.mesh.node_count(); ++n) a.segment(d * n, d) = g;
    EXPECT_LT((mass_matrix(k.mesh, 1000, MassKind::consistent) * a - f).norm(), 1e-12 * f.norm());
  }
  // A uniform traction on the whole boundary sums to traction × boundary measure; a linear
  // one (t = x) to ∫ x dS (exact for straight edges and flat faces, the rule being exact for
  // linear integrands).
  const Mesh box = box_mesh({0, 0, 0}, {1, 2, 3}, 0.5, ElementType::H8);
  const Eigen::MatrixXd R = rigid_body_modes(box);
  const Eigen::VectorXd f = traction_load(box, box.boundary_set("zmax"), [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(1.0, 0.0, x.x());
  });
  EXPECT_NEAR(R.col(0).dot(f), 2.0, 1e-13);       // area of z = 3 is 1 × 2
  EXPECT_NEAR(R.col(2).dot(f), 2.0 * 0.5, 1e-13);  // ∫ x dS = area × mean x
  const Mesh rect = rectangle_mesh({0, 0}, {2, 1}, 0.3, ElementType::T3);
  const Eigen::VectorXd f2 = traction_load(rect, rect.boundary_set("boundary"), [](const Eigen::Vector3d&) {
    return Eigen::Vector3d(0.0, 2.0, 0.0);
  });
  EXPECT_NEAR(rigid_body_modes(rect).col(1).dot(f2), 2.0 * 6.0, 1e-12);
  // Nodal forces.
  const Eigen::VectorXd fn = nodal_load(rect, rect.node_set("xmax"), Eigen::Vector2d(0, -3));
  EXPECT_NEAR(fn.sum(), -3.0 * rect.node_set("xmax").size(), 1e-12);
  // Vectors of the wrong size are refused.
  EXPECT_THROW(gravity_load(rect, 1000, Eigen::Vector3d(0, 0, -9.81)), std::invalid_argument);
  EXPECT_THROW(nodal_load(rect, {0}, Eigen::Vector3d(0, 0, 1)), std::invalid_argument);
  EXPECT_THROW(element_stress(rect, test::steel(Hypothesis::plane_stress), Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

TEST(FemMatrices, ElementMatricesAreSymmetricAndTheThetaMatrixIsEquationSix) {
  for (ElementType type : test::volume_types()) {
    const Mesh m = test::one_element(type);
    Eigen::MatrixXd Ke, Me;
    element_stiffness(m, 0, test::steel(m.dim == 3 ? Hypothesis::solid : Hypothesis::plane_stress), Ke);
    element_mass(m, 0, 1000, MassKind::consistent, Me);
    EXPECT_LT((Ke - Ke.transpose()).norm(), 1e-14 * Ke.norm());
    EXPECT_LT((Me - Me.transpose()).norm(), 1e-14 * Me.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Me).eigenvalues().minCoeff(), 0);
  }
  const Mesh m = rectangle_mesh({0, 0}, {1, 1}, 0.5, ElementType::Q4);
  const SparseMatrix K = stiffness_matrix(m, test::steel(Hypothesis::plane_strain));
  const SparseMatrix M = mass_matrix(m, 7800, MassKind::consistent);
  const SparseMatrix C = rayleigh_damping(M, K, 2.0, 1e-4);
  const double h = 1e-3, theta = 0.6;
  const Eigen::MatrixXd expected = Eigen::MatrixXd(M) + h * theta * (2.0 * Eigen::MatrixXd(M) + 1e-4 * Eigen::MatrixXd(K)) +
                                   h * h * theta * theta * Eigen::MatrixXd(K);
  EXPECT_LT((Eigen::MatrixXd(theta_lhs(M, C, K, h, theta)) - expected).norm(), 1e-14 * expected.norm());
}

TEST(FemMatrices, StressRecoveryAndVonMises) {
  // A uniaxial stress state σxx = s: von Mises = |s|; plane strain adds σzz = ν s.
  const Mesh m = rectangle_mesh({0, 0}, {1, 1}, 0.5, ElementType::Q4);
  const Material mat = test::steel(Hypothesis::plane_stress);
  const double s = 1e6, E = mat.young, nu = mat.poisson;
  Eigen::VectorXd u(m.dof_count());
  for (int n = 0; n < m.node_count(); ++n) u.segment(2 * n, 2) << s / E * m.x(0, n), -nu * s / E * m.x(1, n);
  const StressField sigma = element_stress(m, mat, u);
  for (int e = 0; e < m.element_count(); ++e) {
    EXPECT_NEAR(sigma(0, e), s, 1e-6 * s);
    EXPECT_NEAR(sigma.col(e).tail(5).norm(), 0, 1e-6 * s);
  }
  EXPECT_NEAR(von_mises(sigma)[0], s, 1e-6 * s);
  const StressField nodal = nodal_stress(m, sigma);
  EXPECT_NEAR(nodal(0, 4), s, 1e-6 * s);
  // Pure shear τ: von Mises √3 τ.
  StressField shear = StressField::Zero(6, 1);
  shear(3, 0) = 2.0;
  EXPECT_NEAR(von_mises(shear)[0], 2.0 * std::sqrt(3.0), 1e-15);
}

}  // namespace
}  // namespace moreau::fem
