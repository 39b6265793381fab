#pragma once
// The fill of Newton's sparse LU (plugins/solver/newton/newton_core.cpp: Eigen's SparseLU,
// COLAMD column ordering, J + λI of W's block-row pattern) predicted before its numeric
// factorisation, from a symbolic analysis: the same ordering as Newton's (SparseLU's own
// analyzePattern on W's pattern plus the diagonal), then the column counts of the Cholesky
// factor of that pattern ordered symmetrically (the factors of an LU that pivots on the
// diagonal; its pivoting adds up to 30 % more on the corpus). `auto` counts a Newton step from them (work.hpp factorisation()) before it
// pays one: W's own size says little of a 3D LU's fill (wet_pile_3d, 650 contacts: nnz(L)
// + nnz(U) about 20 nnz(W), where 2D stacks fill 1–3 nnz(W)).
#include <algorithm>
#include <vector>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace moreau {

struct LuFill {
  double nnz_l = 0, nnz_u = 0;  ///< the factors' entries, the diagonal in each (as SparseLU's nnzL(), nnzU())
  double work = 0;              ///< the analysis's own cost, in work.hpp's units
};

/// The predicted fill of SparseLU<COLAMD> on a matrix with the pattern of `W` (square,
/// symmetric pattern, d × d blocks per contact) plus its diagonal. The analysis runs on the
/// contacts' graph (one node per block row: d² times fewer entries than W, so it costs a few
/// percent of a Newton step), each block of the factor counted as d² entries (d(d+1)/2 on
/// the diagonal).
template <class Matrix>
LuFill predicted_lu_fill(const Matrix& W, int d) {
  using Index = int;
  const Index nc = static_cast<Index>(W.rows() / std::max(d, 1));
  LuFill f;
  if (nc == 0 || W.rows() != W.cols()) return f;
  // The contacts' pattern (block (a, b) when W has an entry there, and (a, a)), compressed
  // column storage built directly (W's pattern is symmetric).
  std::vector<Index> mark(nc, -1), outer(nc + 1, 0), inner;
  inner.reserve(static_cast<std::size_t>(W.nonZeros() / std::max(d * d, 1) + nc));
  const auto& M = W;
  for (Index a = 0; a < nc; ++a) {
    mark[a] = a;
    inner.push_back(a);
    for (Index i = a * d; i < (a + 1) * d; ++i)
      for (typename Matrix::InnerIterator it(M, i); it; ++it) {
        const Index b = static_cast<Index>((Matrix::IsRowMajor ? it.col() : it.row()) / d);
        if (mark[b] != a) mark[b] = a, inner.push_back(b);
      }
    outer[a + 1] = static_cast<Index>(inner.size());
  }
  std::vector<double> ones(inner.size(), 1.0);
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, Index>> S(nc, nc, static_cast<Index>(inner.size()),
                                                                                 outer.data(), inner.data(), ones.data());
  // Newton's kind of column ordering (COLAMD, then the column elimination tree's postorder).
  Eigen::SparseLU<Eigen::SparseMatrix<double, Eigen::ColMajor, Index>> lu;
  lu.analyzePattern(S);
  const auto& perm = lu.colsPermutation().indices();  // column j goes to perm[j]
  // Column counts of the Cholesky factor of P S Pᵀ (LDL's symbolic pass: each entry of
  // column k above the diagonal walks the elimination tree up to k, O(nnz(L))).
  std::vector<Index> parent(nc, -1), flag(nc, -1), count(nc, 0), inv(nc);
  for (Index j = 0; j < nc; ++j) inv[perm[j]] = j;
  for (Index k = 0; k < nc; ++k) {
    flag[k] = k;
    const Index col = inv[k];
    for (Index p = outer[col]; p < outer[col + 1]; ++p) {
      Index i = perm[inner[p]];
      if (i >= k) continue;
      for (; flag[i] != k; i = parent[i]) {
        if (parent[i] == -1) parent[i] = k;
        ++count[i];
        flag[i] = k;
      }
    }
  }
  double below = 0;  // blocks below the diagonal
  for (Index k = 0; k < nc; ++k) below += count[k];
  f.nnz_l = f.nnz_u = d * d * below + nc * d * (d + 1) / 2.0;
  // Its cost, fitted to its CPU time (ns) on the corpus (docs/solvers-history.md, i15-fill):
  // 1.5 per entry of W (the read), 24 per entry of the contacts' pattern (COLAMD), 20 per
  // block of the factor (the walk, pointer chasing): 3–15 % of a Newton step (whose steps
  // took 1.0–1.6 ns per counted unit), 3 % on wet_pile_3d's.
  f.work = 1.5 * static_cast<double>(W.nonZeros()) + 24.0 * static_cast<double>(inner.size()) + 20.0 * below + 3000;
  return f;
}

}  // namespace moreau
