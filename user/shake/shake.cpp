// Example steering hook `shake`: imposes a sinusoidal velocity on one component of a
// body (a vibrated box, a shaken floor): x(t) = A sin(2π f t), so v(t) = 2π f A cos(2π f t).
// It writes the State's `imposed_velocity` field, which hooks may change before the
// solve stage. Copy it to steer a run your own way.
//
//   {"type": "shake", "body": "floor", "component": 1, "amplitude": 0.002, "frequency": 30}
#include <cmath>
#include <moreau/error.hpp>
#include <moreau/hook.hpp>
#include <moreau/node_fields.hpp>
#include <numbers>

namespace {

using namespace moreau;

class Shake : public Hook {
 public:
  static Schema schema() {
    Schema s;
    s.string("body", "the shaken body");
    s.integer("component", "velocity component (0 = x)").min(0).max(2).fallback(0);
    s.number("amplitude", "displacement amplitude").units("m").min(0);
    s.number("frequency", "frequency").units("Hz").gt(0);
    return s;
  }
  static constexpr const char* doc = "imposes a sinusoidal velocity on a body component (steering example)";

  Shake(const Params& p, const BuildContext& ctx)
      : body_(ctx.body_index(p.string("body"), p.pointer("body"))),
        component_(static_cast<int>(p.integer("component"))),
        amplitude_(p.number("amplitude")),
        omega_(2 * std::numbers::pi * p.number("frequency")) {
    if (component_ >= ctx.dimension) throw p.error("component", "no such component in " + std::to_string(ctx.dimension) + "D");
  }

  // After begin_step (where the kernel applies the scene's drivers), before the solve.
  std::vector<std::pair<Stage, When>> points() const override { return {{Stage::begin_step, When::after}}; }

  void run(HookContext& ctx) override {
    State& st = ctx.steer();
    const double t_end = static_cast<double>(ctx.step() + 1) * ctx.time_step();  // v⁺ is imposed
    // The body's node (a rigid body has one): its row of the imposed velocity.
    st.node_values(static_cast<std::size_t>(body_), node_fields::imposed_velocity)[component_] =
        amplitude_ * omega_ * std::cos(omega_ * t_end);
  }

 private:
  int body_, component_;
  double amplitude_, omega_;
};

MOREAU_REGISTER(Shake, "shake")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_hook_shake")
