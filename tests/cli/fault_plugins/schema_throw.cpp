// A schema() that throws: it runs in the library's static constructors (MOREAU_REGISTER).
#include "faulty_force.hpp"
namespace {
class SchemaThrow : public moreau_test::QuietForce {
 public:
  using QuietForce::QuietForce;
  static moreau::Schema schema() { throw std::logic_error("schema not written yet"); }
};
}  // namespace
MOREAU_REGISTER(SchemaThrow, "schemathrow")
MOREAU_PLUGIN_LIBRARY("moreau_force_schemathrow")
