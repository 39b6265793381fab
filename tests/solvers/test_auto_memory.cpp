// `auto` with `remember`: its memory of the members' costs is the solver's state
// (Solver::state_fields): saved into the `solver` set and loaded into another instance,
// the later solves are bit-identical to those of the instance that learnt it.
#include <cmath>
#include <moreau/factor_matrix.hpp>

#include "../work.hpp"  // plugins/solver (through the nlgs include directory)
#include "factored_problem.hpp"
#include "solver_cases.hpp"

using namespace solver_cases;

namespace {

moreau::EntitySet state_set(const moreau::Solver& s) {
  moreau::EntitySet set(moreau::sets::solver, 3);
  for (const auto& f : s.state_fields(3)) set.declare(f);
  set.add_rows(1);
  return set;
}

/// The solver's state as save_state() writes it.
moreau::EntitySet saved_state(const moreau::Solver& s) {
  moreau::EntitySet set = state_set(s);
  s.save_state(set);
  return set;
}

std::vector<double> values(const moreau::EntitySet& set) {
  std::vector<double> v;
  for (const auto& f : set.fields()) v.insert(v.end(), f.data(), f.data() + f.components());
  return v;
}

/// A problem as the time-stepper gives it to `auto`: the factor W = H M⁻¹ Hᵀ only.
moreau::LocalProblem factored(int d, int bodies, int nc, unsigned seed) {
  moreau::LocalProblem p = factored_problem(d, bodies, 2, nc, seed);
  p.W.resize(0, 0);
  return p;
}

/// A memory in which APGD is the remembered member (work per contact `apgd`, NLGS's 10⁶)
/// and no member is tried first before solve 10⁶; `at_rest`: the last solve was at rest.
void remembered_apgd(moreau::Solver& s, double apgd, bool at_rest) {
  moreau::EntitySet set = state_set(s);
  set.field("solves").data()[0] = 10;
  for (int k = 0; k < 5; ++k) {
    set.field("member_cost").data()[k] = k == 0 ? 1e6 : k == 1 ? apgd : 0.0;
    set.field("member_next_try").data()[k] = 1e6;
    set.field("member_try_interval").data()[k] = 4;
  }
  set.field("at_rest").data()[0] = at_rest ? 1 : 0;
  s.load_state(set);
}

}  // namespace

TEST(AutoMemory, AfterAStepAtRestTheWarmStartIsCheckedFirst) {
  // After a step at rest the warm start's error is checked first (APGD's start: one product
  // and the error), and a warm start within the tolerance is the answer, as `apgd` alone
  // takes it: no iteration, no NLGS sweep (until branch i15-light NLGS swept it). The
  // step stays at rest. Without a step at rest before, APGD remembered: its own check
  // accepts it (counted as one iteration), for the same work.
  const moreau::LocalProblem p = factored(2, 8, 16, 11u);
  Eigen::VectorXd answer, u;
  ASSERT_TRUE(make("auto", {{"tolerance", 1e-12}, {"remember", false}})->solve(p, answer, u).converged);
  const nlohmann::json params = {{"tolerance", 1e-3}, {"remember", true}, {"direct_max_contacts", 0}};
  moreau::SolverReport rep[2];
  Eigen::VectorXd out[2], vel[2];
  for (int at_rest = 0; at_rest < 2; ++at_rest) {
    auto a = make("auto", params);
    remembered_apgd(*a, 1e3, at_rest == 1);
    out[at_rest] = answer;
    rep[at_rest] = a->solve(p, out[at_rest], vel[at_rest]);
    ASSERT_TRUE(rep[at_rest].converged) << at_rest;
    moreau::EntitySet after = saved_state(*a);
    EXPECT_EQ(after.field("at_rest").data()[0], 1.0) << "the warm start was the answer";
  }
  EXPECT_EQ(rep[0].iterations, 1) << "APGD's check";
  EXPECT_EQ(rep[1].iterations, 0) << "the warm start's check only";
  EXPECT_EQ(rep[1].work, rep[0].work);
  EXPECT_LT((out[1] - answer).norm(), 1e-12 * answer.norm()) << "the warm start (projected on the cones) is the answer";
  ASSERT_EQ(vel[1].size(), answer.size());
  Eigen::VectorXd w;
  std::vector<double> impulse, dv;
  moreau::multiply_w(p.dim, p.factor, out[1], w, impulse, dv);
  EXPECT_LT((vel[1] - (w + p.q)).norm(), 1e-12 * (1 + p.q.norm())) << "its u = W r + q";
}

