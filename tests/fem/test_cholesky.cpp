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

TEST(FemCholesky, FactorColumnsGiveTheInverseEntries) {
  // (A⁻¹)_ij = z_i · z_j, z_i = D^{-1/2} L⁻¹ P e_i nonzero only up the elimination tree:
  // against columns of A⁻¹ from full solves, on every backend that shows its factor (after
  // a refactorisation too), and z_i · z_j = z_j · z_i to the bit (W stays symmetric).
  const Mesh m = box_mesh({0, 0, 0}, {2, 1, 1}, 0.25, ElementType::H8);
  const Material mat = test::steel(Hypothesis::solid);
  const SparseMatrix K = stiffness_matrix(m, mat), M = mass_matrix(m, mat.density, MassKind::consistent);
  const DofPartition dofs(m.dof_count(), node_dofs(m, m.node_set("xmin")));
  const SparseMatrix A = dofs.free_block(theta_lhs(M, SparseMatrix(M.rows(), M.cols()), K, 1e-4, 0.5));
  const std::vector<Eigen::Index> rows = {0, 1, 7, A.rows() / 2, A.rows() - 1};
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(A.rows(), static_cast<Eigen::Index>(rows.size()));
  for (std::size_t c = 0; c < rows.size(); ++c) E(rows[c], static_cast<Eigen::Index>(c)) = 1;
  for (CholeskyBackend backend : backends) {
    if (!backend_available(backend)) continue;
    SCOPED_TRACE(std::string(backend_name(backend)));
    SparseCholesky chol(backend);
    chol.factorize(A);
    if (backend == CholeskyBackend::eigen_llt) {
      EXPECT_FALSE(chol.has_factor_columns());
      EXPECT_THROW(chol.factor_column(0), std::logic_error);
      continue;
    }
    ASSERT_TRUE(chol.has_factor_columns());
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::MatrixXd X = chol.solve_columns(E);  // columns of A⁻¹
      std::vector<FactorColumn> z;
      std::size_t longest = 0;
      for (Eigen::Index r : rows) {
        z.push_back(chol.factor_column(r));
        longest = std::max(longest, z.back().index.size());
      }
      EXPECT_LT(longest, static_cast<std::size_t>(A.rows())) << "a column reaches every pivot";
      for (std::size_t i = 0; i < rows.size(); ++i)
        for (std::size_t j = 0; j < rows.size(); ++j) {
          EXPECT_NEAR(dot(z[i], z[j]), X(rows[i], static_cast<Eigen::Index>(j)), 1e-12 * X.cwiseAbs().maxCoeff());
          EXPECT_EQ(dot(z[i], z[j]), dot(z[j], z[i]));
        }
      chol.refactorize(A);  // a second pass on the refactorised matrix
    }
  }
}

// A body whose every DOF is fixed (found by the scene fuzz target: a mesh coarser than the
// body, both ends fixed): CHOLMOD gave no factor for the 0 × 0 matrix and the run crashed.
TEST(FemCholesky, EmptyMatrixFactorisesAndSolves) {
  const SparseMatrix A(0, 0);
  for (CholeskyBackend backend : backends) {
    if (!backend_available(backend)) continue;
    SCOPED_TRACE(std::string(backend_name(backend)));
    SparseCholesky chol(backend);
    chol.factorize(A);
    chol.refactorize(A);
    EXPECT_EQ(chol.rows(), 0);
    EXPECT_EQ(chol.solve(Eigen::VectorXd(0)).size(), 0);
    const Eigen::MatrixXd X = chol.solve_columns(Eigen::MatrixXd(0, 3));
    EXPECT_EQ(X.rows(), 0);
    EXPECT_EQ(X.cols(), 3);
    EXPECT_FALSE(chol.has_factor_columns());
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
  EXPECT_EQ(automatic_backend(), backend_available(CholeskyBackend::cholmod_supernodal) ? CholeskyBackend::cholmod_supernodal
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
