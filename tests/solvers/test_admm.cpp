// `admm` on the shared solver checks (solver_cases.hpp): hand-made problems with known
// answers, redundant contacts, mass ratios, q = 0, μ ≥ 1, non-convergence said honestly,
// warm starts; then the shared FCLib problems.
#include "solver_cases.hpp"

using namespace solver_cases;

TEST(Admm, OpenContactHasNoImpulse) { open_contact("admm"); }
TEST(Admm, StickingAndSlidingIn2D) { stick_and_slide_2d("admm"); }
TEST(Admm, StickingAndSlidingIn3D) { stick_and_slide_3d("admm"); }
TEST(Admm, FrictionlessAndLargeFriction) { frictionless_and_large_friction("admm"); }
TEST(Admm, TwoCoupledContacts) { two_coupled_contacts("admm"); }
TEST(Admm, RedundantContactsStayFiniteAndHonest) { redundant_contacts("admm"); }
TEST(Admm, ZeroQ) { zero_q("admm"); }
TEST(Admm, MassRatio1e4AgreesWithNlgs) { mass_ratio("admm", 1e-10); }
TEST(Admm, RandomProblemsWithLargeFriction) { random_problems("admm", 1e-10, 12, 8, 1.0); }
TEST(Admm, NotConvergedIsReportedAsSuch) { not_converged("admm"); }
TEST(Admm, WarmStartAndEdgeCases) { warm_start("admm"); }

TEST(Admm, SharedFclibProblems) {
  fclib_case("admm", "fclib-local_problem_test.hdf5", 1e-8, 20000);
  fclib_case("admm", "faf-Capsules-i97-269.hdf5", 1e-8, 20000);
  fclib_case("admm", "faf-Box_Stacks-i0035-31-0.hdf5", 1e-8, 20000);
  fclib_case("admm", "CubeH8.hdf5", 1e-8, 20000);
  fclib_case("admm", "spheres-in-a-box-98-i10000-256-10.hdf5", 1e-4, 20000);  // 1e-8 takes ~1e5 iterations
}