TEST(AutoMemory, AChallengerThatWinsAtItsFirstCheckIsLearnt) {
  // NLGS remembered at a high cost (a cold first step), APGD not yet known and due for a
  // try: on a warm start that APGD accepts at its check it wins, and is learnt at what it
  // took (before, a win at the first check was not learnt: NLGS stayed remembered at its
  // cold cost and APGD was tried again every 4 solves, block_on_incline_3d).
  const moreau::LocalProblem p = factored(2, 8, 16, 11u);
  Eigen::VectorXd answer, u;
  ASSERT_TRUE(make("auto", {{"tolerance", 1e-12}, {"remember", false}})->solve(p, answer, u).converged);
  auto a = make("auto", {{"tolerance", 1e-3}, {"remember", true}, {"direct_max_contacts", 0}});
  moreau::EntitySet set = state_set(*a);
  set.field("solves").data()[0] = 10;
  for (int k = 0; k < 5; ++k) {
    set.field("member_cost").data()[k] = k == 0 ? 1e6 : 0.0;
    set.field("member_next_try").data()[k] = k == 1 ? 0 : 1e6;
    set.field("member_try_interval").data()[k] = 4;
  }
  a->load_state(set);
  Eigen::VectorXd r = answer;
  const moreau::SolverReport rep = a->solve(p, r, u);
  ASSERT_TRUE(rep.converged);
  EXPECT_EQ(rep.iterations, 1) << "APGD's check";
  moreau::EntitySet after = saved_state(*a);
  const double apgd = after.field("member_cost").data()[1];
  EXPECT_EQ(apgd, rep.work / 16) << "learnt at what it took";
  EXPECT_EQ(after.field("member_cost").data()[0], 1e6) << "NLGS did not run";
  EXPECT_EQ(after.field("member_try_interval").data()[1], 4.0);
}

TEST(AutoMemory, TheRememberedMemberIsLearntAtWhatItTookPastItsBudget) {
  // APGD remembered at a work per contact far below what this solve needs: it stops at its
  // budget (three times that), goes on with its own run in the slices and converges. Its
  // memory then rises towards what it took, at most twofold a solve (one hard step must not
  // leave it far above the usual cost); before, a member that needed more than its budget
  // was never learnt, so its budget stayed short and every such step paid for probes.
  const moreau::LocalProblem p = factored(2, 8, 16, 11u);
  auto a = make("auto", {{"tolerance", 1e-6}, {"remember", true}, {"direct_max_contacts", 0}, {"nlgs_sweeps", 0}});
  const double remembered = 1.0;
  remembered_apgd(*a, remembered, false);
  double expected = remembered, took = 0;
  for (int k = 0; k < 6; ++k) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u;
    const moreau::SolverReport rep = a->solve(p, r, u);
    ASSERT_TRUE(rep.converged) << k;
    took = rep.work / 16;
    expected *= 2;
    moreau::EntitySet after = saved_state(*a);
    EXPECT_EQ(after.field("member_cost").data()[1], expected) << "solve " << k << ": APGD's memory doubles";
  }
  EXPECT_GT(took, 3 * expected) << "still below what it takes";
}

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
  moreau::EntitySet saved = saved_state(*a);
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
  const moreau::EntitySet sa = saved_state(*a), sb = saved_state(*b);
  EXPECT_EQ(values(sa), values(sb));
}

TEST(AutoMemory, WithoutRememberAutoKeepsNoState) {
  EXPECT_TRUE(make("auto", {{"remember", false}})->state_fields(2).empty());
  EXPECT_EQ(make("auto", {{"remember", true}})->state_fields(2).size(), 6u);
  EXPECT_TRUE(make("nlgs")->state_fields(3).empty());
}

