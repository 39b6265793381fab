// DofPartition's blocks when one side is empty: a body without fixed nodes (no constrained
// DOFs, the usual free body) and a body whose every DOF is constrained. Under
// AddressSanitizer the first one overflowed the heap (an Eigen reserve on a matrix without
// columns), from configs/elastic_disk_on_plane_2d.json on.
#include <gtest/gtest.h>

#include "fem_test_util.hpp"
#include "theta_scheme.hpp"

namespace moreau::fem {
namespace {

struct Block {
  Mesh mesh = rectangle_mesh({0, 0}, {1, 1}, 0.5, ElementType::Q4);
  Material mat{1e6, 0.3, 1000, Hypothesis::plane_strain};
  SparseMatrix K = stiffness_matrix(mesh, mat), M = mass_matrix(mesh, mat.density, MassKind::consistent);
};

TEST(FemDofPartition, NoConstrainedDofs) {
  const Block b;
  const int n = b.mesh.dof_count();
  const DofPartition dofs(n, {});
  EXPECT_EQ(dofs.free().size(), static_cast<std::size_t>(n));
  const SparseMatrix coupling = dofs.coupling_block(b.K);
  EXPECT_EQ(coupling.rows(), n);
  EXPECT_EQ(coupling.cols(), 0);
  EXPECT_EQ(coupling.nonZeros(), 0);
  const SparseMatrix free = dofs.free_block(b.K);
  EXPECT_EQ(Eigen::MatrixXd(free), Eigen::MatrixXd(b.K));

  // A free block under gravity, from rest: v⁺ = h g on every DOF of its direction, exactly
  // as M v⁺ = h M g (M's rows sum the load: f = M g).
  const double h = 1e-3;
  const LinearThetaScheme scheme(b.M, SparseMatrix(n, n), b.K, h, 0.5, dofs);
  Eigen::VectorXd g(n);
  for (int i = 0; i < n; ++i) g[i] = i % 2 ? -9.81 : 0.0;
  const Eigen::VectorXd f = b.M * g;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd v = scheme.free_velocity(zero, zero, f, f, Eigen::VectorXd(0));
  EXPECT_LT((v - h * g).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(FemDofPartition, EveryDofConstrained) {
  const Block b;
  const int n = b.mesh.dof_count();
  std::vector<int> all(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
  const DofPartition dofs(n, all);
  const SparseMatrix free = dofs.free_block(b.K);
  EXPECT_EQ(free.rows(), 0);
  EXPECT_EQ(free.cols(), 0);
  const SparseMatrix coupling = dofs.coupling_block(b.K);
  EXPECT_EQ(coupling.rows(), 0);
  EXPECT_EQ(coupling.cols(), n);
  EXPECT_EQ(coupling.nonZeros(), 0);
}

}  // namespace
}  // namespace moreau::fem
