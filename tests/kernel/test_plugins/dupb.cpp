#include "test_force.hpp"
MOREAU_REGISTER(moreau_test::TestForce, "dupb")
MOREAU_REGISTER(moreau_test::TestForce, "shared")
MOREAU_PLUGIN_LIBRARY("moreau_force_dupb")