TEST(AutoMemory, InATimeStepNewtonWaitsForTheWorkOfItsProbe) {
  // Ski rental in a time step: Newton's probe (4 steps, each a factorisation) is paid only
  // once the work spent reaches its cost (its step remembered from earlier solves), whatever
  // the slices' rates say: near the tolerance they are noise (APGD's error is not monotone),
  // and on wet_pile_3d Newton was probed at once on 650 3D contacts, 1.2e9 units a solve,
  // on steps that APGD alone finishes. Here APGD is remembered far below its need, so the
  // slices start at once; before, their rates sent the solve to Newton's probe at once
  // (1.27e6 units, 3.5 times the solve without a factorisation, direct_max_contacts 0); now
  // Newton never runs, and the factorisations (ADMM's one step once the work reaches it)
  // cost at most as much again as the solve without them (ski rental).
  const int nc = 40;
  const moreau::LocalProblem p = factored(3, 20, nc, 3u);
  const double step = 1e3;  // Newton's remembered step, work per contact: a probe of 1.6e5
  moreau::SolverReport rep[2];
  double newton_step_after = 0;
  for (int direct = 0; direct < 2; ++direct) {
    auto a = make("auto", {{"tolerance", 1e-6}, {"remember", true}, {"direct_max_contacts", direct ? 1000 : 0}});
    remembered_apgd(*a, 1.0, false);
    moreau::EntitySet mem = saved_state(*a);
    mem.field("member_iteration").data()[2] = step;
    a->load_state(mem);
    Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u;
    rep[direct] = a->solve(p, r, u);
    ASSERT_TRUE(rep[direct].converged) << direct;
    a->save_state(mem);
    newton_step_after = mem.field("member_iteration").data()[2];
  }
  EXPECT_EQ(newton_step_after, step) << "Newton did not run";
  EXPECT_GT(rep[1].work, 4 * step * nc) << "the solve went past the probe's work";
  EXPECT_LE(rep[1].work, 2 * rep[0].work) << "without a factorisation: " << rep[0].work;
}

TEST(AutoMemory, AMemberThatDidNotConvergeIsRememberedAtMostAtItsWorkToItsCap) {
  // A tolerance no member reaches within `max_iterations` = 4: every member stops at its
  // cap, and its extrapolated need (its work to converge at its last rate) is far above
  // what it can spend. Its memory is at most its work to that cap (here: what it spent, at
  // most the solve's work); before, a slice that gained next to nothing was remembered at
  // its extrapolation (ADMM on a 650-contact step of wet_pile_3d: 7·10²⁰ units a contact).
  const int nc = 12;
  const moreau::LocalProblem p = factored(3, 6, nc, 7u);
  auto a = make("auto", {{"tolerance", 1e-15}, {"remember", true}, {"max_iterations", 4}});
  Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u;
  const moreau::SolverReport rep = a->solve(p, r, u);
  ASSERT_FALSE(rep.converged);
  moreau::EntitySet after = saved_state(*a);
  const double* cost = after.field("member_cost").data();
  int learnt = 0;
  for (int k = 0; k < 5; ++k) {
    EXPECT_LE(cost[k], rep.work / nc * (1 + 1e-12)) << "member " << k;
    learnt += cost[k] > 0;
  }
  EXPECT_GE(learnt, 2) << "members tried and learnt";
}

TEST(AutoMemory, InATimeStepGivenWithWTheAnswerAPGDFinishesKeepsItsProduct) {
  // Finite-element bodies: the time-stepper gives W itself (no factor), with its stopping
  // scale (LocalProblem::error_scale). There, as through the bodies, the answer APGD
  // finishes keeps APGD's u = W r + q (the same product `apgd` alone returns): no second
  // product and error evaluation, a tenth of a warm step of blocks_on_elastic_slab_3d
  // (docs/solvers.md "Finite-element scenes"). Given with W outside a time step (FCLib,
  // the guarantee's counts), the answer's u and error are recomputed and counted as before.
  // Here error_scale = ‖q‖, the FCLib measure: the same iterates, the same answer.
  moreau::LocalProblem p = factored_problem(3, 20, 2, 40, 3u);
  p.factor = moreau::BodyFactor{};  // W only
  moreau::LocalProblem step = p;
  step.error_scale = p.q.norm();
  moreau::SolverReport rep[2];
  Eigen::VectorXd r[2], u[2];
  for (int in_step = 0; in_step < 2; ++in_step) {
    auto a = make("auto", {{"tolerance", 1e-6}, {"remember", true}});
    remembered_apgd(*a, 1e5, false);  // APGD first, on a budget it finishes within
    r[in_step] = Eigen::VectorXd::Zero(p.q.size());
    rep[in_step] = a->solve(in_step ? step : p, r[in_step], u[in_step]);
    ASSERT_TRUE(rep[in_step].converged) << in_step;
  }
  EXPECT_EQ(r[1], r[0]) << "the same iterates";
  // APGD's error from its own product: the same up to rounding (relative to ‖q‖, ~1e-16)
  EXPECT_NEAR(rep[1].error, rep[0].error, 1e-13);
  const Eigen::VectorXd exact = p.W * r[1] + p.q;
  EXPECT_LE((u[1] - exact).norm(), 1e-12 * exact.norm()) << "APGD's u is W r + q";
  const moreau::WorkCosts c = moreau::WorkCosts::of(p, false);
  EXPECT_NEAR(rep[0].work - rep[1].work, c.product + c.error, 1e-9 * rep[0].work) << "the recomputation, outside a time step only";
}

