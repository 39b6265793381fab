#pragma once
// W = H M⁻¹ Hᵀ from its factored form (contact_problem.hpp): what the time-stepper passes
// as `LocalProblem::W`, and what a solver given only the factor assembles when it needs
// the matrix after all (`auto` escalating from NLGS to Newton or ADMM); and the product
// W x through the factor, for solvers that need only products (APGD, NLGS's checks).
// W_αβ = Σ over the bodies α and β share of H_α,b M_b⁻¹ H_β,bᵀ (plus the laws' compliance
// on the diagonal, BodyFactor::diagonal, when given), written straight into
// compressed rows: a triplet list would hold every contribution of every body (~3·10⁶
// entries for 10⁴ spheres) and sort them. Fixed bodies (index −1) couple nothing. Column
// indices are sorted within each row, as Eigen's compressed format expects.
#include <algorithm>
#include <cstddef>
#include <moreau/contact_problem.hpp>
#include <utility>
#include <vector>

namespace moreau {

inline Eigen::SparseMatrix<double, Eigen::RowMajor> assemble_w(int d, const BodyFactor& f) {
  const int k = f.k;
  const std::size_t nc = f.body.size() / 2;
  const std::vector<double>& H = f.H;

  const std::size_t nb = f.inverse_mass.size() / static_cast<std::size_t>(k * k);
  // Contacts touching each moving body, as (contact, side), grouped by body (counting sort).
  std::vector<int> first(nb + 1, 0);
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side)
      if (f.body[2 * a + side] >= 0) ++first[f.body[2 * a + side] + 1];
  for (std::size_t b = 0; b < nb; ++b) first[b + 1] += first[b];
  std::vector<std::pair<int, int>> touching(first[nb]);
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (std::size_t a = 0; a < nc; ++a)
      for (int side = 0; side < 2; ++side)
        if (f.body[2 * a + side] >= 0) touching[fill[f.body[2 * a + side]]++] = {static_cast<int>(a), side};
  }
  // HM = H_α,s M_b⁻¹ per contact side (d × k).
  std::vector<double> HM(nc * 2 * d * k, 0.0);
  for (std::size_t a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      const double* Ha = &H[(a * 2 + side) * d * k];
      const double* Mi = &f.inverse_mass[static_cast<std::size_t>(b) * k * k];
      double* out = &HM[(a * 2 + side) * d * k];
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < k; ++j) {
          double s = 0;
          for (int l = 0; l < k; ++l) s += Ha[i * k + l] * Mi[l * k + j];
          out[i * k + j] = s;
        }
    }
  // Row block by row block: the neighbour contacts (sorted, merged when two contacts share
  // both bodies), then their d × d blocks.
  std::vector<int> row_ptr(nc * d + 1, 0);
  std::vector<int> cols;
  std::vector<double> vals;
  cols.reserve(static_cast<std::size_t>(first[nb]) * 4 * d * d);  // ~ 2 sides × neighbours per body
  vals.reserve(cols.capacity());
  std::vector<int> neighbours, slot(nc, -1);
  std::vector<double> blocks;
  const bool diagonal = !f.diagonal.empty();
  for (std::size_t a = 0; a < nc; ++a) {
    neighbours.clear();
    if (diagonal) {  // its own block, even between bodies impulses do not move
      slot[a] = 0;
      neighbours.push_back(static_cast<int>(a));
    }
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      for (int t = first[b]; t < first[b + 1]; ++t)
        if (slot[touching[t].first] < 0) {
          slot[touching[t].first] = 0;
          neighbours.push_back(touching[t].first);
        }
    }
    std::sort(neighbours.begin(), neighbours.end());
    for (std::size_t n = 0; n < neighbours.size(); ++n) slot[neighbours[n]] = static_cast<int>(n);
    blocks.assign(neighbours.size() * d * d, 0.0);
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      const double* hm = &HM[(a * 2 + side) * d * k];
      for (int t = first[b]; t < first[b + 1]; ++t) {
        const auto [c, sc] = touching[t];
        const double* Hc = &H[(static_cast<std::size_t>(c) * 2 + sc) * d * k];
        double* blk = &blocks[static_cast<std::size_t>(slot[c]) * d * d];
        for (int i = 0; i < d; ++i)
          for (int j = 0; j < d; ++j) {
            double s = 0;
            for (int l = 0; l < k; ++l) s += hm[i * k + l] * Hc[j * k + l];
            blk[i * d + j] += s;
          }
      }
    }
    if (diagonal)
      for (int i = 0; i < d; ++i) blocks[(static_cast<std::size_t>(slot[a]) * d + i) * d + i] += f.diagonal[a * d + i];
    for (int i = 0; i < d; ++i) {
      for (std::size_t n = 0; n < neighbours.size(); ++n)
        for (int j = 0; j < d; ++j) {
          cols.push_back(neighbours[n] * d + j);
          vals.push_back(blocks[(n * d + i) * d + j]);
        }
      row_ptr[a * d + i + 1] = static_cast<int>(cols.size());
    }
    for (int c : neighbours) slot[c] = -1;
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> W(static_cast<Eigen::Index>(nc * d), static_cast<Eigen::Index>(nc * d));
  W.resizeNonZeros(static_cast<Eigen::Index>(vals.size()));
  std::copy(row_ptr.begin(), row_ptr.end(), W.outerIndexPtr());
  std::copy(cols.begin(), cols.end(), W.innerIndexPtr());
  std::copy(vals.begin(), vals.end(), W.valuePtr());
  return W;
}

/// out = W x = H (M⁻¹ (Hᵀ x)) (+ diagonal ∘ x) without forming W: per contact side, d × k
/// each way, and k × k per body. `impulse` and `dv` are scratch (bodies × k), kept by the
/// caller so repeated products do not allocate.
inline void multiply_w(int d, const BodyFactor& f, const Eigen::VectorXd& x, Eigen::VectorXd& out,
                       std::vector<double>& impulse, std::vector<double>& dv) {
  const int k = f.k;
  const std::size_t nc = f.body.size() / 2;
  impulse.assign(f.inverse_mass.size() / static_cast<std::size_t>(k), 0.0);
  dv.assign(impulse.size(), 0.0);
  for (std::size_t a = 0; a < nc; ++a)  // Hᵀ x per body
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      const double* H = &f.H[(a * 2 + side) * d * k];
      for (int l = 0; l < k; ++l)
        for (int i = 0; i < d; ++i) impulse[b * k + l] += H[i * k + l] * x[static_cast<Eigen::Index>(a * d + i)];
    }
  for (std::size_t b = 0; b < dv.size() / k; ++b) {  // M⁻¹ per body
    const double* Mi = &f.inverse_mass[b * k * k];
    for (int l = 0; l < k; ++l)
      for (int m = 0; m < k; ++m) dv[b * k + l] += Mi[l * k + m] * impulse[b * k + m];
  }
  out.setZero(x.size());
  for (std::size_t a = 0; a < nc; ++a)  // H Δv per contact
    for (int side = 0; side < 2; ++side) {
      const int b = f.body[2 * a + side];
      if (b < 0) continue;
      const double* H = &f.H[(a * 2 + side) * d * k];
      for (int i = 0; i < d; ++i) {
        double s = 0;
        for (int l = 0; l < k; ++l) s += H[i * k + l] * dv[b * k + l];
        out[static_cast<Eigen::Index>(a * d + i)] += s;
      }
    }
  if (!f.diagonal.empty())
    for (Eigen::Index i = 0; i < x.size(); ++i) out[i] += f.diagonal[static_cast<std::size_t>(i)] * x[i];
}

}  // namespace moreau
