// `constant`: a force and torque (world frame) on one body, for the whole run, constant or
// growing at a constant rate (F(t) = force + rate t: a load ramp, as in a pull test). The
// body is addressed by name; its data is its node's row in its modelization's node set
// (State::node_values), so it works whatever other modelizations share the scene. With
// `nodes` (a node group of a mesh, State::node_group) the force acts on each node of the
// group: nodal forces on deformable bodies.
#include <moreau/force.hpp>
#include <moreau/node_fields.hpp>
#include <moreau/rigid_fields.hpp>

namespace {

using namespace moreau;

class Constant : public Force {
 public:
  static Schema schema() {
    Schema s;
    s.string("body", "name of the body");
    s.string("nodes", "a node group of the body (meshes): the force acts on each of its nodes").optional();
    s.vector("force", "force, world frame", length::dimension).units("N").optional();
    s.vector("torque", "torque about the centre of mass, world frame", length::rotation).units("N m").optional();
    s.vector("rate", "growth of the force per second: F(t) = force + rate t", length::dimension).units("N/s").optional();
    return s;
  }
  static constexpr const char* doc = "constant force and torque on a body (or a force growing at a constant rate), or a force on each node of a node group";

  Constant(const Params& p, const BuildContext& ctx)
      : body_(static_cast<std::size_t>(ctx.body_index(p.string("body"), p.pointer("body")))),
        force_(p.has("force") ? p.vector("force") : std::vector<double>(ctx.dimension, 0.0)),
        torque_(p.has("torque") ? p.vector("torque") : std::vector<double>(ctx.dimension == 2 ? 1 : 3, 0.0)),
        rate_(p.has("rate") ? p.vector("rate") : std::vector<double>(ctx.dimension, 0.0)) {
    if (!p.has("force") && !p.has("torque") && !p.has("rate"))
      throw p.error("", "give a \"force\", a \"torque\", a \"rate\", or several");
    if (p.has("nodes")) {
      // Nodal forces on a node group: nodes that take forces but do not turn.
      if (p.has("torque")) throw p.error("torque", "a force on \"nodes\" acts on each node of the group: nodes take no torque");
      if (ctx.state) {
        const auto b = static_cast<std::size_t>(body_);
        rows_ = ctx.state->node_group(b, p.string("nodes"), p.pointer("nodes"));
        if (!ctx.state->has_node_field(b, node_fields::force))
          throw p.error("body", "body \"" + p.string("body") + "\" is a \"" + ctx.state->model_of(b).name +
                                    "\" body, whose nodes take no forces");
        nodes_ = ctx.state->model_of(b).nodes;
      }
      return;
    }
    // A force on the body's one node: bodies of a modelization with loads on one node (rigid).
    if (ctx.state) {
      const auto b = static_cast<std::size_t>(body_);
      const ModelInfo& m = ctx.state->model_of(b);
      if (ctx.state->body(b).nodes != 1 || !ctx.state->has_node_field(b, rigid::force) ||
          (p.has("torque") && !ctx.state->has_node_field(b, rigid::torque)))
        throw p.error("body", "a constant force acts on a body of one node with forces and torques (rigid): \"" +
                                  p.string("body") + "\" is a \"" + m.name + "\" body");
    }
  }

  void apply(StepContext& c) override {
    // The force of the step at t⁻ + θh: the θ-scheme's (1−θ)F⁻ + θF⁺ for a linear ramp.
    const double time = c.time + c.theta * c.h;
    if (!nodes_.empty()) {
      Field& field = c.state.field(nodes_, node_fields::force);
      for (const std::size_t r : rows_) {
        auto f = field.row(r);
        for (std::size_t k = 0; k < f.size(); ++k) f[k] += force_[k] + rate_[k] * time;
      }
      return;
    }
    auto f = c.state.node_values(body_, rigid::force);
    for (std::size_t k = 0; k < f.size(); ++k) f[k] += force_[k] + rate_[k] * time;
    if (!c.state.has_node_field(body_, rigid::torque)) return;
    auto t = c.state.node_values(body_, rigid::torque);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] += torque_[k];
  }

 private:
  std::size_t body_;
  std::vector<double> force_, torque_, rate_;
  std::string nodes_;              ///< with `nodes`: the node set, and the group's rows in it
  std::vector<std::size_t> rows_;
};

MOREAU_REGISTER(Constant, "constant")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_force_constant")