TEST(AutoMemory, AWinnerThatFinishedFromAnotherMembersIterateIsLearnt) {
  // A cold solve where NLGS's first stage and slices improve the best iterate and APGD
  // finishes from it: APGD, the winner, did not run from the warm start alone, yet it is
  // what the step needs, so it is learnt (at its own work) and is the next solve's
  // incumbent. Before, it was not learnt; here nothing was remembered (NLGS's need was
  // unknown), and on mortar_wall_2d at 1e-8 only ADMM, which failed, was: its need was the
  // next challenger's budget.
  const moreau::LocalProblem p = factored(2, 4, 8, 1u);
  auto a = make("auto", {{"tolerance", 1e-8}, {"remember", true}, {"direct_max_contacts", 0}});
  Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u;
  const moreau::SolverReport rep = a->solve(p, r, u);
  ASSERT_TRUE(rep.converged);
  moreau::EntitySet after = saved_state(*a);
  const double* cost = after.field("member_cost").data();
  EXPECT_GT(cost[1], 0.0) << "APGD, the winner, is learnt";
  EXPECT_LT(cost[1], rep.work / 8) << "at its own work, below the solve's";
  EXPECT_TRUE(cost[0] == 0 || cost[0] > cost[1]) << "and is the incumbent";
}

TEST(AutoMemory, AStepStillAtRestCountsTheSolveAndLeavesTheMemoryAsItWas) {
  // After a step at rest, a warm start that meets the tolerance ends the solve at its check,
  // before the rest of the set-up (rest_check()): the solve is counted, the memory and the
  // rest flag stay as they were, and the answer is the (projected) warm start with u = W r + q.
  // A warm start above the tolerance goes on from that check to the tolerance.
  const moreau::LocalProblem p = factored(2, 8, 16, 11u);
  Eigen::VectorXd answer, u;
  ASSERT_TRUE(make("auto", {{"tolerance", 1e-12}, {"remember", false}})->solve(p, answer, u).converged);
  const nlohmann::json params = {{"tolerance", 1e-3}, {"remember", true}, {"direct_max_contacts", 0}};
  auto a = make("auto", params);
  remembered_apgd(*a, 1e3, true);
  const std::vector<double> before = values(saved_state(*a));
  Eigen::VectorXd r = answer, v;
  const moreau::SolverReport rep = a->solve(p, r, v);
  ASSERT_TRUE(rep.converged);
  EXPECT_EQ(rep.iterations, 0);
  EXPECT_GT(rep.work, 0.0) << "the check's product and error";
  moreau::EntitySet after = saved_state(*a);
  EXPECT_EQ(after.field("solves").data()[0], 11.0) << "the solve is counted";
  after.field("solves").data()[0] = 10;
  EXPECT_EQ(values(after), before) << "nothing else changed";
  Eigen::VectorXd w;
  std::vector<double> impulse, dv;
  moreau::multiply_w(p.dim, p.factor, r, w, impulse, dv);
  EXPECT_LT((v - (w + p.q)).norm(), 1e-12 * (1 + p.q.norm())) << "its u = W r + q";

  auto b = make("auto", params);
  remembered_apgd(*b, 1e3, true);
  Eigen::VectorXd far = 0.5 * answer;
  const moreau::SolverReport moved = b->solve(p, far, v);
  ASSERT_TRUE(moved.converged);
  EXPECT_GT(moved.iterations, 0) << "the step moved: the members went on";
  EXPECT_EQ(saved_state(*b).field("solves").data()[0], 11.0);
}

