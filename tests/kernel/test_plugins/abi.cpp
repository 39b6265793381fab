// A plugin built for another plugin ABI: its manifest is written by hand, as a future
// (or past) SDK would write it.
#include "test_force.hpp"
MOREAU_REGISTER(moreau_test::TestForce, "abi")
namespace {
void register_all(moreau::Registrar& r) {
  for (auto& reg : moreau::detail::local_registrations()) r.add(reg);
}
const moreau_manifest manifest{MOREAU_ABI_VERSION + 98, "9.9.9", MOREAU_BUILD_ID, "moreau_force_abi", &register_all};
const moreau_manifest* get_manifest() { return &manifest; }
}  // namespace
BOOST_DLL_ALIAS(get_manifest, moreau_plugin_manifest)
