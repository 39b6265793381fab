// A constructor that throws a std::exception (not a moreau error).
#include "faulty_force.hpp"
namespace {
class CtorThrow : public moreau_test::QuietForce {
 public:
  using QuietForce::QuietForce;
  CtorThrow(const moreau::Params& p, const moreau::BuildContext& c) : QuietForce(p, c) {
    throw std::runtime_error("cannot start: the frobnicator is missing");
  }
};
}  // namespace
MOREAU_REGISTER(CtorThrow, "ctorthrow")
MOREAU_PLUGIN_LIBRARY("moreau_force_ctorthrow")
