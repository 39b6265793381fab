// NLGS exchanging impulses through body velocities (`exchange: bodies`) against the same
// algorithm reading W (`exchange: w`), on random rigid-body problems given in factored
// form W = H M⁻¹ Hᵀ, 2D and 3D, with fixed bodies; and the error when no factor is given.
#include <gtest/gtest.h>

#include <moreau/contact_error.hpp>
#include <moreau/error.hpp>
#include <moreau/factor_matrix.hpp>
#include <moreau/solver.hpp>
#include <random>
#include <string>

#include "apgd_core.hpp"
#include "factored_problem.hpp"
#include "rigid_frames.hpp"
#include "scaled_factor.hpp"
#include "sim.hpp"
#include "../work.hpp"  // plugins/solver (through the nlgs include directory)

namespace {

std::unique_ptr<moreau::Solver> nlgs(const std::string& exchange) {
  return moreau_test::create<moreau::Solver>("nlgs",
                                             {{"tolerance", 1e-11}, {"max_iterations", 20000}, {"relaxation", 1.0},
                                              {"ordering", "given"}, {"seed", 1}, {"check_every", 1}, {"exchange", exchange},
                                               {"local_solver", "exact"}, {"local_iterations", 0}, {"local_tolerance", 1e-14}},
                                             moreau::BuildContext{});
}

void same_answer_both_ways(int d, unsigned seed) {
  // Few contacts on several bodies: W is non-singular and the solution unique, so both
  // exchanges must reach the same r (to the tolerance over W's conditioning).
  const auto P = factored_problem(d, 6, 2, d == 2 ? 6 : 5, seed);
  Eigen::VectorXd rw, uw, rb, ub;
  const auto rep_w = nlgs("w")->solve(P, rw, uw);
  const auto rep_b = nlgs("bodies")->solve(P, rb, ub);
  ASSERT_TRUE(rep_w.converged) << rep_w.error;
  ASSERT_TRUE(rep_b.converged) << rep_b.error;
  EXPECT_NEAR(rep_b.error, moreau::natural_map_error(P, rb), 1e-12) << "the error is that of u = W r + q";
  EXPECT_LT((ub - (P.W * rb + P.q)).norm(), 1e-10 * (1 + P.q.norm())) << "u from body velocities is W r + q";
  EXPECT_LT((rb - rw).norm(), 1e-7 * (1 + rw.norm()));
  EXPECT_GT(rw.norm(), 0.1) << "the case closes contacts";
}

TEST(NlgsBodies, SameAnswerAsWBlocksIn2D) {
  for (unsigned seed = 1; seed <= 5; ++seed) same_answer_both_ways(2, seed);
}

TEST(NlgsBodies, SameAnswerAsWBlocksIn3D) {
  for (unsigned seed = 1; seed <= 5; ++seed) same_answer_both_ways(3, seed);
}

/// The problem made frictionless; with `central`, the normal rows no longer turn the
/// bodies and the inverse masses no longer couple translation and rotation (spheres and
/// disks), so the sweep packs only the normal row and the translations.
moreau::LocalProblem frictionless(moreau::LocalProblem P, bool central) {
  const int d = P.dim, k = P.factor.k;
  P.mu.setZero();
  if (central) {
    for (std::size_t a = 0; a < P.factor.body.size() / 2; ++a)
      for (int s = 0; s < 2; ++s)
        for (int l = d; l < k; ++l) P.factor.H[(a * 2 + s) * d * k + l] = 0;  // row 0: the normal
    for (std::size_t b = 0; b < P.factor.inverse_mass.size() / (k * k); ++b)
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
          if ((i < d) != (j < d)) P.factor.inverse_mass[b * k * k + i * k + j] = 0;
  }
  P.W = moreau::assemble_w(d, P.factor);
  return P;
}

TEST(NlgsBodies, FrictionlessPackedRecordsGiveTheSameAnswer) {
  // μ = 0 keeps the normal rows only; without rotation coupling, the translations only.
  // Both must give what the W-reading sweep gives, r_t = 0, and the whole u = W r + q.
  for (int d : {2, 3})
    for (bool central : {false, true})
      for (unsigned seed = 1; seed <= 3; ++seed) {
        const auto P = frictionless(factored_problem(d, 6, 2, d == 2 ? 6 : 5, seed), central);
        Eigen::VectorXd rw, uw, rb = Eigen::VectorXd::Constant(P.q.size(), 0.1), ub;  // r_t ≠ 0 to begin
        const auto rep_w = nlgs("w")->solve(P, rw, uw);
        const auto rep_b = nlgs("bodies")->solve(P, rb, ub);
        ASSERT_TRUE(rep_w.converged) << rep_w.error;
        ASSERT_TRUE(rep_b.converged) << "dim " << d << " central " << central << " seed " << seed << ": " << rep_b.error;
        EXPECT_LT((rb - rw).norm(), 1e-7 * (1 + rw.norm()));
        EXPECT_LT((ub - (P.W * rb + P.q)).norm(), 1e-10 * (1 + P.q.norm())) << "tangential rows of u too";
        for (Eigen::Index a = 0; a < P.contacts(); ++a)
          for (int i = 1; i < d; ++i) EXPECT_EQ(rb[a * d + i], 0.0);
        EXPECT_GT(rw.norm(), 0.1) << "the case closes contacts";
      }
}

TEST(NlgsBodies, ScalarInverseMassesGiveTheSameAnswer) {
  // Spheres and disks: M⁻¹ = diag(m_t I, m_r I) per body, kept as two scalars instead of
  // G = M⁻¹Hᵀ in the records (with friction). Rounding-size off-diagonal terms (a sphere's
  // R I⁻¹ Rᵀ) must not stop it from applying, nor change the answer.
  for (int d : {2, 3})
    for (unsigned seed = 1; seed <= 3; ++seed) {
      auto P = factored_problem(d, 6, 2, d == 2 ? 6 : 5, seed);
      const int k = P.factor.k;
      for (std::size_t b = 2; b < P.factor.inverse_mass.size() / (k * k); ++b) {
        double* Mi = &P.factor.inverse_mass[b * k * k];
        const double mt = 0.5 + 0.1 * static_cast<double>(b), mr = 2.0 + 0.3 * static_cast<double>(b);
        for (int i = 0; i < k; ++i)
          for (int j = 0; j < k; ++j) Mi[i * k + j] = i != j ? 1e-17 * mr : i < d ? mt : mr;
      }
      P.W = moreau::assemble_w(d, P.factor);
      Eigen::VectorXd rw, uw, rb, ub;
      const auto rep_w = nlgs("w")->solve(P, rw, uw);
      const auto rep_b = nlgs("bodies")->solve(P, rb, ub);
      ASSERT_TRUE(rep_w.converged) << rep_w.error;
      ASSERT_TRUE(rep_b.converged) << "dim " << d << " seed " << seed << ": " << rep_b.error;
      EXPECT_LT((rb - rw).norm(), 1e-7 * (1 + rw.norm()));
      EXPECT_LT((ub - (P.W * rb + P.q)).norm(), 1e-10 * (1 + P.q.norm()));
      EXPECT_GT(rw.norm(), 0.1) << "the case closes contacts";
    }
}

TEST(NlgsBodies, WarmStartFromTheAnswerStopsAtOnce) {
  const auto P = factored_problem(3, 6, 2, 5, 7);
  Eigen::VectorXd r, u;
  ASSERT_TRUE(nlgs("bodies")->solve(P, r, u).converged);
  const auto again = nlgs("bodies")->solve(P, r, u);
  EXPECT_TRUE(again.converged);
  EXPECT_EQ(again.iterations, 1) << "Δv must be rebuilt from the warm start";
}

TEST(NlgsBodies, WithoutAFactorTheErrorNamesTheOption) {
  auto P = factored_problem(3, 4, 1, 3, 3);
  P.factor = {};
  Eigen::VectorXd r, u;
  try {
    nlgs("bodies")->solve(P, r, u);
    FAIL() << "no error";
  } catch (const moreau::InputError& e) {
    EXPECT_EQ(e.where(), "/solver/exchange");
    EXPECT_NE(std::string(e.what()).find("factored form"), std::string::npos) << e.what();
  }
  // `auto` falls back to W.
  EXPECT_TRUE(nlgs("auto")->solve(P, r, u).converged);
}

}  // namespace

