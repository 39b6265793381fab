// `spring`: a linear spring pulling a body's centre toward a fixed anchor,
// F = −k (x − anchor). An example of a third-party external-force plugin.
#include <moreau/force.hpp>
#include <moreau/rigid_fields.hpp>

namespace {

class Spring : public moreau::Force {
 public:
  static moreau::Schema schema() {
    moreau::Schema s;
    s.string("body", "the body pulled");
    s.vector("anchor", "where the spring is attached", moreau::length::dimension).units("m");
    s.number("stiffness", "spring constant k").units("N/m").gt(0);
    return s;
  }
  static constexpr const char* doc = "linear spring from a body to a fixed anchor (SDK example)";

  Spring(const moreau::Params& p, const moreau::BuildContext& ctx)
      : body_(ctx.body_index(p.string("body"), p.pointer("body"))), anchor_(p.vector("anchor")), k_(p.number("stiffness")) {}

  // The force is evaluated on the ⁻ state (explicit in the spring, as the θ-scheme's
  // external forces are given at the start of the step).
  void apply(moreau::StepContext& ctx) override {
    // The body's node (rigid: its one row in rigid.nodes), whatever other bodies there are.
    const auto x = ctx.state.node_values(body_, moreau::rigid::position, moreau::Depth::begin);
    auto f = ctx.state.node_values(body_, moreau::rigid::force);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] += -k_ * (x[i] - anchor_[i]);
  }

 private:
  std::size_t body_;
  std::vector<double> anchor_;
  double k_;
};

MOREAU_REGISTER(Spring, "spring")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_force_spring")
