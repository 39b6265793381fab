#pragma once
// A minimal force plugin for the loader tests: adds a constant force to body 0.
#include <moreau/force.hpp>

namespace moreau_test {

class TestForce : public moreau::Force {
 public:
  static moreau::Schema schema() {
    moreau::Schema s;
    s.number("magnitude", "force on body 0").units("N").fallback(1.0);
    return s;
  }
  static constexpr const char* doc = "test force";
  TestForce(const moreau::Params& p, const moreau::BuildContext&) : magnitude_(p.has("magnitude") ? p.number("magnitude") : 1.0) {}
  void apply(moreau::StepContext& ctx) override { ctx.state.node_values(0, "force")[0] += magnitude_; }

 private:
  double magnitude_;
};

}  // namespace moreau_test