namespace {

std::unique_ptr<moreau::Solver> auto_solver(long nlgs_sweeps, long direct_max_contacts = 1000) {
  return moreau_test::create<moreau::Solver>(
      "auto",
      {{"tolerance", 1e-11}, {"max_iterations", 20000}, {"nlgs_sweeps", nlgs_sweeps}, {"check_every", 5},
       {"direct_max_contacts", direct_max_contacts}, {"newton_max_iterations", 200}, {"remember", true}},
      moreau::BuildContext{});
}

TEST(AutoFactored, WithoutWSameAnswerAsWithW) {
  // The time-stepper gives `auto` only the factor (it says it does not read W): its NLGS
  // stage goes through body velocities, and with nlgs_sweeps = 0 it goes straight to
  // Newton on the W it assembles itself. Both must reach the answer found with W given.
  for (int d : {2, 3})
    for (long sweeps : {200L, 0L}) {
      const auto full = factored_problem(d, 6, 2, d == 2 ? 6 : 5, 11);
      auto factored = full;
      factored.W.resize(0, 0);
      Eigen::VectorXd rw, uw, rf, uf;
      const auto rep_w = auto_solver(sweeps)->solve(full, rw, uw);
      const auto rep_f = auto_solver(sweeps)->solve(factored, rf, uf);
      ASSERT_TRUE(rep_w.converged);
      ASSERT_TRUE(rep_f.converged) << "dim " << d << ", nlgs_sweeps " << sweeps;
      EXPECT_NEAR(rep_f.error, moreau::natural_map_error(full, rf), 1e-12);
      EXPECT_LT((rf - rw).norm(), 1e-7 * (1 + rw.norm()));
      EXPECT_LT((uf - (full.W * rf + full.q)).norm(), 1e-10 * (1 + full.q.norm()));
    }
}

std::unique_ptr<moreau::Solver> apgd_solver() {
  return moreau_test::create<moreau::Solver>(
      "apgd", {{"tolerance", 1e-10}, {"max_iterations", 100000}, {"shrink", 0.9}, {"restart", true}, {"check_every", 1}, {"scaling", "contact"}},
      moreau::BuildContext{});
}

/// APGD on `full` with W and on the same problem given by its factor only (as the
/// time-stepper gives it): both converge to the same r, u = W r + q. Returns the iteration
/// counts (with W, through the factor).
std::pair<long, long> apgd_same_answer_through_the_factor(const moreau::LocalProblem& full) {
  auto factored = full;
  factored.W.resize(0, 0);
  Eigen::VectorXd rw, uw, rf, uf;
  const auto rep_w = apgd_solver()->solve(full, rw, uw);
  const auto rep_f = apgd_solver()->solve(factored, rf, uf);
  EXPECT_TRUE(rep_w.converged) << rep_w.error;
  EXPECT_TRUE(rep_f.converged) << rep_f.error;
  EXPECT_LT((rf - rw).norm(), 1e-7 * (1 + rw.norm()));
  EXPECT_LT((uf - (full.W * rf + full.q)).norm(), 1e-10 * (1 + full.q.norm()));
  return {rep_w.iterations, rep_f.iterations};
}

TEST(ApgdFactored, ThroughTheFactorSameAnswerAsWithW) {
  // Given only the factor, APGD multiplies by H M⁻¹ Hᵀ (packed with M⁻¹ = L Lᵀ folded into
  // H): the same answer as with W. The iteration count is compared loosely: rounding
  // changes APGD's restart and backtracking decisions (on dim 2, seed 21, perturbing W's
  // entries by 1e-15 relative moved it from 96 to 80–111), so the products' different
  // rounding moves it by up to about 20 %.
  for (int d : {2, 3})
    for (unsigned seed : {21u, 22u}) {
      const auto [with_w, through_factor] = apgd_same_answer_through_the_factor(factored_problem(d, 6, 2, d == 2 ? 6 : 5, seed));
      EXPECT_LT(std::abs(through_factor - with_w), 1 + 3 * with_w / 10) << "dim " << d << " seed " << seed << ": " << with_w << " with W";
    }
}

TEST(AutoFactored, AboveDirectMaxContactsApgdAndNlgsReachTheSameAnswer) {
  // With direct_max_contacts = 0 every problem counts as large: after the first NLGS
  // stage, APGD and NLGS alternate (no sparse LU). Stopped NLGS stages early
  // (nlgs_sweeps = 10) so the later stages do the work; the answer is the one with W.
  for (int d : {2, 3})
    for (unsigned seed : {11u, 12u, 13u}) {
      const auto full = factored_problem(d, 6, 2, d == 2 ? 6 : 5, seed);
      auto factored = full;
      factored.W.resize(0, 0);
      Eigen::VectorXd rw, uw, rf, uf;
      const auto rep_w = auto_solver(200)->solve(full, rw, uw);
      const auto rep_f = auto_solver(10, 0)->solve(factored, rf, uf);
      ASSERT_TRUE(rep_w.converged);
      ASSERT_TRUE(rep_f.converged) << "dim " << d << ", seed " << seed << ": error " << rep_f.error;
      EXPECT_GT(rep_f.iterations, 10) << "beyond the first NLGS stage";
      EXPECT_NEAR(rep_f.error, moreau::natural_map_error(full, rf), 1e-12);
      EXPECT_LT((rf - rw).norm(), 1e-7 * (1 + rw.norm()));
    }
}

}  // namespace

