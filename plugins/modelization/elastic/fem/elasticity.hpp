#pragma once
// Small-strain isotropic linear elasticity on a Mesh: element and global matrices, loads,
// stresses. DOFs are ordered node-major: dof = dim·node + component (x, y[, z]), one
// displacement (m) or velocity (m/s) per DOF. Global matrices are square over all DOFs,
// symmetric, stored in full (both triangles) as Eigen::SparseMatrix<double> (column-major);
// fixed or imposed DOFs are removed by a DofPartition (dof_partition.hpp).
// Units SI; in 2D every extensive quantity is per unit thickness (material.hpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "material.hpp"
#include "mesh.hpp"

namespace moreau::fem {

using SparseMatrix = Eigen::SparseMatrix<double>;
/// Stresses, one column per element or node: (xx, yy, zz, xy, yz, xz) (VTK's order), Pa.
using StressField = Eigen::Matrix<double, 6, Eigen::Dynamic>;

enum class MassKind {
  consistent,  ///< ∫ ρ NᵀN, integrated exactly on affine elements
  lumped       ///< diagonal, by HRZ scaling of the consistent diagonal (positive for every type)
};

// ---- Element level: [dim·nodes]² matrices in the element's node order ----

void element_stiffness(const Mesh& mesh, int e, const Material& material, Eigen::MatrixXd& Ke);
void element_mass(const Mesh& mesh, int e, double density, MassKind kind, Eigen::MatrixXd& Me);

// ---- Global matrices ----

/// K, N/m (2D: N/m per unit thickness).
SparseMatrix stiffness_matrix(const Mesh& mesh, const Material& material);
/// M, kg. The lumped one is diagonal but shares K's pattern type (a SparseMatrix).
SparseMatrix mass_matrix(const Mesh& mesh, double density, MassKind kind);
/// Diagonal of the lumped mass matrix, [dofs], kg.
Eigen::VectorXd lumped_mass(const Mesh& mesh, double density);
/// Rayleigh damping C = αM + βK (α in 1/s, β in s).
SparseMatrix rayleigh_damping(const SparseMatrix& M, const SparseMatrix& K, double alpha, double beta);
/// The θ-scheme's iteration matrix (LMGC90 paper, eq. 6): LHS = M + hθC + h²θ²K.
SparseMatrix theta_lhs(const SparseMatrix& M, const SparseMatrix& C, const SparseMatrix& K, double h, double theta);

// ---- Loads, [dofs], N ----
// (Vectors of the wrong size throw std::invalid_argument.)

/// Body force of gravity g (m/s², dim components): f_a = ∫ ρ N_a g.
Eigen::VectorXd gravity_load(const Mesh& mesh, double density, const Eigen::VectorXd& g);
/// The same force (dim components) on each listed node.
Eigen::VectorXd nodal_load(const Mesh& mesh, const std::vector<int>& nodes, const Eigen::VectorXd& force);
/// Consistent load of a surface traction t(x) (Pa; x and t with 3 components, the third
/// ignored in 2D) over facets: f_a = ∫ N_a t dS.
Eigen::VectorXd traction_load(const Mesh& mesh, const Facets& facets,
                              const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& traction);

// ---- Stress recovery ----

/// Stress of each element at its reference centre from displacements u [dofs]. Plane
/// strain gives σzz = λ(εxx + εyy), plane stress σzz = 0.
StressField element_stress(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u);
/// Nodal stresses: the average of the adjacent elements' stresses weighted by their measure
/// (for display; not a recovery of higher accuracy).
StressField nodal_stress(const Mesh& mesh, const StressField& element_stress);
/// Von Mises equivalent stress of each column.
Eigen::VectorXd von_mises(const StressField& stress);

// ---- Rigid-body modes ----

/// The rigid motions as columns [dofs, 3 (2D) or 6 (3D)]: translations, then rotations
/// about the origin (z in 2D; x, y, z in 3D). K times each is zero.
Eigen::MatrixXd rigid_body_modes(const Mesh& mesh);

}  // namespace moreau::fem
