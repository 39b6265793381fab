// A constructor that throws something that is not an exception class at all.
#include "faulty_force.hpp"
namespace {
class CtorThrow42 : public moreau_test::QuietForce {
 public:
  CtorThrow42(const moreau::Params& p, const moreau::BuildContext& c) : QuietForce(p, c) { throw 42; }
};
}  // namespace
MOREAU_REGISTER(CtorThrow42, "ctorthrow42")
MOREAU_PLUGIN_LIBRARY("moreau_force_ctorthrow42")
