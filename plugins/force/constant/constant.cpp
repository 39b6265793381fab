// `constant`: a constant force and torque (world frame) on one body, for the whole run.
#include <moreau/force.hpp>
#include <moreau/rigid_fields.hpp>

namespace {

using namespace moreau;

class Constant : public Force {
 public:
  static Schema schema() {
    Schema s;
    s.string("body", "name of the body");
    s.vector("force", "force, world frame", length::dimension).units("N").optional();
    s.vector("torque", "torque about the centre of mass, world frame", length::rotation).units("N m").optional();
    return s;
  }
  static constexpr const char* doc = "constant force and torque on a body";

  Constant(const Params& p, const BuildContext& ctx)
      : body_(ctx.body_index(p.string("body"), p.pointer("body"))),
        force_(p.has("force") ? p.vector("force") : std::vector<double>(ctx.dimension, 0.0)),
        torque_(p.has("torque") ? p.vector("torque") : std::vector<double>(ctx.dimension == 2 ? 1 : 3, 0.0)) {
    if (!p.has("force") && !p.has("torque")) throw p.error("", "give a \"force\", a \"torque\", or both");
  }

  void apply(StepContext& c) override {
    auto f = c.state.field(rigid::force).row(body_);
    for (std::size_t k = 0; k < f.size(); ++k) f[k] += force_[k];
    auto t = c.state.field(rigid::torque).row(body_);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] += torque_[k];
  }

 private:
  int body_;
  std::vector<double> force_, torque_;
};

MOREAU_REGISTER(Constant, "constant")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_force_constant")
