// Bad rigid-body input: clear errors at the body's JSON pointer.
#include <gtest/gtest.h>

#include "sim.hpp"

using namespace moreau_test;

namespace {
std::string error_of(int dim, const nlohmann::json& body) {
  Sim s(dim, 0.01, 0.5, std::vector<double>(dim, 0.0));
  try {
    s.add_body("b", body);
  } catch (const moreau::InputError& e) {
    return e.describe();
  }
  return "(no error)";
}
}  // namespace

TEST(RigidInput, MissingMass) {
  EXPECT_EQ(error_of(2, {{"position", {0, 0}}}),
            "at /bodies/0: a body that is not fixed needs a mass: give \"mass\" and \"inertia\", or contactors and a "
            "\"material\" with a density");
}

TEST(RigidInput, NonPositiveMass) {
  EXPECT_EQ(error_of(2, {{"position", {0, 0}}, {"mass", -1}, {"inertia", 1}}),
            "at /bodies/0/mass: value -1 out of range: expected > 0");
}

TEST(RigidInput, MassWithoutInertia) {
  EXPECT_EQ(error_of(3, {{"position", {0, 0, 0}}, {"mass", 1}}),
            "at /bodies/0: a body with an explicit mass and no contactors needs \"inertia\"");
}

TEST(RigidInput, BadQuaternion) {
  EXPECT_EQ(error_of(3, {{"position", {0, 0, 0}}, {"mass", 1}, {"inertia", {1, 1, 1}}, {"orientation", {1, 1, 0, 0}}}),
            "at /bodies/0/orientation: expected a unit quaternion [w, x, y, z], its norm is 1.414214");
}

TEST(RigidInput, InertiaShapeAndDefiniteness) {
  EXPECT_EQ(error_of(3, {{"position", {0, 0, 0}}, {"mass", 1}, {"inertia", {1, 1}}}),
            "at /bodies/0/inertia: expected 3 principal moments or 6 components (xx yy zz xy xz yz), got 2 numbers");
  EXPECT_EQ(error_of(3, {{"position", {0, 0, 0}}, {"mass", 1}, {"inertia", {1, 1, 1, 2, 0, 0}}}),
            "at /bodies/0/inertia: the inertia tensor must be positive definite");
}
