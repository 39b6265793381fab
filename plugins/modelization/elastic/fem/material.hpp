#pragma once
// Isotropic linear elastic material (small strains). Units SI: E in Pa, density in kg/m³.
// In 2D every extensive quantity is per unit thickness (out of plane), as for moreau's
// rigid bodies: mass in kg/m, forces in N/m, stiffness in N/m².
#include <Eigen/Core>

namespace moreau::fem {

/// The 2D reduction, or 3D.
enum class Hypothesis { plane_strain, plane_stress, solid };

struct Material {
  double young = 0;    ///< E (Pa), > 0
  double poisson = 0;  ///< ν, in (−1, 0.5)
  double density = 0;  ///< ρ (kg/m³), ≥ 0 (0: massless, quasi-static)
  Hypothesis hypothesis = Hypothesis::solid;
};

/// Throws MaterialError naming the parameter when E ≤ 0, ν ∉ (−1, 0.5), ρ < 0, any value
/// non-finite, or the hypothesis does not fit the dimension (plane_* in 2D, solid in 3D).
void validate(const Material& material, int dim);

/// Elasticity matrix D (σ = D ε) in Voigt notation with engineering shear strains:
/// 2D [3, 3] on (xx, yy, xy); 3D [6, 6] on (xx, yy, zz, yz, xz, xy).
Eigen::MatrixXd elasticity_matrix(const Material& material);

/// Lamé's parameters λ, μ of the 3D law.
double lame_lambda(const Material& material);
double shear_modulus(const Material& material);

}  // namespace moreau::fem