namespace {

/// The random problem with some bodies' inverse masses replaced: body 2 a sphere's
/// (diag(m_t, m_r)), body 3 a body whose rotations are locked (zero rows and columns), and
/// the laws' compliance on the diagonal; W rebuilt from them.
moreau::LocalProblem varied_problem(int d, unsigned seed, bool compliance) {
  auto P = factored_problem(d, 8, 2, d == 2 ? 14 : 12, seed);
  auto& f = P.factor;
  const int k = f.k;
  for (int b : {2, 3})
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        double& m = f.inverse_mass[static_cast<std::size_t>(b * k * k + i * k + j)];
        if (b == 2) m = i != j ? 0.0 : i < d ? 0.25 : 3.0;
        else if (i >= d || j >= d) m = 0.0;
      }
  if (compliance) {
    f.diagonal.resize(P.q.size());
    for (std::size_t i = 0; i < f.diagonal.size(); ++i) f.diagonal[i] = 0.01 * static_cast<double>(1 + i % 3);
  }
  P.W = moreau::assemble_w(d, f);
  return P;
}

/// A 3D rigid-body problem in the form the time-stepper gives it: per contact an
/// orthonormal frame E (rows n, t, s) at a point p; per side the block ±[E, rows r × e_i],
/// r = p − c the lever arm from the body's centre c (the second side negated); inverse
/// masses 1/m I₃ ⊕ R I⁻¹ Rᵀ (R a rotation: symmetric to rounding only, as the integrator
/// gives them); bodies 0 and 1 fixed; optionally the laws' compliance.
moreau::LocalProblem rigid_frames_problem(unsigned seed, bool compliance) {
  const int nb = 8, fixed = 2, nc = 16, k = 6;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  moreau::LocalProblem P;
  P.dim = 3;
  auto& f = P.factor;
  f.k = k;
  f.inverse_mass.assign(static_cast<std::size_t>(nb * k * k), 0.0);
  std::vector<Eigen::Vector3d> centre(nb);
  for (int b = 0; b < nb; ++b) {
    centre[b] = Eigen::Vector3d(U(rng), U(rng), U(rng));
    if (b < fixed) continue;
    const Eigen::Matrix3d R = Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)).normalized().toRotationMatrix();
    const Eigen::Vector3d I(1.5 + U(rng), 1.5 + U(rng), 1.5 + U(rng));
    const Eigen::Matrix3d Rs = R * I.cwiseInverse().asDiagonal();
    Eigen::Matrix3d Iw;  // R I⁻¹ Rᵀ, summed in the integrator's order (symmetric to rounding)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Iw(i, j) = Rs(i, 0) * R(j, 0) + Rs(i, 1) * R(j, 1) + Rs(i, 2) * R(j, 2);
    double* M = &f.inverse_mass[static_cast<std::size_t>(b * k * k)];
    const double im = 0.5 + 0.25 * (U(rng) + 1);
    for (int i = 0; i < 3; ++i) M[i * k + i] = im;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[(3 + i) * k + 3 + j] = Iw(i, j);
  }
  f.body.resize(2 * nc);
  f.H.resize(static_cast<std::size_t>(nc * 2 * 3 * k));
  for (int a = 0; a < nc; ++a) {
    const int b0 = fixed + static_cast<int>(rng() % static_cast<unsigned>(nb - fixed));
    int b1 = static_cast<int>(rng() % static_cast<unsigned>(nb));
    if (b1 == b0) b1 = (b0 + 1) % nb;
    const Eigen::Matrix3d E = Eigen::Quaterniond(U(rng), U(rng), U(rng), U(rng)).normalized().toRotationMatrix().transpose();
    const Eigen::Vector3d p(U(rng), U(rng), U(rng));
    const int bs[2] = {b0, b1};
    for (int s = 0; s < 2; ++s) {
      f.body[2 * a + s] = bs[s] < fixed ? -1 : bs[s];
      const Eigen::Vector3d r = p - centre[bs[s]];
      const double sign = s == 0 ? 1.0 : -1.0;
      double* h = &f.H[static_cast<std::size_t>((a * 2 + s) * 3 * k)];
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d e = E.row(i).transpose(), c = r.cross(e);
        for (int j = 0; j < 3; ++j) h[i * k + j] = sign * e[j], h[i * k + 3 + j] = sign * c[j];
      }
    }
  }
  if (compliance) {
    f.diagonal.resize(3 * nc);
    for (std::size_t i = 0; i < f.diagonal.size(); ++i) f.diagonal[i] = 0.01 * static_cast<double>(1 + i % 3);
  }
  P.W = moreau::assemble_w(3, f);
  P.q.resize(3 * nc);
  for (int a = 0; a < nc; ++a) {
    P.q[3 * a] = -0.5 - 0.5 * (U(rng) + 1);  // approaching
    P.q[3 * a + 1] = U(rng), P.q[3 * a + 2] = U(rng);
  }
  P.mu = Eigen::VectorXd::Constant(nc, 0.3);
  return P;
}

