// Claims plugin ABI MOREAU_ABI_VERSION + 1, as a plugin built for a newer moreau would.
#include <moreau/force.hpp>

namespace {
class Nothing : public moreau::Force {
 public:
  static moreau::Schema schema() { return {}; }
  static constexpr const char* doc = "mismatched test plugin";
  Nothing(const moreau::Params&, const moreau::BuildContext&) {}
  void apply(moreau::StepContext&) override {}
};
MOREAU_REGISTER(Nothing, "mismatched")
void register_all(moreau::Registrar& r) {
  for (auto& reg : moreau::detail::local_registrations()) r.add(reg);
}
const moreau_manifest manifest{MOREAU_ABI_VERSION + 1, "99.0.0", MOREAU_BUILD_ID, "moreau_force_mismatched", &register_all};
const moreau_manifest* get_manifest() { return &manifest; }
}  // namespace
BOOST_DLL_ALIAS(get_manifest, moreau_plugin_manifest)
