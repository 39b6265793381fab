#pragma once
// A random rigid-body contact problem in the factored form the time-stepper gives,
// W = H M⁻¹ Hᵀ (LocalProblem::factor), with W built too: for the solvers that exchange
// impulses through body velocities (NLGS's body records, APGD's packed factor, `auto`).
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <moreau/contact_problem.hpp>
#include <random>
#include <vector>

/// nb bodies (the first `fixed` with zero inverse mass), nc contacts between random pairs
/// of distinct bodies, random H blocks and SPD inverse masses; q pushes contacts closed.
inline moreau::LocalProblem factored_problem(int d, int nb, int fixed, int nc, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  const int k = d == 2 ? 3 : 6;
  moreau::LocalProblem P;
  P.dim = d;
  auto& f = P.factor;
  f.k = k;
  f.inverse_mass.assign(static_cast<std::size_t>(nb * k * k), 0.0);
  std::vector<Eigen::MatrixXd> Mi(nb, Eigen::MatrixXd::Zero(k, k));
  for (int b = fixed; b < nb; ++b) {
    Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(k, k, [&] { return U(rng); });
    Mi[b] = A * A.transpose() + 0.5 * Eigen::MatrixXd::Identity(k, k);
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) f.inverse_mass[b * k * k + i * k + j] = Mi[b](i, j);
  }
  f.body.resize(2 * nc);
  f.H.resize(static_cast<std::size_t>(nc * 2 * d * k));
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(nc * d, nb * k);
  for (int a = 0; a < nc; ++a) {
    const int b0 = fixed + static_cast<int>(rng() % static_cast<unsigned>(nb - fixed));  // a moving body
    int b1 = static_cast<int>(rng() % static_cast<unsigned>(nb));
    if (b1 == b0) b1 = (b0 + 1) % nb;
    const int bs[2] = {b0, b1};
    for (int s = 0; s < 2; ++s) {
      f.body[2 * a + s] = bs[s] < fixed ? -1 : bs[s];
      for (int i = 0; i < d; ++i)
        for (int l = 0; l < k; ++l) {
          const double h = U(rng);
          f.H[(a * 2 + s) * d * k + i * k + l] = h;
          H(a * d + i, bs[s] * k + l) += h;
        }
    }
  }
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(nb * k, nb * k);
  for (int b = 0; b < nb; ++b) M.block(b * k, b * k, k, k) = Mi[b];
  const Eigen::MatrixXd W = H * M * H.transpose();
  P.W = W.sparseView();
  P.q.resize(nc * d);
  for (int a = 0; a < nc; ++a) {
    P.q[a * d] = -0.5 - 0.5 * (U(rng) + 1);  // approaching
    for (int i = 1; i < d; ++i) P.q[a * d + i] = U(rng);
  }
  P.mu = Eigen::VectorXd::Constant(nc, 0.3);
  return P;
}
