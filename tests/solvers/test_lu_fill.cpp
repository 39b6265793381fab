// Newton's LU fill predicted before a factorisation (plugins/solver/lu_fill.hpp), as `auto`
// estimates a Newton step from it (WorkCosts::newton_step): against the step Newton counts.
#include <filesystem>
#include <random>

#include "solver_cases.hpp"
#include "../../plugins/solver/lu_fill.hpp"
#include "../../plugins/solver/work.hpp"
#include "newton_core.hpp"

using namespace solver_cases;

namespace {

/// The work Newton counts for its first step from r = 0 (its start's error left out), and
/// its factors' entries.
std::pair<double, double> measured_step(const moreau::LocalProblem& P) {
  moreau::newton::Options o;
  o.max_iterations = 1;
  o.tolerance = 0;
  double work = 0;
  o.work = &work;
  moreau::newton::Newton newton;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(P.q.size()), u;
  newton.solve(P, o, r, u);
  const moreau::WorkCosts c = moreau::WorkCosts::of(P, false);
  return {work - c.product - c.error, newton.factor_entries()};
}

double estimated_step(const moreau::LocalProblem& P, double nnz_l, double nnz_u) {
  return moreau::WorkCosts::newton_step(static_cast<double>(P.W.nonZeros()), static_cast<double>(P.q.size()), nnz_l, nnz_u,
                                        moreau::WorkCosts::of(P, false).product);
}

/// Spheres on a g×g×g lattice (6 dof each), a contact between each sphere and its
/// neighbour along x, y and z and each bottom sphere and the ground, random frames: the
/// contact graph of a 3D pile, whose LU fills in far beyond W's size (as wet_pile_3d's).
moreau::LocalProblem lattice_3d(int g, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  const int bodies = g * g * g, dof = 6;
  std::vector<std::pair<int, int>> pairs;  // (body, other body or −1: the ground)
  auto id = [g](int i, int j, int k) { return (k * g + j) * g + i; };
  for (int k = 0; k < g; ++k)
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        if (i + 1 < g) pairs.emplace_back(id(i, j, k), id(i + 1, j, k));
        if (j + 1 < g) pairs.emplace_back(id(i, j, k), id(i, j + 1, k));
        if (k + 1 < g) pairs.emplace_back(id(i, j, k), id(i, j, k + 1));
        if (k == 0) pairs.emplace_back(id(i, j, k), -1);
      }
  const int nc = static_cast<int>(pairs.size()), n = 3 * nc;
  std::vector<Eigen::Triplet<double>> t;
  for (int a = 0; a < nc; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = side == 0 ? pairs[a].first : pairs[a].second;
      if (b < 0) continue;
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < dof; ++k) t.emplace_back(b * dof + k, a * 3 + i, (side == 0 ? 1 : -1) * U(rng));
    }
  Eigen::SparseMatrix<double> H(bodies * dof, n);
  H.setFromTriplets(t.begin(), t.end());
  moreau::LocalProblem p;
  p.dim = 3;
  p.W = Eigen::SparseMatrix<double>(H.transpose() * H);
  p.W.makeCompressed();
  p.q.resize(n);
  for (int i = 0; i < n; ++i) p.q[i] = i % 3 == 0 ? -1.0 : 0.2 * U(rng);
  p.mu = Eigen::VectorXd::Constant(nc, 0.5);
  return p;
}

}  // namespace

// The estimate from W's size alone (each factor taken as nnz(W)) is under a third of the
// step here; the predicted fill brings it within 2× (its factors within 1.5× of Newton's).
TEST(LuFill, NewtonStepOfA3DPileIsPredicted) {
  const moreau::LocalProblem P = lattice_3d(7, 3);
  const auto [step, entries] = measured_step(P);
  const moreau::LuFill f = moreau::predicted_lu_fill(P.W, P.dim);
  const double nnz = static_cast<double>(P.W.nonZeros());
  EXPECT_LT(estimated_step(P, nnz, nnz), step / 3) << "W's size alone no longer misses here: the test shows nothing";
  EXPECT_GT(f.nnz_l + f.nnz_u, entries / 1.5);
  EXPECT_LT(f.nnz_l + f.nnz_u, entries * 1.5);
  EXPECT_GT(estimated_step(P, f.nnz_l, f.nnz_u), step / 2);
  EXPECT_LT(estimated_step(P, f.nnz_l, f.nnz_u), step * 2);
  EXPECT_LT(f.work, step / 3);  // the analysis costs a fraction of the step it predicts
}

// On every problem of the guarantee's corpus whose first Newton step factorises.
TEST(LuFill, NewtonStepOfCorpusProblemsIsPredicted) {
  int checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(MOREAU_SOURCE_DIR) + "/tests/data/corpus")) {
    const moreau::LocalProblem P = moreau::fclib::read(e.path().string()).local;
    const auto [step, entries] = measured_step(P);
    if (entries == 0) continue;  // no step taken (r = 0 is the answer)
    const moreau::LuFill f = moreau::predicted_lu_fill(P.W, P.dim);
    const double estimate = estimated_step(P, f.nnz_l, f.nnz_u);
    EXPECT_GT(estimate, step / 2) << e.path();
    EXPECT_LT(estimate, step * 2) << e.path();
    ++checked;
  }
  EXPECT_GE(checked, 6);
}
