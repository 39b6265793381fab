#include "test_force.hpp"
MOREAU_REGISTER(moreau_test::TestForce, "good")
MOREAU_PLUGIN_LIBRARY("moreau_force_good")