/// A packed product of APGD (ScaledFactor, RigidFrames) against W assembled from the
/// factor, on a seeded random x: the product and the diagonal to rounding.
template <class Packed, class Problem>
void expect_multiplies_by_w(Packed& packed, const Problem& P, unsigned seed, const std::string& what) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  const Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(P.q.size(), [&] { return U(rng); });
  Eigen::VectorXd out;
  packed.multiply(x, out);
  const Eigen::VectorXd want = P.W * x;
  EXPECT_LT((out - want).norm(), 1e-13 * (1 + want.norm())) << what;
  EXPECT_LT((packed.diagonal() - Eigen::VectorXd(P.W.diagonal())).norm(), 1e-13 * (1 + want.norm())) << what;
  EXPECT_GT(want.norm(), 0.1) << what;
}

TEST(ApgdFactored, RigidFramesMultiplyByW) {
  // APGD's product packed from the frames and lever arms of 3D rigid bodies (15 doubles a
  // contact: rigid_frames.hpp) against W assembled from the factor, with fixed bodies and
  // the compliance; to rounding. A factor of another form (random H blocks, locked
  // rotations) is not packed that way.
  for (unsigned seed : {41u, 42u, 43u})
    for (bool compliance : {false, true}) {
      const auto P = rigid_frames_problem(seed, compliance);
      moreau::apgd::RigidFrames F;
      ASSERT_TRUE(F.prepare(3, P.factor));
      expect_multiplies_by_w(F, P, seed, "seed " + std::to_string(seed));
    }
  moreau::apgd::RigidFrames F;
  EXPECT_FALSE(F.prepare(3, varied_problem(3, 31, false).factor));
  auto locked = rigid_frames_problem(44, false);
  locked.factor.inverse_mass[static_cast<std::size_t>(locked.factor.body[0] * 36)] = 0;  // contact 0's first body: x locked
  EXPECT_FALSE(F.prepare(3, locked.factor));
  auto bent = rigid_frames_problem(45, false);
  bent.factor.H[3] += 1e-6;  // contact 0, side 0: a rotational entry off r × n
  EXPECT_FALSE(F.prepare(3, bent.factor));
  EXPECT_FALSE(F.prepare(2, varied_problem(2, 31, false).factor));
}

