#pragma once
// Force plugins that fail in the ways plugins written by users do (tests/cli/test_plugin_faults.cpp).
#include <moreau/force.hpp>
#include <stdexcept>

namespace moreau_test {

/// Does nothing; the faulty variants below fail before or while they are made.
class QuietForce : public moreau::Force {
 public:
  static moreau::Schema schema() { return {}; }
  static constexpr const char* doc = "test force that does nothing";
  QuietForce(const moreau::Params&, const moreau::BuildContext&) {}
  void apply(moreau::StepContext&) override {}
};

}  // namespace moreau_test
