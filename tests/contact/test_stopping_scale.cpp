// The time-stepper's error denominator (kernel/contact/stopping_scale.hpp, docs/solvers.md
// "Stopping test"): the approaching contacts' norm of q, whatever the open contacts, with a
// floor of √ε ‖q‖ so that a contact approaching by a rounding residue cannot make the
// rounding of W r + q read as a large error.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <moreau/contact_error.hpp>

#include "kernel/contact/stopping_scale.hpp"

namespace {

/// A 2D problem with a diagonal W (1 per unknown) and the given q, μ = 0.3.
moreau::LocalProblem problem(const std::vector<double>& q) {
  moreau::LocalProblem p;
  p.dim = 2;
  const auto n = static_cast<Eigen::Index>(q.size());
  p.q = Eigen::Map<const Eigen::VectorXd>(q.data(), n);
  p.mu = Eigen::VectorXd::Constant(n / 2, 0.3);
  p.W.resize(n, n);
  p.W.setIdentity();
  return p;
}

}  // namespace

TEST(StoppingScale, TheApproachingContactsNormWhateverTheOpenContacts) {
  const double expected = std::sqrt(0.01 * 0.01 + 0.002 * 0.002 + 0.02 * 0.02);
  EXPECT_DOUBLE_EQ(moreau::kernel::approaching_contacts_scale(problem({-0.01, 0.002, -0.02, 0})), expected);
  // Open contacts (q_n = gap/h > 0) of a larger alert distance change nothing.
  std::vector<double> q = {-0.01, 0.002, -0.02, 0};
  for (int k = 0; k < 50; ++k) q.insert(q.end(), {2.0, 0.1});
  EXPECT_DOUBLE_EQ(moreau::kernel::approaching_contacts_scale(problem(q)), expected);
  // None approaches: 0, so the error falls back to ‖q‖ (r = 0 is then the answer).
  EXPECT_EQ(moreau::kernel::approaching_contacts_scale(problem({0.5, 0.1, 2.0, 0})), 0.0);
}

TEST(StoppingScale, AContactApproachingByARoundingResidueDoesNotSetTheScale) {
  // disks_in_box_2d, step 56 (apgd with the normal/tangent scaling): the only approaching
  // contact had q_n = -1.4e-17 while ‖q‖ = 16; the rounding of u = W r + q on it, 4.5e-18,
  // read as error 0.32 and the solve could not stop. Here: that contact, its exact answer
  // r_n = 1.4e-17 and u_n = 4.5e-18 of rounding, next to open contacts of ‖q‖ = 16.
  moreau::LocalProblem p = problem({-1.4e-17, 0, 16, 0});
  p.error_scale = moreau::kernel::approaching_contacts_scale(p);
  const double floor = std::sqrt(std::numeric_limits<double>::epsilon()) * p.q.norm();
  EXPECT_DOUBLE_EQ(p.error_scale, floor);
  Eigen::VectorXd r(4), u(4);
  r << 1.4e-17, 0, 0, 0;
  u << 4.5e-18, 0, 16, 0;
  EXPECT_LT(moreau::natural_map_error(p, r, u), 1e-8) << "rounding must stay below any tolerance a solve uses";
  // Without the floor the same answer reads as 0.32 (what the solve saw).
  moreau::LocalProblem bare = p;
  bare.error_scale = 1.4e-17;
  EXPECT_GT(moreau::natural_map_error(bare, r, u), 0.3);
}