TEST(ApgdFactored, RigidFramesSameAnswerAsWithW) {
  // End to end: APGD through the rigid-frame product reaches W's answer.
  for (bool compliance : {false, true}) apgd_same_answer_through_the_factor(rigid_frames_problem(46, compliance));
}

TEST(ApgdFactored, PackedScaledFactorMultipliesByW) {
  // APGD's packed product (H̃ = H L with M⁻¹ = L Lᵀ folded in) against W assembled from
  // the factor: general, diagonal (sphere) and locked (semi-definite) inverse masses, fixed
  // bodies, with and without the laws' compliance; to rounding.
  for (int d : {2, 3})
    for (unsigned seed : {31u, 32u, 33u})
      for (bool compliance : {false, true}) {
        const auto P = varied_problem(d, seed, compliance);
        moreau::apgd::ScaledFactor S;
        ASSERT_TRUE(S.prepare(d, P.factor));
        expect_multiplies_by_w(S, P, seed, "dim " + std::to_string(d) + ", seed " + std::to_string(seed));
      }
}

TEST(ApgdFactored, IndefiniteInverseMassIsNotPackedAndApgdStillSolves) {
  // An inverse mass that is not positive semi-definite has no L with L Lᵀ = M⁻¹: nothing is
  // packed, and APGD multiplies through multiply_w instead, with the answer found with W.
  auto P = varied_problem(3, 34, false);
  const int k = P.factor.k;
  P.factor.inverse_mass[static_cast<std::size_t>(4 * k * k)] = -1e-3;  // body 4: a negative pivot
  moreau::apgd::ScaledFactor S;
  EXPECT_FALSE(S.prepare(3, P.factor));
  P.W = moreau::assemble_w(3, P.factor);
  apgd_same_answer_through_the_factor(P);
}

