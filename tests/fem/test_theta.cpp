// The θ-scheme of eq. 6 on assembled matrices. Started on a vibration mode, the FE scheme
// must follow exactly the scalar θ-scheme of that mode (M and K are diagonal in the modal
// basis, and so is Rayleigh damping): energy kept to rounding at θ = 0.5 without damping,
// lost at θ > 0.5 as the scalar recursion says. Imposed velocities and impulses too.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "fem_test_util.hpp"
#include "modal.hpp"
#include "theta_scheme.hpp"

namespace moreau::fem {
namespace {

struct Beam {
  Mesh mesh = rectangle_mesh({0, -0.5}, {10, 1}, 0.5, ElementType::Q4);
  Material mat{200e9, 0.3, 7800, Hypothesis::plane_stress};
  SparseMatrix K = stiffness_matrix(mesh, mat), M = mass_matrix(mesh, mat.density, MassKind::consistent);
  DofPartition dofs{mesh.dof_count(), node_dofs(mesh, mesh.node_set("xmin"))};
};

double energy(const SparseMatrix& M, const SparseMatrix& K, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  return 0.5 * v.dot(M * v) + 0.5 * u.dot(K * u);
}

TEST(FemTheta, ModalInitialConditionFollowsTheScalarScheme) {
  const Beam b;
  const Modes mode = lowest_modes(b.dofs.free_block(b.K), b.dofs.free_block(b.M), 1);
  const double w2 = mode.omega2[0], w = std::sqrt(w2), period = 2 * M_PI / w;
  const Eigen::VectorXd zero_c = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(b.dofs.constrained().size()));
  const Eigen::VectorXd phi = b.dofs.combine(mode.vectors.col(0), zero_c);  // φᵀMφ = 1
  const Eigen::VectorXd f = Eigen::VectorXd::Zero(b.mesh.dof_count());
  struct Case {
    double theta, alpha, beta;
  };
  for (const Case c : {Case{0.5, 0, 0}, Case{0.55, 0, 0}, Case{1.0, 0, 0}, Case{0.5, 0.5, 1e-5}}) {
    SCOPED_TRACE("theta " + std::to_string(c.theta) + " alpha " + std::to_string(c.alpha));
    const double h = period / 40;
    const SparseMatrix C = rayleigh_damping(b.M, b.K, c.alpha, c.beta);
    const LinearThetaScheme scheme(b.M, C, b.K, h, c.theta, b.dofs);
    Eigen::VectorXd u = 1e-3 * phi, v = Eigen::VectorXd::Zero(b.mesh.dof_count());
    double q = 1e-3, p = 0;  // the mode's coordinate and velocity under the scalar scheme
    const double cw = c.alpha + c.beta * w2, e0 = energy(b.M, b.K, u, v);
    double previous = e0;
    for (int step = 0; step < 200; ++step) {
      const Eigen::VectorXd v_next = scheme.free_velocity(u, v, f, f, zero_c);
      u = scheme.displacement(u, v, v_next);
      v = v_next;
      // Scalar: (1 + hθc + h²θ²ω²) p⁺ = (1 − h(1−θ)c − h²θ(1−θ)ω²) p − hω² q.
      const double th = c.theta;
      const double p_next = ((1 - h * (1 - th) * cw - h * h * th * (1 - th) * w2) * p - h * w2 * q) /
                            (1 + h * th * cw + h * h * th * th * w2);
      q += h * ((1 - th) * p + th * p_next);
      p = p_next;
      const double e = energy(b.M, b.K, u, v);
      ASSERT_NEAR(e, 0.5 * (p * p + w2 * q * q), 1e-9 * e0) << "step " << step;
      ASSERT_LT((u - q * phi).norm(), 1e-9 * 1e-3 * phi.norm()) << "step " << step;
      if (c.theta == 0.5 && c.alpha == 0) ASSERT_NEAR(e, e0, 1e-11 * e0);  // trapezoidal rule: exact energy
      else ASSERT_LT(e, previous * (1 + 1e-12));                         // dissipative
      previous = e;
    }
    if (c.theta > 0.5 || c.alpha > 0) EXPECT_LT(previous, 0.99 * e0);
  }
}

TEST(FemTheta, ImposedVelocityCarriesARigidTranslation) {
  // Every xmin node moves at v0 and the body starts at v0: it must translate as a whole
  // (K and stiffness-proportional damping annihilate the rigid motion), which needs the
  // LHS_fc coupling right. (Mass-proportional damping αM would brake it: it damps absolute
  // velocities.)
  const Beam b;
  const LinearThetaScheme scheme(b.M, rayleigh_damping(b.M, b.K, 0, 1e-4), b.K, 1e-4, 0.7, b.dofs);
  Eigen::VectorXd v(b.mesh.dof_count()), u = Eigen::VectorXd::Zero(b.mesh.dof_count());
  for (int n = 0; n < b.mesh.node_count(); ++n) v.segment(2 * n, 2) << 0.3, -0.2;
  const Eigen::VectorXd imposed = b.dofs.constrained_part(v), f = Eigen::VectorXd::Zero(b.mesh.dof_count());
  for (int step = 0; step < 10; ++step) {
    const Eigen::VectorXd next = scheme.free_velocity(u, v, f, f, imposed);
    ASSERT_LT((next - v).norm(), 1e-12 * v.norm());
    u = scheme.displacement(u, v, next);
  }
  EXPECT_NEAR(u[1], -0.2 * 10 * 1e-4, 1e-15);
}

TEST(FemTheta, ImpulseResponseInvertsTheFreeBlock) {
  const Beam b;
  const double h = 1e-4, theta = 0.5;
  const SparseMatrix C = rayleigh_damping(b.M, b.K, 0, 0);
  const LinearThetaScheme scheme(b.M, C, b.K, h, theta, b.dofs);
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(b.mesh.dof_count(), 2);
  const int tip = b.mesh.node_set("xmax").back();
  P(2 * tip + 1, 0) = 1;
  P(2 * tip, 1) = 1;
  const Eigen::MatrixXd V = scheme.impulse_responses(P);
  const SparseMatrix lhs = theta_lhs(b.M, C, b.K, h, theta);
  const Eigen::MatrixXd back = lhs * V;
  for (int dof : b.dofs.free()) EXPECT_NEAR((back.row(dof) - P.row(dof)).norm(), 0, 1e-10);
  for (int dof : b.dofs.constrained()) EXPECT_EQ(V.row(dof).norm(), 0);
  EXPECT_LT((V.col(0) - scheme.impulse_response(Eigen::VectorXd(P.col(0)))).norm(), 1e-15 * V.col(0).norm());
}

TEST(FemTheta, BadArguments) {
  const Beam b;
  EXPECT_THROW(LinearThetaScheme(b.M, b.M, b.K, 1e-3, 0.4, b.dofs), std::invalid_argument);
  EXPECT_THROW(LinearThetaScheme(b.M, b.M, b.K, 0, 0.5, b.dofs), std::invalid_argument);
  const LinearThetaScheme s(b.M, b.M, b.K, 1e-3, 0.5, b.dofs);
  const Eigen::VectorXd z = Eigen::VectorXd::Zero(b.mesh.dof_count());
  EXPECT_THROW(s.free_velocity(z, z, z, z, Eigen::VectorXd()), std::invalid_argument);
}

}  // namespace
}  // namespace moreau::fem
