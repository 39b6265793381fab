// `auto` with `remember`: its memory of the members' costs is the solver's state
// (Solver::state_fields): saved into the `solver` set and loaded into another instance,
// the later solves are bit-identical to those of the instance that learnt it.
#include <cmath>

#include "solver_cases.hpp"

using namespace solver_cases;

namespace {

moreau::EntitySet state_set(const moreau::Solver& s) {
  moreau::EntitySet set(moreau::sets::solver, 3);
  for (const auto& f : s.state_fields(3)) set.declare(f);
  set.add_rows(1);
  return set;
}

std::vector<double> values(const moreau::EntitySet& set) {
  std::vector<double> v;
  for (const auto& f : set.fields()) v.insert(v.end(), f.data(), f.data() + f.components());
  return v;
}

}  // namespace

TEST(AutoMemory, LoadedIntoAnotherInstanceTheLaterSolvesAreBitIdentical) {
  // A sequence of problems as a time-stepper gives them: W fixed, q drifting, each solve
  // warm-started from the last answer.
  const moreau::LocalProblem base = random_problem(3, 6, 14, 0.5, 100.0, 5u);
  auto at = [&](int k) {
    moreau::LocalProblem p = base;
    for (Eigen::Index i = 0; i < p.q.size(); ++i) p.q[i] += 0.05 * std::sin(0.7 * k + static_cast<double>(i));
    return p;
  };
  const nlohmann::json params = {{"tolerance", 1e-9}, {"remember", true}};
  auto a = make("auto", params);
  Eigen::VectorXd ra, u;
  for (int k = 0; k < 12; ++k) ASSERT_TRUE(a->solve(at(k), ra, u).converged) << k;
  moreau::EntitySet saved = state_set(*a);
  a->save_state(saved);
  const auto& cost = saved.field("member_cost");
  EXPECT_GT(*std::max_element(cost.data(), cost.data() + cost.components()), 0.0) << "it has learnt something";
  EXPECT_EQ(saved.field("solves").data()[0], 12.0);

  auto b = make("auto", params);
  b->load_state(saved);
  Eigen::VectorXd rb = ra, ub;
  for (int k = 12; k < 30; ++k) {
    const auto p = at(k);
    const auto ea = a->solve(p, ra, u), eb = b->solve(p, rb, ub);
    EXPECT_EQ(ea.iterations, eb.iterations) << k;
    ASSERT_EQ(ra.size(), rb.size());
    for (Eigen::Index i = 0; i < ra.size(); ++i) ASSERT_EQ(ra[i], rb[i]) << "solve " << k << ", r[" << i << "]";
  }
  moreau::EntitySet sa = state_set(*a), sb = state_set(*b);
  a->save_state(sa);
  b->save_state(sb);
  EXPECT_EQ(values(sa), values(sb));
}

TEST(AutoMemory, WithoutRememberAutoKeepsNoState) {
  EXPECT_TRUE(make("auto", {{"remember", false}})->state_fields(2).empty());
  EXPECT_EQ(make("auto", {{"remember", true}})->state_fields(2).size(), 6u);
  EXPECT_TRUE(make("nlgs")->state_fields(3).empty());
}