TEST(ApgdFactored, PackedProductSameAnswerAsWWithLockedAndSphericalBodies) {
  // End to end through the packed product, on the varied inverse masses and the compliance.
  for (int d : {2, 3})
    for (bool compliance : {false, true}) apgd_same_answer_through_the_factor(varied_problem(d, 35, compliance));
}

TEST(ApgdFactored, SlicesWithKeptProductsAreOneRun) {
  // `auto` runs APGD in slices on one problem: later slices keep the packed products and
  // the run's state (State::products, same_problem, resume) and the error is taken from
  // the iteration (recompute_error = false). The slices must be the run alone, iterate for
  // iterate: the same answer bit for bit and the same iteration count; and the state's
  // product gives u = W r + q. With either scaling of the step.
  for (int d : {2, 3})
    for (auto scaling : {moreau::apgd::Scaling::contact, moreau::apgd::Scaling::normal_tangent}) {
    auto P = varied_problem(d, 36, true);
    P.W.resize(0, 0);  // through the factor (packed)
    moreau::apgd::Options one;
    // Not 1e-10: the one run's error is recomputed from r with a fresh product, which
    // differs from the iteration's updated W x by ~1e-13 of the error's scale, so at 1e-10
    // the run could stop (iteration: within) and report a miss (1.0006e-10, dim 2).
    one.tolerance = 1e-9;
    one.max_iterations = 100000;
    one.scaling = scaling;
    Eigen::VectorXd r1, u1;
    const auto rep1 = moreau::apgd::solve(P, one, r1, u1);
    ASSERT_TRUE(rep1.converged) << rep1.error;
    moreau::apgd::State state;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(P.q.size()), u;
    long iterations = 0;
    moreau::SolverReport rep;
    for (int slice = 0; slice < 1000 && !rep.converged; ++slice) {
      moreau::apgd::Options o = one;
      o.max_iterations = slice == 0 ? 0 : 1 + slice % 4;  // the start alone first, as auto's start check
      o.state = &state;
      o.same_problem = o.resume = slice > 0;
      o.recompute_error = false;
      rep = moreau::apgd::solve(P, o, r, u);
      iterations += rep.iterations;
    }
    EXPECT_EQ(iterations, rep1.iterations) << "dim " << d;
    EXPECT_EQ((r - r1).norm(), 0.0) << "dim " << d;
    // The error from the iteration's W x (updated, not recomputed): the same to rounding of
    // the normalised error's scale (1e-13 measured; 1e-4 of an error of 1e-9).
    EXPECT_NEAR(rep.error, rep1.error, 1e-12) << "dim " << d;
    Eigen::VectorXd v;
    ASSERT_TRUE(moreau::apgd::velocities(state, P, r, v));
    EXPECT_LT((v - u1).norm(), 1e-12 * (1 + u1.norm()));
  }
}

