// The sparse Cholesky backends agree, refactorise, and refuse what they cannot factorise.
#include <gtest/gtest.h>

#include "dof_partition.hpp"
#include "fem_test_util.hpp"
#include "sparse_cholesky.hpp"

namespace moreau::fem {
namespace {

const CholeskyBackend backends[] = {CholeskyBackend::eigen_ldlt, CholeskyBackend::eigen_llt,
                                    CholeskyBackend::cholmod_supernodal, CholeskyBackend::cholmod_simplicial,
                                    CholeskyBackend::automatic};

TEST(FemCholesky, BackendsAgreeOnTheThetaMatrix) {
  for (const Mesh& m : {rectangle_mesh({0, 0}, {4, 1}, 0.1, ElementType::Q4), box_mesh({0, 0, 0}, {2, 1, 1}, 0.2, ElementType::T4)}) {
    const Material mat = test::steel(m.dim == 3 ? Hypothesis::solid : Hypothesis::plane_strain);
    const SparseMatrix K = stiffness_matrix(m, mat), M = mass_matrix(m, mat.density, MassKind::lumped);
    const DofPartition dofs(m.dof_count(), node_dofs(m, m.node_set("xmin")));
    const SparseMatrix A = dofs.free_block(theta_lhs(M, rayleigh_damping(M, K, 0, 1e-5), K, 1e-5, 0.5));
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(0.37 * i);
    Eigen::MatrixXd B(A.rows(), 3);
    B << b, b.reverse(), Eigen::VectorXd::Ones(b.size());
    for (CholeskyBackend backend : backends) {
      if (!backend_available(backend)) continue;
      SCOPED_TRACE(std::string(backend_name(backend)));
      SparseCholesky chol(backend);
      chol.factorize(A);
      EXPECT_NE(chol.backend(), CholeskyBackend::automatic);
      const Eigen::VectorXd x = chol.solve(b);
      EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
      const Eigen::MatrixXd X = chol.solve_columns(B);
      EXPECT_LT((A * X - B).norm(), 1e-10 * B.norm());
      // A new matrix of the same pattern (another time step) reuses the analysis.
      const SparseMatrix A2 = dofs.free_block(theta_lhs(M, rayleigh_damping(M, K, 0, 1e-5), K, 2e-5, 0.5));
      chol.refactorize(A2);
      EXPECT_LT((A2 * chol.solve(b) - b).norm(), 1e-10 * b.norm());
    }
  }
}

TEST(FemCholesky, RefusesSingularOrIndefinite) {
  // A free body without mass: K alone has the rigid motions in its null space.
  const Mesh m = rectangle_mesh({0, 0}, {1, 1}, 0.25, ElementType::Q4);
  SparseMatrix K = stiffness_matrix(m, test::steel(Hypothesis::plane_strain));
  SparseMatrix negative = -K;
  for (CholeskyBackend backend : backends) {
    if (!backend_available(backend)) continue;
    SCOPED_TRACE(std::string(backend_name(backend)));
    SparseCholesky chol(backend);
    try {
      chol.factorize(negative);
      FAIL() << "factorised a negative definite matrix";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("the matrix is not positive definite"), std::string::npos) << e.what();
    }
  }
  SparseCholesky unused;
  EXPECT_THROW(unused.solve(Eigen::VectorXd::Zero(3)), std::logic_error);
}

TEST(FemCholesky, AvailabilityAndNames) {
  EXPECT_TRUE(backend_available(CholeskyBackend::eigen_ldlt));
  EXPECT_EQ(automatic_backend(), backend_available(CholeskyBackend::cholmod_simplicial) ? CholeskyBackend::cholmod_simplicial
                                                                                        : CholeskyBackend::eigen_ldlt);
  for (CholeskyBackend b : backends) EXPECT_EQ(backend_from_name(backend_name(b)), b);
  try {
    backend_from_name("cholesky");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "unknown sparse Cholesky backend 'cholesky'; valid: automatic, eigen-ldlt, eigen-llt, "
                                     "cholmod-supernodal, cholmod-simplicial");
  }
#ifndef MOREAU_FEM_CHOLMOD
  EXPECT_FALSE(backend_available(CholeskyBackend::cholmod_supernodal));
  EXPECT_THROW(SparseCholesky(CholeskyBackend::cholmod_supernodal), std::runtime_error);
#endif
}

}  // namespace
}  // namespace moreau::fem
