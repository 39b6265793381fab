#include "dof_partition.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace moreau::fem {

std::vector<int> node_dofs(const Mesh& mesh, const std::vector<int>& nodes, std::array<bool, 3> components) {
  std::vector<int> dofs;
  dofs.reserve(nodes.size() * mesh.dim);
  for (int n : nodes)
    for (int i = 0; i < mesh.dim; ++i)
      if (components[i]) dofs.push_back(mesh.dim * n + i);
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

DofPartition::DofPartition(int dofs, const std::vector<int>& constrained)
    : equation_(dofs, 0) {
  for (int d : constrained) {
    if (d < 0 || d >= dofs)
      throw std::out_of_range("DofPartition: DOF " + std::to_string(d) + " outside [0, " + std::to_string(dofs) + ")");
    equation_[d] = -1;
  }
  for (int d = 0; d < dofs; ++d) {
    if (equation_[d] < 0) {
      constrained_.push_back(d);
    } else {
      equation_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }
  }
}

SparseMatrix DofPartition::block(const SparseMatrix& A, const std::vector<int>& columns) const {
  SparseMatrix B(static_cast<Eigen::Index>(free_.size()), static_cast<Eigen::Index>(columns.size()));
  // No columns (no constrained DOFs, as for any body without fixed nodes; or no free ones):
  // Eigen 3.4's reserve() then makeCompressed() on a matrix without columns writes past its
  // outer index array (AddressSanitizer, heap-buffer-overflow). The empty matrix is the block.
  if (columns.empty()) return B;
  std::vector<int> count(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (SparseMatrix::InnerIterator it(A, columns[c]); it; ++it) count[c] += equation_[it.row()] >= 0;
  B.reserve(count);
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (SparseMatrix::InnerIterator it(A, columns[c]); it; ++it)
      if (const int r = equation_[it.row()]; r >= 0) B.insert(r, static_cast<Eigen::Index>(c)) = it.value();
  B.makeCompressed();
  return B;
}

SparseMatrix DofPartition::free_block(const SparseMatrix& A) const { return block(A, free_); }
SparseMatrix DofPartition::coupling_block(const SparseMatrix& A) const { return block(A, constrained_); }

Eigen::VectorXd DofPartition::free_part(const Eigen::VectorXd& v) const {
  Eigen::VectorXd r(free_.size());
  for (std::size_t i = 0; i < free_.size(); ++i) r[static_cast<Eigen::Index>(i)] = v[free_[i]];
  return r;
}

Eigen::VectorXd DofPartition::constrained_part(const Eigen::VectorXd& v) const {
  Eigen::VectorXd r(constrained_.size());
  for (std::size_t i = 0; i < constrained_.size(); ++i) r[static_cast<Eigen::Index>(i)] = v[constrained_[i]];
  return r;
}

Eigen::VectorXd DofPartition::combine(const Eigen::VectorXd& v_free, const Eigen::VectorXd& v_constrained) const {
  Eigen::VectorXd v(dof_count());
  for (std::size_t i = 0; i < free_.size(); ++i) v[free_[i]] = v_free[static_cast<Eigen::Index>(i)];
  for (std::size_t i = 0; i < constrained_.size(); ++i) v[constrained_[i]] = v_constrained[static_cast<Eigen::Index>(i)];
  return v;
}

}  // namespace moreau::fem
