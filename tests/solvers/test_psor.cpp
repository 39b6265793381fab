// `psor` on the shared solver checks (solver_cases.hpp): hand-made problems with known
// answers, redundant contacts, mass ratios, q = 0, μ ≥ 1, non-convergence said honestly,
// warm starts; then the shared FCLib problems.
#include "solver_cases.hpp"

using namespace solver_cases;

TEST(Psor, OpenContactHasNoImpulse) { open_contact("psor"); }
TEST(Psor, StickingAndSlidingIn2D) { stick_and_slide_2d("psor"); }
TEST(Psor, StickingAndSlidingIn3D) { stick_and_slide_3d("psor"); }
TEST(Psor, FrictionlessAndLargeFriction) { frictionless_and_large_friction("psor"); }
TEST(Psor, TwoCoupledContacts) { two_coupled_contacts("psor"); }
TEST(Psor, RedundantContactsStayFiniteAndHonest) { redundant_contacts("psor"); }
TEST(Psor, ZeroQ) { zero_q("psor"); }
TEST(Psor, MassRatio1e4AgreesWithNlgs) { mass_ratio("psor", 1e-8); }
TEST(Psor, RandomProblemsWithLargeFriction) { random_problems("psor", 1e-8, 6, 4, 1.0); }
TEST(Psor, NotConvergedIsReportedAsSuch) { not_converged("psor"); }
TEST(Psor, WarmStartAndEdgeCases) { warm_start("psor"); }

TEST(Psor, SharedFclibProblems) {
  fclib_case("psor", "faf-Capsules-i97-269.hdf5", 1e-8, 100000);
  fclib_case("psor", "faf-Box_Stacks-i0035-31-0.hdf5", 1e-8, 100000);
  fclib_case("psor", "CubeH8.hdf5", 1e-8, 100000);
  // Gauss–Seidel-like: 1e-4 only on the hard ones (1e-8 stalls near 1e-6 / 6e-5).
  fclib_case("psor", "spheres-in-a-box-98-i10000-256-10.hdf5", 1e-4, 100000);
  fclib_case("psor", "fclib-local_problem_test.hdf5", 1e-4, 100000);
}
