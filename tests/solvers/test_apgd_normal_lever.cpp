// apgd::normal_lever, the measure by which `auto` picks APGD's scaling in a time
// step (normal_lever.hpp): body factors built from rigid kinematics (a contact point, its
// normal and tangents, the bodies' centres and inverse masses), so that round bodies
// (normals through the centres) and blocks (contacts at their corners) are what the
// time-stepper gives.
#include <gtest/gtest.h>

#include <Eigen/Geometry>  // unitOrthogonal, cross
#include <cmath>

#include "normal_lever.hpp"

namespace {

using moreau::BodyFactor;

/// Appends one side of a 2D contact (point p, normal n, tangent t = (-n_y, n_x)) on the body
/// centred at c: rows e · (v + ω ẑ × r), r = p − c.
void side_2d(BodyFactor& f, int body, Eigen::Vector2d c, Eigen::Vector2d p, Eigen::Vector2d n) {
  const Eigen::Vector2d r = p - c, t(-n.y(), n.x());
  for (const Eigen::Vector2d& e : {n, t}) {
    f.H.push_back(e.x());
    f.H.push_back(e.y());
    f.H.push_back(e.dot(Eigen::Vector2d(-r.y(), r.x())));
  }
  f.body.push_back(body);
}

/// One side of a 3D contact: rows [e, r × e] for e = n, t1, t2.
void side_3d(BodyFactor& f, int body, Eigen::Vector3d c, Eigen::Vector3d p, Eigen::Vector3d n) {
  const Eigen::Vector3d r = p - c;
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  for (const Eigen::Vector3d& e : {n, t1, t2}) {
    const Eigen::Vector3d rot = r.cross(e);
    for (int i = 0; i < 3; ++i) f.H.push_back(e[i]);
    for (int i = 0; i < 3; ++i) f.H.push_back(rot[i]);
  }
  f.body.push_back(body);
}
void fixed_side(BodyFactor& f, int d) {
  f.H.insert(f.H.end(), static_cast<std::size_t>(d * f.k), 0.0);
  f.body.push_back(-1);
}
/// A body's inverse mass, diagonal (m, m[, m], I…) or the given k × k matrix.
void body(BodyFactor& f, const Eigen::MatrixXd& Mi) {
  for (int i = 0; i < f.k; ++i)
    for (int j = 0; j < f.k; ++j) f.inverse_mass.push_back(Mi(i, j));
}

TEST(ApgdNormalLever, DisksOnAFloorAndOnEachOtherHaveNone) {
  // Three disks (radii 1, 0.5, 0.7; different masses): two on the floor, the third on both.
  BodyFactor f;
  f.k = 3;
  const Eigen::Vector2d c0(0, 1), c1(1.6, 0.5), c2(0.9, 2.0);
  body(f, Eigen::Vector3d(1 / 3.0, 1 / 3.0, 1 / 1.5).asDiagonal().toDenseMatrix());
  body(f, Eigen::Vector3d(1.0, 1.0, 8.0).asDiagonal().toDenseMatrix());
  body(f, Eigen::Vector3d(0.5, 0.5, 2.0).asDiagonal().toDenseMatrix());
  auto on_floor = [&](int b, Eigen::Vector2d c, double R) {
    side_2d(f, b, c, c - Eigen::Vector2d(0, R), Eigen::Vector2d(0, 1));
    fixed_side(f, 2);
  };
  auto between = [&](int a, Eigen::Vector2d ca, double Ra, int b, Eigen::Vector2d cb) {
    const Eigen::Vector2d n = (cb - ca).normalized();
    side_2d(f, a, ca, ca + Ra * n, -n);
    side_2d(f, b, cb, ca + Ra * n, n);
  };
  on_floor(0, c0, 1);
  on_floor(1, c1, 0.5);
  between(0, c0, 1, 2, c2);
  between(1, c1, 0.5, 2, c2);
  EXPECT_LT(moreau::apgd::normal_lever(2, f), 1e-12);
  EXPECT_TRUE(moreau::apgd::round_contacts(2, f));
}

TEST(ApgdNormalLever, ABrickOnItsCornersTurnsThroughItsNormals) {
  // A 2 × 1 brick of mass 2 (I = m (w² + h²) / 12 = 5/6) on the floor at its two lower
  // corners r = (±1, −0.5), normal (0, 1): W_nn = 1/m + r_x²/I = 0.5 + 1.2, of which 1.2
  // through the rotation.
  BodyFactor f;
  f.k = 3;
  body(f, Eigen::Vector3d(0.5, 0.5, 1.2).asDiagonal().toDenseMatrix());
  const Eigen::Vector2d c(3, 0.5);
  for (double sx : {-1.0, 1.0}) {
    side_2d(f, 0, c, c + Eigen::Vector2d(sx, -0.5), Eigen::Vector2d(0, 1));
    fixed_side(f, 2);
  }
  EXPECT_NEAR(moreau::apgd::normal_lever(2, f), 1.2 / 1.7, 1e-12);
  EXPECT_FALSE(moreau::apgd::round_contacts(2, f));
  // A compliant law adds to W_nn, not through the rotation.
  f.diagonal = {1.0, 1.0, 1.0, 1.0};
  EXPECT_NEAR(moreau::apgd::normal_lever(2, f), 1.2 / 2.7, 1e-12);
  // Stacked on another brick (moving) instead of the floor: both bodies turn, the share
  // is the same (the lower brick's r = (±1, +0.5) gives the same r_x²/I).
  BodyFactor g;
  g.k = 3;
  body(g, Eigen::Vector3d(0.5, 0.5, 1.2).asDiagonal().toDenseMatrix());
  body(g, Eigen::Vector3d(0.5, 0.5, 1.2).asDiagonal().toDenseMatrix());
  const Eigen::Vector2d below(3, -0.5);
  for (double sx : {-1.0, 1.0}) {
    side_2d(g, 0, c, c + Eigen::Vector2d(sx, -0.5), Eigen::Vector2d(0, 1));
    side_2d(g, 1, below, c + Eigen::Vector2d(sx, -0.5), Eigen::Vector2d(0, -1));
  }
  EXPECT_NEAR(moreau::apgd::normal_lever(2, g), 2.4 / 3.4, 1e-12);
}

TEST(ApgdNormalLever, SpheresHaveNoneAndABoxOnItsCornersHasMost) {
  BodyFactor f;
  f.k = 6;
  Eigen::VectorXd m(6);
  m << 1, 1, 1, 2.5, 2.5, 2.5;  // a unit sphere of mass 1: I = 2/5
  body(f, m.asDiagonal().toDenseMatrix());
  body(f, (0.5 * m).asDiagonal().toDenseMatrix());
  const Eigen::Vector3d c0(0, 0, 1), c1(0.6, 1.2, 2.0);
  side_3d(f, 0, c0, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1));
  fixed_side(f, 3);
  const Eigen::Vector3d n = (c1 - c0).normalized();
  side_3d(f, 0, c0, c0 + n, -n);
  side_3d(f, 1, c1, c0 + n, n);
  EXPECT_LT(moreau::apgd::normal_lever(3, f), 1e-12);
  EXPECT_TRUE(moreau::apgd::round_contacts(3, f));

