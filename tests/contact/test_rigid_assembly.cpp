// W = H M⁻¹ Hᵀ for rigid bodies, checked against hand-derived Delassus blocks.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "kernel/contact/local_frame.hpp"
#include "kernel/contact/rigid_assembly.hpp"

using namespace moreau::kernel;

namespace {

RigidContact contact_3d(int a, int b, std::array<double, 3> p, std::array<double, 3> n) {
  RigidContact c;
  c.body[0] = a;
  c.body[1] = b;
  for (int i = 0; i < 3; ++i) c.point[i] = p[i];
  const Frame3 f = local_frame_3d(n.data());
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c.frame[i][j] = f[i][j];
  return c;
}

/// Sphere (mass m, inertia I, radius R) at the origin on a fixed body 1.
RigidBodies sphere_on_ground(double m, double I) {
  RigidBodies b;
  b.dim = 3;
  b.com = {0, 0, 0, 0, 0, -5};
  b.inverse_mass.assign(2 * 36, 0.0);
  for (int i = 0; i < 3; ++i) b.inverse_mass[i * 6 + i] = 1 / m;
  for (int i = 3; i < 6; ++i) b.inverse_mass[i * 6 + i] = 1 / I;
  b.free_velocity = {1, 2, -3, 0.5, -0.25, 2, 0, 0, 0, 0, 0, 0};
  return b;
}

}  // namespace

TEST(RigidAssembly, SphereOnGroundDelassus) {
  const double m = 2, I = 0.1, R = 0.5;
  RigidBodies bodies = sphere_on_ground(m, I);
  RigidAssembly as;
  as.build(bodies, {contact_3d(0, 1, {0, 0, -R}, {0, 0, 1})});
  Eigen::MatrixXd W(as.W());
  // Normal: 1/m (the lever arm is along n). Tangents: 1/m + R²/I (rolling couples in).
  EXPECT_NEAR(W(0, 0), 1 / m, 1e-14);
  EXPECT_NEAR(W(1, 1), 1 / m + R * R / I, 1e-14);
  EXPECT_NEAR(W(2, 2), 1 / m + R * R / I, 1e-14);
  EXPECT_NEAR(W(0, 1), 0, 1e-14);
  EXPECT_NEAR(W(1, 2), 0, 1e-14);
  // u = H v: normal relative velocity is v_z (ground at rest), tangential includes ω × r.
  Eigen::VectorXd u = as.free_local_velocity(bodies);
  EXPECT_NEAR(u[0], -3, 1e-14);
  const Frame3 f = local_frame_3d(std::array<double, 3>{0, 0, 1}.data());
  const double w[3] = {0.5, -0.25, 2}, r[3] = {0, 0, -R};
  const double wxr[3] = {w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2], w[0] * r[1] - w[1] * r[0]};
  const double vc[3] = {1 + wxr[0], 2 + wxr[1], -3 + wxr[2]};
  EXPECT_NEAR(u[1], f[1][0] * vc[0] + f[1][1] * vc[1] + f[1][2] * vc[2], 1e-14);
}

TEST(RigidAssembly, ImpulsesAreTheTransposeAndWIsSymmetric) {
  // Two free spheres touching, and one on the ground: W couples contacts through body 0.
  RigidBodies b;
  b.dim = 3;
  b.com = {0, 0, 0, 1, 0, 0, 0, 0, -5};
  b.inverse_mass.assign(3 * 36, 0.0);
  for (int body = 0; body < 2; ++body) {
    for (int i = 0; i < 3; ++i) b.inverse_mass[body * 36 + i * 6 + i] = 1.0 / (1 + body);
    for (int i = 3; i < 6; ++i) b.inverse_mass[body * 36 + i * 6 + i] = 10.0 / (1 + body);
  }
  b.free_velocity.assign(18, 0.0);
  RigidAssembly as;
  as.build(b, {contact_3d(1, 0, {0.5, 0, 0}, {1, 0, 0}), contact_3d(0, 2, {0, 0, -0.5}, {0, 0, 1})});
  Eigen::MatrixXd W(as.W());
  EXPECT_TRUE(W.isApprox(W.transpose(), 1e-14));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(W);
  EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12);
  // W r = H M⁻¹ Hᵀ r, computed the long way through body impulses.
  Eigen::VectorXd r(6);
  r << 1, 0.2, -0.3, 2, 0.1, 0.4;
  std::vector<double> P;
  as.body_impulses(r, 3, P);
  std::vector<double> dv(18, 0.0);
  for (int body = 0; body < 3; ++body)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) dv[body * 6 + i] += b.inverse_mass[body * 36 + i * 6 + j] * P[body * 6 + j];
  Eigen::VectorXd Wr = as.local_velocity(dv);
  EXPECT_TRUE(Wr.isApprox(W * r, 1e-12)) << Wr.transpose() << "\n" << (W * r).transpose();
}

TEST(RigidAssembly, DiskOnGround2D) {
  const double m = 3, I = 0.2, R = 0.4;
  RigidBodies b;
  b.dim = 2;
  b.com = {0, 0, 0, 0, -5, 0};
  b.inverse_mass = {1 / m, 0, 0, 0, 1 / m, 0, 0, 0, 1 / I, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  b.free_velocity = {1, -2, 3, 0, 0, 0};
  RigidContact c;
  c.body[0] = 0;
  c.body[1] = 1;
  c.point[1] = -R;
  const double n[2] = {0, 1};
  auto f = local_frame_2d(n);
  c.frame[0][0] = f[0][0]; c.frame[0][1] = f[0][1];
  c.frame[1][0] = f[1][0]; c.frame[1][1] = f[1][1];
  RigidAssembly as;
  as.build(b, {c});
  Eigen::MatrixXd W(as.W());
  EXPECT_NEAR(W(0, 0), 1 / m, 1e-14);
  EXPECT_NEAR(W(1, 1), 1 / m + R * R / I, 1e-14);
  Eigen::VectorXd u = as.free_local_velocity(b);
  EXPECT_NEAR(u[0], -2, 1e-14);
  // t = (-1, 0); contact point velocity v + ω ẑ × r = (1 + 3·R, -2)
  EXPECT_NEAR(u[1], -(1 + 3 * R), 1e-14);
}