TEST(ApgdFactored, ErrorEveryFewStepsStopsWithinThemAtAMeasuredIterate) {
  // check_every = k: the iterates are the same, only measured at the first step and every
  // k-th, so the run stops at most k − 1 steps after the run measured at every step, at a
  // measured iterate whose error (recomputed from r) is within the tolerance.
  for (int d : {2, 3})
    for (long k : {2L, 3L, 5L}) {
      auto P = varied_problem(d, 37, false);
      P.W.resize(0, 0);
      moreau::apgd::Options o;
      o.tolerance = 1e-9;
      o.max_iterations = 100000;
      Eigen::VectorXd r1, u1, rk, uk;
      const auto rep1 = moreau::apgd::solve(P, o, r1, u1);
      o.check_every = k;
      const auto repk = moreau::apgd::solve(P, o, rk, uk);
      ASSERT_TRUE(rep1.converged);
      ASSERT_TRUE(repk.converged) << "dim " << d << ", k " << k << ": " << repk.error;
      EXPECT_GE(repk.iterations, rep1.iterations);
      EXPECT_LT(repk.iterations, rep1.iterations + k);
      EXPECT_TRUE(repk.iterations == 1 || repk.iterations % k == 0) << repk.iterations;
      EXPECT_NEAR(repk.error, moreau::natural_map_error(varied_problem(d, 37, false), rk), 1e-12);
    }
}

}  // namespace

namespace {

TEST(ApgdFactored, NormalTangentScalingReachesThePlainScalingsAnswer) {
  // The step scaled per direction (normal and tangential diagonal entries of W apart, the
  // cone projected in that metric) converges to the answer of the scalar scaling, through
  // the packed product and with W, on the varied inverse masses (a sphere's rotation makes
  // its tangential entries larger than the normal) with and without the laws' compliance.
  // W is definite on these problems, so r is unique: both runs within 1e-6 of each other at
  // the tolerance 1e-9 (measured: at most 2e-7; seeds whose W is nearly singular, e.g. dim 2
  // seed 36, take 10⁴ steps with either scaling and end 1e-5 apart, so they are not used).
  for (int d : {2, 3})
    for (unsigned seed : {31u, 32u, 33u, 34u, 35u})
      for (bool compliance : {false, true}) {
        const auto full = varied_problem(d, seed, compliance);
        auto factored = full;
        factored.W.resize(0, 0);
        moreau::apgd::Options plain;
        plain.tolerance = 1e-9;
        plain.max_iterations = 20000;
        auto split = plain;
        split.scaling = moreau::apgd::Scaling::normal_tangent;
        Eigen::VectorXd r0, u0, rw, uw, rf, uf;
        const auto rep0 = moreau::apgd::solve(full, plain, r0, u0);
        const auto repw = moreau::apgd::solve(full, split, rw, uw);
        const auto repf = moreau::apgd::solve(factored, split, rf, uf);
        SCOPED_TRACE("dim " + std::to_string(d) + ", seed " + std::to_string(seed) + (compliance ? ", compliance" : ""));
        ASSERT_TRUE(rep0.converged) << rep0.error;
        ASSERT_TRUE(repw.converged) << repw.error;
        ASSERT_TRUE(repf.converged) << repf.error;
        EXPECT_NEAR(repf.error, moreau::natural_map_error(full, rf), 1e-12);
        EXPECT_LT((rw - r0).norm(), 1e-6 * (1 + r0.norm())) << (rw - r0).norm();
        EXPECT_LT((rf - r0).norm(), 1e-6 * (1 + r0.norm())) << (rf - r0).norm();
        // The scalings differ on these problems (else the test would compare a run with itself).
        const Eigen::VectorXd w = full.W.diagonal();
        bool anisotropic = false;
        for (Eigen::Index a = 0; a < full.contacts(); ++a) anisotropic |= std::abs(w[a * d + 1] - w[a * d]) > 0.1 * w[a * d];
        EXPECT_TRUE(anisotropic);
      }
}

TEST(ApgdFactored, KeptProductsOfTheOtherScalingAreNotTaken) {
  // The kept products carry the scaling they were packed with: a later call on the same
  // problem with the other scaling packs its own (the same iterates as a fresh call).
  for (int d : {2, 3}) {
    auto P = varied_problem(d, 36, true);
    P.W.resize(0, 0);
    moreau::apgd::Options one;
    one.tolerance = 1e-9;  // as in SlicesWithKeptProductsAreOneRun
    one.max_iterations = 100000;
    one.scaling = moreau::apgd::Scaling::normal_tangent;
    moreau::apgd::State state;
    one.state = &state;
    Eigen::VectorXd r1, u1;
    ASSERT_TRUE(moreau::apgd::solve(P, one, r1, u1).converged);
    // A later call with the scalar scaling does not take the split one's products: it is
    // the plain run from r1 (the same iterations as a fresh call).
    moreau::apgd::Options plain;
    plain.tolerance = 1e-12;
    plain.max_iterations = 5;
    plain.state = &state;
    plain.same_problem = true;
    Eigen::VectorXd ra = r1, rb = r1, ua, ub;
    moreau::apgd::solve(P, plain, ra, ua);
    plain.state = nullptr;
    plain.same_problem = false;
    moreau::apgd::solve(P, plain, rb, ub);
    EXPECT_EQ((ra - rb).norm(), 0.0) << "dim " << d;
  }
}

}  // namespace

