#include "test_force.hpp"
MOREAU_REGISTER(moreau_test::TestForce, "dupa")
MOREAU_REGISTER(moreau_test::TestForce, "shared")
MOREAU_PLUGIN_LIBRARY("moreau_force_dupa")
