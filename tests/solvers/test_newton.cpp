// `newton` on the shared solver checks (solver_cases.hpp): hand-made problems with known
// answers, redundant contacts, mass ratios, q = 0, μ ≥ 1, non-convergence said honestly,
// warm starts; then the shared FCLib problems.
#include "solver_cases.hpp"

using namespace solver_cases;

TEST(Newton, OpenContactHasNoImpulse) { open_contact("newton"); }
TEST(Newton, StickingAndSlidingIn2D) { stick_and_slide_2d("newton"); }
TEST(Newton, StickingAndSlidingIn3D) { stick_and_slide_3d("newton"); }
TEST(Newton, FrictionlessAndLargeFriction) { frictionless_and_large_friction("newton"); }
TEST(Newton, TwoCoupledContacts) { two_coupled_contacts("newton"); }
TEST(Newton, RedundantContactsStayFiniteAndHonest) { redundant_contacts("newton"); }
TEST(Newton, ZeroQ) { zero_q("newton"); }
TEST(Newton, MassRatio1e4AgreesWithNlgs) { mass_ratio("newton", 1e-10); }
TEST(Newton, RandomProblemsWithLargeFriction) { random_problems("newton", 1e-10, 12, 8, 1.0); }
TEST(Newton, NotConvergedIsReportedAsSuch) { not_converged("newton"); }
TEST(Newton, WarmStartAndEdgeCases) { warm_start("newton"); }

TEST(Newton, SharedFclibProblems) {
  for (const char* f : {"fclib-local_problem_test.hdf5", "faf-Capsules-i97-269.hdf5", "faf-Box_Stacks-i0035-31-0.hdf5",
                        "spheres-in-a-box-98-i10000-256-10.hdf5", "CubeH8.hdf5"})
    fclib_case("newton", f, 1e-8, 200);
}
