// Cantilever under a tip load, static (K u = f), against Timoshenko's exact elasticity
// solution (Timoshenko & Goodier, Theory of Elasticity, §21; the benchmark of Augarde &
// Deeks 2008): x ∈ [0, L] from the clamped end, y ∈ [−D/2, D/2], load P (per unit
// thickness in 2D) spread parabolically over the end x = L, I = bD³/12:
//   ux = −P y/(6EI) [(6L − 3x) x + (2 + ν)(y² − D²/4)]
//   uy =  P/(6EI) [3ν y² (L − x) + (4 + 5ν) D² x/4 + (3L − x) x²]
// (plane stress; plane strain with E/(1 − ν²) and ν/(1 − ν)). The tip deflection is
// uy(L, 0) = PL³/(3EI) (Euler–Bernoulli) + (4 + 5ν)PLD²/(24EI) (shear). With ν = 0 the same
// field, uz = 0, is the exact 3D solution for a b × D section, so H8 and T4 are tested on it.
// The clamped end takes the exact displacements (the solution's own support), so the only
// error is the discretisation's: tip deflections must converge at order 2 (linear elements,
// displacement error O(h²)).
#include <gtest/gtest.h>

#include <cstdio>

#include "dof_partition.hpp"
#include "fem_test_util.hpp"
#include "sparse_cholesky.hpp"

namespace moreau::fem {
namespace {

struct Beam {
  double L, D, b, P, E, nu;  // b: width (3D), 1 in 2D
  double I() const { return b * D * D * D / 12; }
  Eigen::Vector3d exact(const Eigen::Vector3d& x) const {
    const double c = P / (6 * E * I());
    return {-c * x.y() * ((6 * L - 3 * x.x()) * x.x() + (2 + nu) * (x.y() * x.y() - D * D / 4)),
            c * (3 * nu * x.y() * x.y() * (L - x.x()) + (4 + 5 * nu) * D * D * x.x() / 4 + (3 * L - x.x()) * x.x() * x.x()), 0};
  }
  double tip() const { return P * L * L * L / (3 * E * I()) + (4 + 5 * nu) * P * L * D * D / (24 * E * I()); }
};

/// Solves the beam on a mesh; returns the tip deflection uy(L, 0[, 0]).
double tip_deflection(const Mesh& m, const Material& mat, const Beam& beam) {
  const int d = m.dim;
  const DofPartition dofs(m.dof_count(), node_dofs(m, m.node_set("xmin")));
  Eigen::VectorXd exact(m.dof_count());
  for (int n = 0; n < m.node_count(); ++n) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x.head(d) = m.x.col(n);
    exact.segment(d * n, d) = beam.exact(x).head(d);
  }
  const double shear = 6 * beam.P / (beam.b * beam.D * beam.D * beam.D);  // τ = shear (D²/4 − y²)
  const Eigen::VectorXd f = traction_load(m, m.boundary_set("xmax"), [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0, shear * (beam.D * beam.D / 4 - x.y() * x.y()), 0);
  });
  const SparseMatrix K = stiffness_matrix(m, mat);
  SparseCholesky chol;
  chol.factorize(dofs.free_block(K));
  const Eigen::VectorXd uc = dofs.constrained_part(exact);
  const Eigen::VectorXd u = dofs.combine(chol.solve(Eigen::VectorXd(dofs.free_part(f) - dofs.coupling_block(K) * uc)), uc);
  for (int n : m.node_set("xmax"))
    if (m.x.col(n).tail(d - 1).norm() < 1e-12) return u[d * n + 1];
  ADD_FAILURE() << "no node at the tip axis";
  return 0;
}

/// Tip deflections under refinement (divisions across the depth, doubling), printed as a
/// table with relative errors and observed orders, then checked:
///  - the observed order reaches the asymptotic 2: last pair within [1.75, 2.1], and orders
///    do not decrease (the stiff T3/T4 approach 2 from below on coarse meshes);
///  - the Richardson extrapolations R = t_h + (t_h − t_2h)/3, which remove the h² term,
///    converge to the exact deflection at an order of at least 2.5: the FE converges to the
///    exact solution, not merely somewhere (a wrong limit would make R stall).
void study(const char* name, const Beam& beam, const Material& mat, ElementType type, const std::vector<int>& divisions) {
  std::vector<double> tips, errors, orders, richardson;
  std::printf("  cantilever %s, L/D = %g: exact tip %.6e m\n", name, beam.L / beam.D, beam.tip());
  for (int nd : divisions) {
    const double h = beam.D / nd;
    const Mesh m = type == ElementType::T3 || type == ElementType::Q4
                       ? rectangle_mesh({0, -beam.D / 2}, {beam.L, beam.D}, h, type)
                       : box_mesh({0, -beam.D / 2, -beam.b / 2}, {beam.L, beam.D, beam.b}, h, type);
    tips.push_back(tip_deflection(m, mat, beam));
    errors.push_back(std::abs(tips.back() - beam.tip()) / beam.tip());
    std::printf("    D/h = %2d  dofs = %6d  tip = %.6e  rel. error = %.3e", nd, m.dof_count(), tips.back(), errors.back());
    if (tips.size() > 1) {
      const std::size_t n = tips.size();
      orders.push_back(test::order(errors[n - 2], errors[n - 1]));
      richardson.push_back(std::abs(tips[n - 1] + (tips[n - 1] - tips[n - 2]) / 3 - beam.tip()) / beam.tip());
      std::printf("  order = %.2f  Richardson error = %.1e", orders.back(), richardson.back());
    }
    std::printf("\n");
  }
  EXPECT_GE(orders.back(), 1.75);
  EXPECT_LE(orders.back(), 2.1);
  for (std::size_t i = 1; i < orders.size(); ++i) EXPECT_GE(orders[i], orders[i - 1] - 0.02);
  const std::size_t n = richardson.size();
  const double richardson_order = test::order(richardson[n - 2], richardson[n - 1]);
  std::printf("    Richardson errors converge at order %.2f\n", richardson_order);
  EXPECT_GE(richardson_order, 2.5);
}

TEST(FemCantilever, PlaneStressQ4AndT3ConvergeAtOrderTwo) {
  const Beam beam{5, 1, 1, 1e3, 200e9, 0.3};
  const Material mat{beam.E, beam.nu, 7800, Hypothesis::plane_stress};
  study("2D plane stress Q4", beam, mat, ElementType::Q4, {2, 4, 8, 16});
  study("2D plane stress T3", beam, mat, ElementType::T3, {2, 4, 8, 16});
}

TEST(FemCantilever, PlaneStrainQ4ConvergesAtOrderTwo) {
  // Plane strain is plane stress with E' = E/(1 − ν²), ν' = ν/(1 − ν) in the exact field.
  const double E = 200e9, nu = 0.3;
  const Beam beam{5, 1, 1, 1e3, E / (1 - nu * nu), nu / (1 - nu)};
  study("2D plane strain Q4", beam, {E, nu, 7800, Hypothesis::plane_strain}, ElementType::Q4, {2, 4, 8, 16});
}

TEST(FemCantilever, SolidH8AndT4ConvergeAtOrderTwo) {
  const Beam beam{4, 1, 1, 1e3, 200e9, 0.0};
  const Material mat{beam.E, beam.nu, 7800, Hypothesis::solid};
  study("3D H8 (ν = 0)", beam, mat, ElementType::H8, {2, 4, 8});
  study("3D T4 (ν = 0)", beam, mat, ElementType::T4, {2, 4, 8});
}

}  // namespace
}  // namespace moreau::fem
