#include "material.hpp"

#include <cmath>
#include <sstream>

#include "error.hpp"

namespace moreau::fem {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

void validate(const Material& m, int dim) {
  if (!std::isfinite(m.young) || m.young <= 0)
    throw MaterialError("Young's modulus E must be a finite value > 0 (Pa), got " + number(m.young), "young");
  if (!std::isfinite(m.poisson) || m.poisson <= -1 || m.poisson >= 0.5)
    throw MaterialError("Poisson's ratio ν must lie in (−1, 0.5), got " + number(m.poisson) +
                            (m.poisson == 0.5 ? " (an incompressible material needs a mixed formulation, "
                                                "which moreau does not have; use e.g. 0.49)"
                                              : ""),
                        "poisson");
  if (!std::isfinite(m.density) || m.density < 0)
    throw MaterialError("density must be a finite value ≥ 0 (kg/m³), got " + number(m.density), "density");
  if (dim == 3 && m.hypothesis != Hypothesis::solid)
    throw MaterialError("plane strain and plane stress are 2D hypotheses; a 3D mesh needs the solid law",
                        "hypothesis");
  if (dim == 2 && m.hypothesis == Hypothesis::solid)
    throw MaterialError("a 2D mesh needs plane strain or plane stress", "hypothesis");
}

double lame_lambda(const Material& m) {
  return m.young * m.poisson / ((1 + m.poisson) * (1 - 2 * m.poisson));
}

double shear_modulus(const Material& m) { return m.young / (2 * (1 + m.poisson)); }

Eigen::MatrixXd elasticity_matrix(const Material& m) {
  const double mu = shear_modulus(m);
  if (m.hypothesis == Hypothesis::solid) {
    const double lambda = lame_lambda(m);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(6, 6);
    D.topLeftCorner(3, 3).setConstant(lambda);
    for (int i = 0; i < 3; ++i) {
      D(i, i) += 2 * mu;
      D(3 + i, 3 + i) = mu;
    }
    return D;
  }
  // Plane stress uses the reduced λ* = 2λμ/(λ + 2μ) = Eν/(1 − ν²).
  const double lambda =
      m.hypothesis == Hypothesis::plane_strain ? lame_lambda(m) : m.young * m.poisson / (1 - m.poisson * m.poisson);
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(3, 3);
  D.topLeftCorner(2, 2).setConstant(lambda);
  D(0, 0) += 2 * mu;
  D(1, 1) += 2 * mu;
  D(2, 2) = mu;
  return D;
}

}  // namespace moreau::fem
