// File name says force "misnamed", but it registers force "other".
#include "test_force.hpp"
MOREAU_REGISTER(moreau_test::TestForce, "other")
MOREAU_PLUGIN_LIBRARY("moreau_force_misnamed")
