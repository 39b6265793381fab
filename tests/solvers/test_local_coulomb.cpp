// The one-contact Coulomb problem solved by NLGS at each contact: the DESIGN §1 error of
// its answer on random symmetric positive definite blocks.
#include <gtest/gtest.h>

#include <moreau/contact_error.hpp>
#include <random>

#include "local_coulomb.hpp"
#include "one_contact_error.hpp"

TEST(LocalCoulomb, RandomBlocks2DAreSolvedExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int worst = 0;
  for (int t = 0; t < 20000; ++t) {
    double B[4], A[4], b[2], r[2] = {0, 0};
    for (double& x : B) x = u(rng);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) A[i * 2 + j] = 0.1 * (i == j) + B[i * 2] * B[j * 2] + B[i * 2 + 1] * B[j * 2 + 1];
    b[0] = u(rng);
    b[1] = u(rng);
    const double mu = 1.5 * (u(rng) + 1) / 2;
    moreau::nlgs::solve_local(2, A, b, mu, r);
    if (moreau_test::one_contact_error(2, A, b, mu, r) > 1e-10) ++worst;
  }
  EXPECT_EQ(worst, 0);
}

TEST(LocalCoulomb, RandomBlocks3D) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int failed = 0;
  const int n = 20000;
  for (int t = 0; t < n; ++t) {
    double B[9], A[9], b[3], r[3] = {0, 0, 0};
    for (double& x : B) x = u(rng);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        A[i * 3 + j] = 0.1 * (i == j);
        for (int k = 0; k < 3; ++k) A[i * 3 + j] += B[i * 3 + k] * B[j * 3 + k];
      }
    for (double& x : b) x = u(rng);
    const double mu = 0.1 + 0.9 * (u(rng) + 1) / 2;
    moreau::nlgs::solve_local(3, A, b, mu, r);
    if (moreau_test::one_contact_error(3, A, b, mu, r) > 1e-8) ++failed;
  }
  // Known limit: a few strongly coupled blocks (about 3 in 10⁵) escape the angle search
  // and fall back to projected iterations (see docs/contacts.md). Isotropic blocks (round
  // shapes) are exact.
  std::printf("3D random blocks: %d of %d not solved to 1e-8\n", failed, n);
  EXPECT_LE(failed, 4);
}
