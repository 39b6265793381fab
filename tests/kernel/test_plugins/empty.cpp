// Valid manifest, registers nothing.
#include <moreau/plugin.hpp>
MOREAU_PLUGIN_LIBRARY("moreau_force_empty")