  // A 1 × 0.8 × 0.6 box of mass 1 (I = (b² + c², a² + c², a² + b²) / 12) on the floor at
  // its four lower corners.
  BodyFactor g;
  g.k = 6;
  Eigen::VectorXd mb(6);
  mb << 1, 1, 1, 12 / 1.0, 12 / 1.36, 12 / 1.64;
  body(g, mb.asDiagonal().toDenseMatrix());
  const Eigen::Vector3d c(0, 0, 0.3);
  for (double sx : {-0.5, 0.5})
    for (double sy : {-0.4, 0.4}) {
      side_3d(g, 0, c, c + Eigen::Vector3d(sx, sy, -0.3), Eigen::Vector3d(0, 0, 1));
      fixed_side(g, 3);
    }
  // r × n = (r_y, −r_x, 0): (0.16 · 12 + 0.25 · 12/1.36) through the rotation, 1 not.
  const double rot = 0.16 * 12 + 0.25 * 12 / 1.36;
  EXPECT_NEAR(moreau::apgd::normal_lever(3, g), rot / (1 + rot), 1e-12);
  EXPECT_FALSE(moreau::apgd::round_contacts(3, g));
}

TEST(ApgdNormalLever, NoFactorOrNoContactsMeasureZero) {
  EXPECT_EQ(moreau::apgd::normal_lever(3, BodyFactor{}), 0.0);
  BodyFactor f;
  f.k = 6;
  EXPECT_EQ(moreau::apgd::normal_lever(3, f), 0.0);
}

}  // namespace