TEST(AutoMemory, TheStateIsWrittenAndReadByFieldNameWhateverTheSetsLayout) {
  // save_state() and load_state() keep each field's index in the set and check its name at
  // every use: a set whose fields sit elsewhere (another field first, reversed order) gets
  // the same values by name, and a later save into the usual layout is right again.
  const moreau::LocalProblem p = factored(2, 8, 16, 11u);
  auto a = make("auto", {{"tolerance", 1e-6}, {"remember", true}, {"direct_max_contacts", 0}});
  Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u;
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(a->solve(p, r, u).converged);
  const moreau::EntitySet usual = saved_state(*a);
  moreau::EntitySet other(moreau::sets::solver, 3);
  other.declare(moreau::field_spec(moreau::sets::solver, "something_else", 2, 2, 1, "1", moreau::FieldOutput::frame, true, "", moreau::FileType::real));
  std::vector<moreau::FieldSpec> specs = a->state_fields(3);
  for (auto it = specs.rbegin(); it != specs.rend(); ++it) other.declare(*it);
  other.add_rows(1);
  a->save_state(other);
  for (const moreau::FieldSpec& f : specs)
    for (int i = 0; i < usual.field(f.name).components(); ++i)
      EXPECT_EQ(other.field(f.name).data()[i], usual.field(f.name).data()[i]) << f.name << " " << i;
  EXPECT_EQ(other.field("something_else").data()[0], 0.0) << "untouched";
  auto b = make("auto", {{"tolerance", 1e-6}, {"remember", true}, {"direct_max_contacts", 0}});
  b->load_state(other);
  EXPECT_EQ(values(saved_state(*b)), values(usual)) << "read back by name";
  EXPECT_EQ(values(saved_state(*a)), values(usual)) << "the usual layout again";
}

TEST(AutoMemory, NewtonFromTheBestFirstInATimeStepTakesTheStartsErrorFirst) {
  // A time step that starts with Newton from the best iterate, remembered as the cheapest
  // member: NLGS's records are not packed, so the start's error is not known yet. It is taken
  // first (one product and the error), as Newton's own run and ADMM take theirs: a warm start
  // within the tolerance is then the answer, with no Newton step. Before, Newton's first slice
  // ran "from ∞": here at least one step (a factorisation) on a step that needed none, and
  // where the slice did not finish, an infinite rate that gave Newton the next slice too, as
  // long as all the work spent (silo_janssen_2d at 1e-4: slices of 0.08 s that ended where
  // they began, then APGD finished in 0.01 s).
  const int nc = 16;
  const moreau::LocalProblem p = factored(2, 8, nc, 11u);
  Eigen::VectorXd answer, u;
  ASSERT_TRUE(make("auto", {{"tolerance", 1e-12}, {"remember", false}})->solve(p, answer, u).converged);
  auto a = make("auto", {{"tolerance", 1e-3}, {"remember", true}});
  moreau::EntitySet set = state_set(*a);
  set.field("solves").data()[0] = 10;
  for (int k = 0; k < 5; ++k) {
    set.field("member_cost").data()[k] = k == 3 ? 10.0 : 1e6;  // Newton from the best remembered
    set.field("member_next_try").data()[k] = 1e6;
    set.field("member_try_interval").data()[k] = 4;
  }
  set.field("at_rest").data()[0] = 0;  // (after a step at rest APGD's check comes first: rest_probe())
  a->load_state(set);
  Eigen::VectorXd r = answer;
  const moreau::SolverReport rep = a->solve(p, r, u);
  ASSERT_TRUE(rep.converged);
  EXPECT_EQ(rep.iterations, 0) << "no Newton step: the warm start is the answer";
  const moreau::WorkCosts c = moreau::WorkCosts::of(p, true);
  EXPECT_NEAR(rep.work, c.product + c.error, 1e-9 * rep.work) << "the start's check only";
  EXPECT_LT((r - answer).norm(), 1e-12 * answer.norm());
}