namespace {

TEST(ApgdFactored, DiagonalInverseMassesArePackedAsTheGeneralOnes) {
  // A diagonal inverse mass (spheres, disks) is split without the general Cholesky loop
  // (scaled_factor.cpp): the product is W's to rounding, also with a locked direction (a
  // zero diagonal entry); a negative entry is not semi-definite and is not packed.
  for (int d : {2, 3}) {
    auto P = varied_problem(d, 40, false);
    auto& f = P.factor;
    const int k = f.k;
    for (int b : {4, 5})
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) f.inverse_mass[static_cast<std::size_t>(b * k * k + i * k + j)] = i != j ? 0.0 : b == 5 && i == k - 1 ? 0.0 : 0.5 + i;
    P.W = moreau::assemble_w(d, f);
    moreau::apgd::ScaledFactor S;
    ASSERT_TRUE(S.prepare(d, f));
    std::mt19937 rng(40);
    std::uniform_real_distribution<double> U(-1, 1);
    const Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(P.q.size(), [&] { return U(rng); });
    Eigen::VectorXd out;
    S.multiply(x, out);
    const Eigen::VectorXd want = P.W * x;
    EXPECT_LT((out - want).norm(), 1e-13 * (1 + want.norm())) << "dim " << d;
    f.inverse_mass[static_cast<std::size_t>(5 * k * k + (k - 1) * k + k - 1)] = -1e-3;
    EXPECT_FALSE(S.prepare(d, f)) << "dim " << d;
  }
}

}  // namespace

TEST(NlgsBodies, ASweepCountsTheSameWorkPerContactAtEverySize) {
  // A sweep through the records costs as much per contact at 10⁴ spheres as at 10³ (shadows
  // of `apgd` on bench_spheres.py's touching spheres, 10 steps at 1e-4: 70, 70, 79 CPU ns per
  // contact and sweep at 3200, 9424, 30894 contacts, 1.4 to 13 MB of records), so its count
  // is linear in the contacts. Before, records beyond 2 MB counted up to 4 times more per
  // contact, and NLGS took 0.21–0.29 ns per counted unit there against 0.67 below and
  // APGD's 0.87 (docs/solvers-history.md "CPU time per counted unit by scene").
  auto spheres = [](Eigen::Index nc) {
    moreau::LocalProblem P;
    P.dim = 3;
    P.mu = Eigen::VectorXd::Constant(nc, 0.3);
    return P;
  };
  const moreau::LocalProblem small = spheres(3200), large = spheres(30894);
  for (const bool dense : {false, true}) {
    const double record = dense ? 85 : 53;  // 3D records: M⁻¹Hᵀ blocks, or scalar inverse masses
    ASSERT_GT(moreau::WorkCosts::record_bytes(large, record), 4 * moreau::WorkCosts::cache_bytes);  // beyond the caches
    const double per_small = moreau::WorkCosts::body_sweep(small, record, dense) / 3200;
    const double per_large = moreau::WorkCosts::body_sweep(large, record, dense) / 30894;
    EXPECT_NEAR(per_large / per_small, 1.0, 0.01) << "dense " << dense;
  }
}
