// A hook that (wrongly) tries to change the state after the solve stage.
#include <moreau/hook.hpp>

namespace {
class SteerLate : public moreau::Hook {
 public:
  static moreau::Schema schema() { return {}; }
  static constexpr const char* doc = "test: steers after solve";
  SteerLate(const moreau::Params&, const moreau::BuildContext&) {}
  std::vector<std::pair<moreau::Stage, moreau::When>> points() const override {
    return {{moreau::Stage::update_dofs, moreau::When::before}};
  }
  void run(moreau::HookContext& ctx) override { ctx.steer(); }
};
MOREAU_REGISTER(SteerLate, "steer_late")
}  // namespace
MOREAU_PLUGIN_LIBRARY("moreau_hook_steer_late")
