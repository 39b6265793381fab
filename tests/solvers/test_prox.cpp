// `prox` (proximal point around NLGS or Newton) on the shared solver checks
// (solver_cases.hpp) and the shared FCLib problems, including the two that Gauss–Seidel
// alone does not bring to 1e-8.
#include "solver_cases.hpp"

using namespace solver_cases;

class Prox : public ::testing::TestWithParam<std::string> {
 protected:
  std::string spec() const { return "prox:inner=" + GetParam(); }
};

TEST_P(Prox, OpenContactHasNoImpulse) { open_contact(spec()); }
TEST_P(Prox, StickingAndSlidingIn2D) { stick_and_slide_2d(spec()); }
TEST_P(Prox, StickingAndSlidingIn3D) { stick_and_slide_3d(spec()); }
TEST_P(Prox, FrictionlessAndLargeFriction) { frictionless_and_large_friction(spec()); }
TEST_P(Prox, TwoCoupledContacts) { two_coupled_contacts(spec()); }
TEST_P(Prox, RedundantContactsStayFiniteAndHonest) { redundant_contacts(spec()); }
TEST_P(Prox, ZeroQ) { zero_q(spec()); }
TEST_P(Prox, MassRatio1e4AgreesWithNlgs) { mass_ratio(spec(), 1e-8); }
TEST_P(Prox, RandomProblemsWithLargeFriction) { random_problems(spec(), 1e-8, 6, 4, 1.0); }
TEST_P(Prox, NotConvergedIsReportedAsSuch) { not_converged(spec()); }
TEST_P(Prox, WarmStartAndEdgeCases) { warm_start(spec()); }
TEST_P(Prox, SharedFclibProblems) {
  fclib_case(spec(), "faf-Capsules-i97-269.hdf5", 1e-8, 100000);
  fclib_case(spec(), "faf-Box_Stacks-i0035-31-0.hdf5", 1e-8, 100000);
  fclib_case(spec(), "CubeH8.hdf5", 1e-8, 100000);
  // Around Newton, the two problems Gauss–Seidel alone stalls on reach 1e-8; around NLGS
  // the regularisation speeds the sweeps up but they still stall near 1e-5 there.
  const double hard = GetParam() == "newton" ? 1e-8 : 1e-4;
  fclib_case(spec(), "fclib-local_problem_test.hdf5", hard, 100000);
  fclib_case(spec(), "spheres-in-a-box-98-i10000-256-10.hdf5", hard, GetParam() == "newton" ? 100000 : 5000);
}

INSTANTIATE_TEST_SUITE_P(Inner, Prox, ::testing::Values("nlgs", "newton"));
