// Example hook `stop_when`: ends the run (cleanly, with its last frame written) when a
// condition holds. Copy this file to start your own stopping rule.
//
//   {"type": "stop_when", "quantity": "kinetic_energy", "below": 1e-6, "after": 0.5}
//   {"type": "stop_when", "quantity": "position", "body": "ball", "component": 1, "below": 0.0}
#include <cmath>
#include <cstdio>
#include <moreau/hook.hpp>
#include <moreau/rigid_energy.hpp>

namespace {

using namespace moreau;

class StopWhen : public Hook {
 public:
  static Schema schema() {
    Schema s;
    s.string("quantity", "what is tested").one_of({"kinetic_energy", "position", "velocity"});
    s.string("body", "the body (for position and velocity)").optional();
    s.integer("component", "component of the vector (0 = x)").min(0).max(2).fallback(0);
    s.number("below", "stop when the quantity is below this value").optional();
    s.number("above", "stop when the quantity is above this value").optional();
    s.number("after", "test only from this time on").units("s").min(0).fallback(0.0);
    return s;
  }
  static constexpr const char* doc = "stops the run when a quantity crosses a threshold";

  StopWhen(const Params& p, const BuildContext& ctx)
      : quantity_(p.string("quantity")), component_(static_cast<int>(p.integer("component"))), after_(p.number("after")) {
    if (p.has("below") == p.has("above")) throw p.error("", "give exactly one of \"below\" and \"above\"");
    below_ = p.has("below");
    threshold_ = below_ ? p.number("below") : p.number("above");
    if (quantity_ != "kinetic_energy") {
      if (!p.has("body")) throw p.error("body", "\"" + quantity_ + "\" needs a \"body\"");
      body_ = ctx.body_index(p.string("body"), p.pointer("body"));
      if (component_ >= ctx.dimension) throw p.error("component", "a " + std::to_string(ctx.dimension) + "D vector has no component " + std::to_string(component_));
    }
  }

  std::vector<std::pair<Stage, When>> points() const override { return {{Stage::end_step, When::after}}; }

  void run(HookContext& ctx) override {
    const double t = static_cast<double>(ctx.step() + 1) * ctx.time_step();
    if (t < after_) return;
    const double value = measure(ctx);
    if (below_ ? value < threshold_ : value > threshold_) {
      char msg[200];
      std::snprintf(msg, sizeof msg, "stop_when: %s = %.6g %s %.6g at t = %.6g s", describe().c_str(), value,
                    below_ ? "<" : ">", threshold_, t);
      ctx.request_stop(msg);
    }
  }

 private:
  double measure(const HookContext& ctx) const {
    if (quantity_ == "kinetic_energy") return user::energies(ctx.state(), ctx.gravity()).kinetic();
    return ctx.state().node_values(static_cast<std::size_t>(body_), quantity_ == "position" ? rigid::position : rigid::velocity,
                                   Depth::begin)[component_];
  }
  std::string describe() const {
    if (quantity_ == "kinetic_energy") return "kinetic energy";
    return quantity_ + "[" + std::to_string(component_) + "] of body " + std::to_string(body_);
  }

  std::string quantity_;
  int component_;
  double after_;
  bool below_ = true;
  double threshold_ = 0;
  int body_ = -1;
};

MOREAU_REGISTER(StopWhen, "stop_when")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_hook_stop_when")
