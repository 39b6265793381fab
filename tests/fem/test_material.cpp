// Material validation and the elasticity matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "error.hpp"
#include "material.hpp"

namespace moreau::fem {
namespace {

std::string refusal(const Material& m, int dim, std::string* parameter = nullptr) {
  try {
    validate(m, dim);
  } catch (const MaterialError& e) {
    if (parameter) *parameter = e.parameter();
    return e.what();
  }
  return "accepted";
}

TEST(FemMaterial, RangesAreEnforced) {
  std::string p;
  EXPECT_EQ(refusal({0, 0.3, 1000, Hypothesis::solid}, 3, &p), "Young's modulus E must be a finite value > 0 (Pa), got 0");
  EXPECT_EQ(p, "young");
  EXPECT_EQ(refusal({-5, 0.3, 1000, Hypothesis::solid}, 3), "Young's modulus E must be a finite value > 0 (Pa), got -5");
  EXPECT_EQ(refusal({1e9, 0.5, 1000, Hypothesis::solid}, 3, &p),
            "Poisson's ratio ν must lie in (−1, 0.5), got 0.5 (an incompressible material needs a mixed formulation, "
            "which moreau does not have; use e.g. 0.49)");
  EXPECT_EQ(p, "poisson");
  EXPECT_EQ(refusal({1e9, 0.7, 1000, Hypothesis::plane_strain}, 2), "Poisson's ratio ν must lie in (−1, 0.5), got 0.7");
  EXPECT_EQ(refusal({1e9, -1, 1000, Hypothesis::solid}, 3), "Poisson's ratio ν must lie in (−1, 0.5), got -1");
  EXPECT_EQ(refusal({1e9, 0.3, -1, Hypothesis::solid}, 3, &p), "density must be a finite value ≥ 0 (kg/m³), got -1");
  EXPECT_EQ(p, "density");
  EXPECT_EQ(refusal({std::nan(""), 0.3, 1, Hypothesis::solid}, 3), "Young's modulus E must be a finite value > 0 (Pa), got nan");
  EXPECT_EQ(refusal({1e9, 0.3, 1, Hypothesis::plane_stress}, 3),
            "plane strain and plane stress are 2D hypotheses; a 3D mesh needs the solid law");
  EXPECT_EQ(refusal({1e9, 0.3, 1, Hypothesis::solid}, 2), "a 2D mesh needs plane strain or plane stress");
  EXPECT_EQ(refusal({1e9, 0.49, 0, Hypothesis::solid}, 3), "accepted");
  EXPECT_EQ(refusal({1e9, -0.9, 1, Hypothesis::plane_stress}, 2), "accepted");
}

TEST(FemMaterial, ElasticityMatrixInvertsHookesLaw) {
  const double E = 210e9, nu = 0.28;
  // 3D: the compliance is the textbook one.
  const Eigen::MatrixXd D = elasticity_matrix({E, nu, 1, Hypothesis::solid});
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(6, 6);
  S.topLeftCorner(3, 3).setConstant(-nu / E);
  for (int i = 0; i < 3; ++i) S(i, i) = 1 / E, S(3 + i, 3 + i) = 2 * (1 + nu) / E;
  EXPECT_LT((D * S - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-12);
  // Plane stress: σzz = 0, so the 2D compliance is the 3D one restricted.
  const Eigen::MatrixXd Ds = elasticity_matrix({E, nu, 1, Hypothesis::plane_stress});
  Eigen::Matrix3d S2;
  S2 << 1 / E, -nu / E, 0, -nu / E, 1 / E, 0, 0, 0, 2 * (1 + nu) / E;
  EXPECT_LT((Ds * S2 - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  // Plane strain: εzz = 0, the 3D matrix restricted to (xx, yy, xy).
  const Eigen::MatrixXd De = elasticity_matrix({E, nu, 1, Hypothesis::plane_strain});
  EXPECT_NEAR(De(0, 0), D(0, 0), 1e-3);
  EXPECT_NEAR(De(0, 1), D(0, 1), 1e-3);
  EXPECT_NEAR(De(2, 2), D(5, 5), 1e-3);
}

}  // namespace
}  // namespace moreau::fem
