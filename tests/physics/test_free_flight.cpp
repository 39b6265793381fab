// Contact-free translation: free fall and projectile against the analytic answer.
//  - θ = 0.5 integrates a constant acceleration exactly (the trapezoidal rule is exact
//    for the quadratic x(t)), so only rounding remains: tolerance 1e-12 relative.
//  - θ = 1 makes an error of exactly g·t·h/2 in position (first order); the measured
//    order from h and h/2 must be 1 within 0.05.
#include <gtest/gtest.h>

#include <cstdio>

#include "sim.hpp"

using namespace moreau_test;
using nlohmann::json;
namespace R = moreau::rigid;

namespace {

double projectile_error(int dim, double h, double theta, double T) {
  const double g = -9.81;
  Sim s(dim, h, theta, dim == 2 ? std::vector<double>{0, g} : std::vector<double>{0, 0, g});
  json body = dim == 2 ? json{{"position", {1, 2}}, {"velocity", {3, 4}}, {"mass", 2}, {"inertia", 0.5}}
                       : json{{"position", {1, 2, 3}}, {"velocity", {3, -1, 4}}, {"mass", 2}, {"inertia", {1, 1, 1}}};
  s.add_body("p", body);
  s.prepare();
  s.run(std::lround(T / h));
  const double t = s.time();
  const int up = dim - 1;
  const double exact_up = body["position"][up].get<double>() + body["velocity"][up].get<double>() * t + 0.5 * g * t * t;
  const double exact_x = 1 + 3 * t;
  return std::hypot(s.at(R::position, 0, up) - exact_up, s.at(R::position, 0, 0) - exact_x);
}

}  // namespace

TEST(FreeFlight, ThetaHalfIsExactForConstantGravity) {
  for (int dim : {2, 3}) {
    const double e = projectile_error(dim, 0.01, 0.5, 2.0);
    EXPECT_LT(e, 1e-12 * 20) << dim << "D";  // positions of order 20 m: rounding only
    std::printf("%dD projectile, theta=0.5, h=0.01, T=2: position error %.3e m\n", dim, e);
  }
}

TEST(FreeFlight, ThetaOneIsFirstOrder) {
  for (int dim : {2, 3}) {
    const double e1 = projectile_error(dim, 0.01, 1.0, 1.0);
    const double e2 = projectile_error(dim, 0.005, 1.0, 1.0);
    const double e3 = projectile_error(dim, 0.0025, 1.0, 1.0);
    const double p1 = order(e1, e2), p2 = order(e2, e3);
    std::printf("%dD theta=1: errors %.4e %.4e %.4e (h = 0.01, 0.005, 0.0025), orders %.4f %.4f\n", dim, e1, e2, e3, p1, p2);
    EXPECT_NEAR(p1, 1.0, 0.05);
    EXPECT_NEAR(p2, 1.0, 0.05);
    EXPECT_NEAR(e1, 9.81 * 1.0 * 0.01 / 2, 1e-9) << "theta = 1 lags by g t h / 2";
  }
}

TEST(FreeFlight, FixedBodiesNeverMove) {
  Sim s(3, 0.01, 0.5, {0, 0, -9.81});
  s.add_body("wall", {{"fixed", true}, {"position", {1, 2, 3}}, {"velocity", {5, 5, 5}}, {"angular_velocity", {1, 2, 3}}});
  s.prepare();
  s.run(50);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(s.at(R::position, 0, k), 1.0 + k);
    EXPECT_EQ(s.at(R::velocity, 0, k), 0.0);
    EXPECT_EQ(s.at(R::angular_velocity, 0, k), 0.0);
  }
  EXPECT_EQ(s.at(R::orientation, 0, 0), 1.0);
}

TEST(FreeFlight, ImposedComponentsHonouredOthersFree) {
  Sim s(2, 0.01, 0.5, {0, -9.81});
  // Initial velocities match the imposed ones (a jump at t = 0 would lag the θ-scheme by h/2).
  s.add_body("cart", {{"position", {0, 0}}, {"velocity", {0.5, 0}}, {"angular_velocity", 2.0}, {"mass", 1}, {"inertia", 1}});
  auto imp = s.declare_field(R::imposed_velocity).row(0);
  imp[0] = 0.5;          // vx imposed
  imp[1] = std::nan("");  // vy free: falls
  imp[2] = 2.0;          // ω imposed
  s.prepare();
  s.run(100);
  const double t = s.time();
  EXPECT_NEAR(s.at(R::velocity, 0, 0), 0.5, 1e-15);
  EXPECT_NEAR(s.at(R::position, 0, 0), 0.5 * t, 1e-12);
  EXPECT_NEAR(s.at(R::velocity, 0, 1), -9.81 * t, 1e-12);
  EXPECT_NEAR(s.at(R::angle, 0, 0), 2.0 * t, 1e-12);
}

TEST(FreeFlight, ConstantForceAndTorque2D) {
  // m a = F + m g, I ω' = τ: with θ = 0.5 both are exact.
  Sim s(2, 0.01, 0.5, {0, -9.81});
  s.add_body("b", {{"position", {0, 0}}, {"mass", 2}, {"inertia", 0.5}});
  s.add_force({{"body", "b"}, {"force", {4, 19.62}}, {"torque", {1.5}}});
  s.prepare();
  s.run(100);
  const double t = s.time();
  EXPECT_NEAR(s.at(R::position, 0, 0), 0.5 * 2 * t * t, 1e-12);  // a = 2
  EXPECT_NEAR(s.at(R::position, 0, 1), 0.0, 1e-12);              // weight balanced
  EXPECT_NEAR(s.at(R::angular_velocity, 0, 0), 1.5 / 0.5 * t, 1e-12);
  EXPECT_NEAR(s.at(R::angle, 0, 0), 0.5 * 3 * t * t, 1e-12);
}