TEST(AutoMemory, InATimeStepGivenWithWNewtonAndADMMStepsCountTheirCallCost) {
  // Finite-element bodies: a time step given with W. There a Newton step counts its cost
  // per call (its sparse LU's analysis and allocations: WorkCosts::newton_step_call_with_w)
  // and an ADMM step its extra (admm_step_with_w) on top of their sizes' counts: uncounted,
  // on elastic_block_hit_by_spheres_3d at 1e-6 Newton and then ADMM were remembered as
  // cheaper than APGD and took 1.5–2× `apgd`'s time on the steps they led (work.hpp). The
  // same problem outside a time step (FCLib, the guarantee's counts) counts as before;
  // error_scale = ‖q‖ is the FCLib measure, so the iterates are the same.
  moreau::LocalProblem p = factored_problem(3, 20, 2, 40, 3u);
  p.factor = moreau::BodyFactor{};  // W only
  moreau::LocalProblem step = p;
  step.error_scale = p.q.norm();
  for (int member : {2, 4}) {  // Newton's own run, ADMM (auto.hpp's Member order)
    moreau::SolverReport rep[2];
    Eigen::VectorXd r[2], u[2];
    for (int in_step = 0; in_step < 2; ++in_step) {
      auto a = make("auto", {{"tolerance", 1e-6}, {"remember", true}});
      moreau::EntitySet set = state_set(*a);
      set.field("solves").data()[0] = 10;
      for (int k = 0; k < 5; ++k) {
        set.field("member_cost").data()[k] = k == member ? 1e5 : k < 2 ? 1e7 : 0.0;  // `member` first, on a budget it finishes within
        set.field("member_next_try").data()[k] = 1e6;
        set.field("member_try_interval").data()[k] = 4;
      }
      a->load_state(set);
      r[in_step] = Eigen::VectorXd::Zero(p.q.size());  // (no start check that differs between the two)
      rep[in_step] = a->solve(in_step ? step : p, r[in_step], u[in_step]);
      ASSERT_TRUE(rep[in_step].converged) << member << " " << in_step;
    }
    EXPECT_EQ(r[1], r[0]) << member << ": the same iterates";
    ASSERT_EQ(rep[1].iterations, rep[0].iterations) << member;
    const double call = member == 2 ? moreau::WorkCosts::newton_step_call_with_w : moreau::WorkCosts::admm_step_with_w;
    EXPECT_NEAR(rep[1].work - rep[0].work, call * static_cast<double>(rep[1].iterations), 1e-9 * rep[1].work) << member;
  }
}

TEST(AutoMemory, AMemberThatFinishesAStepTheRememberedOneDidNotIsTriedFirstNext) {
  // Newton's own run is remembered far below what this step needs: its slice (thrice its
  // memory) does not finish it, another member does, and that member is tried first at the
  // next solve (before, at its turn, here solve 10⁶: on silo_janssen_2d from step 2609 of
  // `auto`'s run, APGD, remembered at 10× its cost, waited 256 solves while Newton led all
  // 200 steps, and finished every step Newton did not).
  const moreau::LocalProblem p = factored(2, 8, 16, 11u);
  auto state = [](moreau::Solver& s, double newton) {
    moreau::EntitySet set = state_set(s);
    set.field("solves").data()[0] = 10;
    for (int k = 0; k < 5; ++k) {
      set.field("member_cost").data()[k] = k == 0 ? 1e6 : k == 2 ? newton : 0.0;
      set.field("member_next_try").data()[k] = 1e6;
      set.field("member_try_interval").data()[k] = 64;
    }
    s.load_state(set);
  };
  const nlohmann::json params = {{"tolerance", 1e-6}, {"remember", true}};
  auto a = make("auto", params);
  state(*a, 1.0);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(p.q.size()), u;
  ASSERT_TRUE(a->solve(p, r, u).converged);
  moreau::EntitySet after = saved_state(*a);
  const double* next = after.field("member_next_try").data();
  int tried_next = -1;
  for (int k = 0; k < 5; ++k)
    if (next[k] != 1e6) tried_next = k;
  ASSERT_GE(tried_next, 0) << "the winner is tried next";
  EXPECT_NE(tried_next, 2) << "not Newton, which did not finish";
  EXPECT_EQ(next[tried_next], 12.0) << "at the next solve (this one is solve 11)";
  EXPECT_EQ(after.field("member_try_interval").data()[tried_next], 4.0);
  // Newton remembered at what the step needs finishes it within its budget: no try moves.
  auto b = make("auto", params);
  state(*b, 1e5);
  Eigen::VectorXd r2 = Eigen::VectorXd::Zero(p.q.size());
  ASSERT_TRUE(b->solve(p, r2, u).converged);
  moreau::EntitySet after_b = saved_state(*b);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(after_b.field("member_next_try").data()[k], 1e6) << k;
}
