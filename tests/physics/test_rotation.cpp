// Rotations on SO(3). A torque-free asymmetric body (I = diag(1, 2, 3), spinning mostly
// about the stable major axis with a wobble) keeps its world angular momentum L = R I Ω
// and its energy: the deviations are discretisation errors and must shrink as h does,
// at the order the θ = 0.5 scheme has (measured and printed).
#include <gtest/gtest.h>

#include <cstdio>

#include "plugins/integrator/theta/rotation.hpp"
#include "sim.hpp"

using namespace moreau_test;
using nlohmann::json;
namespace R = moreau::rigid;

namespace {

struct Drift {
  double momentum = 0;  ///< max |L(t) − L(0)| / |L(0)|
  double energy = 0;    ///< max |E(t) − E(0)| / E(0)
  double quaternion = 0;  ///< max | |q| − 1 |
};

void momentum_energy(const Sim& s, const double I[3], double L[3], double& E) {
  const double* q = s.field(R::orientation).row(0, moreau::Depth::begin).data();
  const double* w = s.field(R::angular_velocity).row(0, moreau::Depth::begin).data();
  double Rm[9], W[3], IW[3];
  moreau::theta::quat_to_matrix(q, Rm);
  moreau::theta::mul_transpose(Rm, w, W);
  for (int k = 0; k < 3; ++k) IW[k] = I[k] * W[k];
  moreau::theta::mul(Rm, IW, L);
  E = 0.5 * (W[0] * IW[0] + W[1] * IW[1] + W[2] * IW[2]);
}

Drift torque_free(double h, double T) {
  const double I[3] = {1, 2, 3};
  Sim s(3, h, 0.5, {0, 0, 0});
  // Orientation tilted so the body and world axes differ; ω in world frame.
  s.add_body("top", {{"position", {0, 0, 0}}, {"mass", 1}, {"inertia", {I[0], I[1], I[2]}},
                     {"orientation", {0.9238795325112867, 0.3826834323650898, 0, 0}},
                     {"angular_velocity", {0.3, -0.4, 5.0}}});
  s.prepare();
  double L0[3], E0;
  momentum_energy(s, I, L0, E0);
  const double n0 = std::sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
  Drift d;
  const long n = std::lround(T / h);
  for (long i = 0; i < n; ++i) {
    s.step();
    double L[3], E;
    momentum_energy(s, I, L, E);
    d.momentum = std::max(d.momentum, std::sqrt(std::pow(L[0] - L0[0], 2) + std::pow(L[1] - L0[1], 2) + std::pow(L[2] - L0[2], 2)) / n0);
    d.energy = std::max(d.energy, std::fabs(E - E0) / E0);
    const double* q = s.field(R::orientation).row(0, moreau::Depth::begin).data();
    d.quaternion = std::max(d.quaternion, std::fabs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1));
  }
  return d;
}

}  // namespace

TEST(Rotation, TorqueFreeAsymmetricBodyConverges) {
  const double T = 5;
  const Drift a = torque_free(0.004, T), b = torque_free(0.002, T), c = torque_free(0.001, T);
  std::printf("torque-free body I=diag(1,2,3), T=%g s, theta=0.5\n", T);
  std::printf("  h       max|dL|/|L|   max|dE|/E    max||q|-1|\n");
  for (auto [h, d] : {std::pair{0.004, a}, std::pair{0.002, b}, std::pair{0.001, c}})
    std::printf("  %.3f   %.3e     %.3e    %.1e\n", h, d.momentum, d.energy, d.quaternion);
  const double pL1 = order(a.momentum, b.momentum), pL2 = order(b.momentum, c.momentum);
  const double pE1 = order(a.energy, b.energy), pE2 = order(b.energy, c.energy);
  std::printf("  orders: momentum %.2f %.2f, energy %.2f %.2f\n", pL1, pL2, pE1, pE2);
  // Both converge; the scheme is second order (midpoint rotation, linearly implicit θ = 0.5).
  EXPECT_GT(pL1, 1.8);
  EXPECT_GT(pL2, 1.8);
  EXPECT_GT(pE1, 1.8);
  EXPECT_GT(pE2, 1.8);
  EXPECT_LT(c.momentum, 1e-3);
  EXPECT_LT(c.quaternion, 1e-14);
}

TEST(Rotation, SpinUpAboutAPrincipalAxis3D) {
  // Constant torque along a principal axis: ω(t) = τ t / I_z exactly, no wobble.
  Sim s(3, 0.01, 0.5, {0, 0, 0});
  s.add_body("wheel", {{"position", {0, 0, 0}}, {"mass", 1}, {"inertia", {1, 2, 3}}});
  s.add_force({{"body", "wheel"}, {"torque", {0, 0, 6}}});
  s.prepare();
  s.run(100);
  const double t = s.time();
  EXPECT_NEAR(s.at(R::angular_velocity, 0, 2), 6.0 / 3.0 * t, 1e-12);
  EXPECT_NEAR(s.at(R::angular_velocity, 0, 0), 0.0, 1e-12);
  // The rotation angle about z: φ = τ t²/(2 I) (θ = 0.5 integrates the linear rate exactly).
  const double phi = 6.0 / 3.0 * t * t / 2;
  EXPECT_NEAR(s.at(R::orientation, 0, 0), std::cos(phi / 2), 1e-12);
  EXPECT_NEAR(s.at(R::orientation, 0, 3), std::sin(phi / 2), 1e-12);
}
