// A static object of the library whose constructor throws while the loader runs it.
#include <string>

#include "faulty_force.hpp"
namespace {
struct Table {
  Table() { throw std::runtime_error("static table: cannot read its data"); }
};
const Table table;
}  // namespace
MOREAU_REGISTER(moreau_test::QuietForce, "staticthrow")
MOREAU_PLUGIN_LIBRARY("moreau_force_staticthrow")
