// A plugin built with another compiler / standard library: same ABI number, other build id.
#include "test_force.hpp"
MOREAU_REGISTER(moreau_test::TestForce, "buildid")
namespace {
void register_all(moreau::Registrar& r) {
  for (auto& reg : moreau::detail::local_registrations()) r.add(reg);
}
const moreau_manifest manifest{MOREAU_ABI_VERSION, MOREAU_SDK_VERSION, "othercc-1/otherlib", "moreau_force_buildid", &register_all};
const moreau_manifest* get_manifest() { return &manifest; }
}  // namespace
BOOST_DLL_ALIAS(get_manifest, moreau_plugin_manifest)
