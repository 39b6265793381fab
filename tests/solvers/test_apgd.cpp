// `apgd` on the shared solver checks (solver_cases.hpp): hand-made problems with known
// answers, redundant contacts, mass ratios, q = 0, μ ≥ 1, non-convergence said honestly,
// warm starts; then the shared FCLib problems.
#include "solver_cases.hpp"

using namespace solver_cases;

TEST(Apgd, OpenContactHasNoImpulse) { open_contact("apgd"); }
TEST(Apgd, StickingAndSlidingIn2D) { stick_and_slide_2d("apgd"); }
TEST(Apgd, StickingAndSlidingIn3D) { stick_and_slide_3d("apgd"); }
TEST(Apgd, FrictionlessAndLargeFriction) { frictionless_and_large_friction("apgd"); }
TEST(Apgd, TwoCoupledContacts) { two_coupled_contacts("apgd"); }
TEST(Apgd, RedundantContactsStayFiniteAndHonest) { redundant_contacts("apgd"); }
TEST(Apgd, ZeroQ) { zero_q("apgd"); }
TEST(Apgd, MassRatio1e4AgreesWithNlgs) { mass_ratio("apgd", 1e-8); }
TEST(Apgd, RandomProblemsWithLargeFriction) { random_problems("apgd", 1e-8, 6, 4, 1.0); }
TEST(Apgd, NotConvergedIsReportedAsSuch) { not_converged("apgd"); }
TEST(Apgd, WarmStartAndEdgeCases) { warm_start("apgd"); }

TEST(Apgd, SharedFclibProblems) {
  for (const char* f : {"fclib-local_problem_test.hdf5", "faf-Capsules-i97-269.hdf5", "faf-Box_Stacks-i0035-31-0.hdf5",
                        "spheres-in-a-box-98-i10000-256-10.hdf5", "CubeH8.hdf5"})
    fclib_case("apgd", f, 1e-8, 100000);
}
