// Calls a function nothing defines: with lazy binding it loads and dies at the first call
// (exit 127 from the loader); with immediate binding it is refused at load.
#include "faulty_force.hpp"
extern "C" void moreau_test_function_nobody_defines();
namespace {
class Unresolved : public moreau_test::QuietForce {
 public:
  using QuietForce::QuietForce;
  void apply(moreau::StepContext&) override { moreau_test_function_nobody_defines(); }
};
}  // namespace
MOREAU_REGISTER(Unresolved, "unresolved")
MOREAU_PLUGIN_LIBRARY("moreau_force_unresolved")
