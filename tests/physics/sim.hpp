#pragma once
// A minimal stepper for validation tests: the rigid model, the theta integrator and
// constant forces, created through their registrations and driven stage by stage as
// the scheduler does (external_forces, free_velocity, update_dofs, end_step).
#include <cmath>
#include <memory>
#include <moreau/force.hpp>
#include <moreau/integrator.hpp>
#include <moreau/modelization.hpp>
#include <moreau/rigid_fields.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "kernel/scene/validate.hpp"

namespace moreau_test {

template <class T>
std::unique_ptr<T> create(const std::string& name, const nlohmann::json& params, const moreau::BuildContext& ctx) {
  for (auto& r : moreau::detail::local_registrations())
    if (r.kind == T::kind && r.name == name) {
      auto obj = r.factory(moreau::Params(params, "/test"), ctx);
      return std::unique_ptr<T>(dynamic_cast<T*>(obj.release()));
    }
  throw std::logic_error("no plugin " + name + " linked into the test");
}

class Sim {
 public:
  Sim(int dim, double h, double theta, std::vector<double> gravity) : state(dim), ctx{state} {
    ctx.h = h;
    ctx.theta = theta;
    ctx.gravity = std::move(gravity);
    build.dimension = dim;
    build.time_step = h;
    build.body_index = [this](const std::string& n, const std::string& ptr) {
      const int i = state.find_body(n);
      if (i < 0) throw moreau::InputError(ptr, "no body " + n);
      return i;
    };
    model = create<moreau::Modelization>("rigid", nlohmann::json::object(), build);
    integrator = create<moreau::Integrator>("theta", nlohmann::json::object(), build);
    state.add_model({"rigid", model->node_set(), "", model->node_dofs(dim)});
    // Every field but those of contacts and imposed velocities (declare_field adds them).
    for (const auto& f : model->fields(dim))
      if (f.components(dim) > 0 && (f.needed == moreau::Needed::always || f.needed == moreau::Needed::forces))
        state.declare(f);
  }

  /// Declares one more field of the rigid table (e.g. imposed_velocity).
  moreau::Field& declare_field(const char* name) {
    for (const auto& f : model->fields(state.dimension()))
      if (f.name == name) return state.declare(f);
    throw std::logic_error(std::string("no rigid field ") + name);
  }
  moreau::Field& field(const char* name) { return state.field(moreau::rigid::nodes, name); }
  const moreau::Field& field(const char* name) const { return state.field(moreau::rigid::nodes, name); }

  /// Adds a body from its scene JSON (validated against the rigid body schema).
  std::size_t add_body(const std::string& name, const nlohmann::json& body) {
    std::vector<moreau::InputError> errors;
    moreau::kernel::Validation v{state.dimension(), errors};
    nlohmann::json checked = moreau::kernel::validate_object(body, model->body_schema(state.dimension()), "/bodies/0", v);
    if (!errors.empty()) throw errors.front();
    const std::size_t b = state.add_bodies({moreau::BodyLayout{name, 0, 1, 0}});
    model->init_body(state, b, moreau::Params(checked, "/bodies/0"), std::nullopt, nullptr);
    return b;
  }

  void add_force(const nlohmann::json& params) {
    forces.push_back(create<moreau::Force>("constant", params, build));
    ctx.external_forces = true;
  }

  void prepare() { integrator->prepare(state, *model); }

  void step() {
    ctx.time = static_cast<double>(ctx.step) * ctx.h;
    if (ctx.external_forces) {
      for (const char* f : {moreau::rigid::force, moreau::rigid::torque}) {
        auto& fld = field(f);
        std::fill(fld.data(), fld.data() + fld.rows() * fld.components(), 0.0);
      }
      for (auto& f : forces) f->apply(ctx);
    }
    integrator->free_velocity(ctx);
    integrator->update_dofs(ctx);
    state.swap_depths();
    ++ctx.step;
  }
  void run(long steps) {
    for (long i = 0; i < steps; ++i) step();
  }
  double time() const { return static_cast<double>(ctx.step) * ctx.h; }
  /// Current (end of last step) value of a field component.
  double at(const char* field, std::size_t body, int k) const {
    return state.field(moreau::rigid::nodes, field).row(body, moreau::Depth::begin)[k];
  }

  moreau::State state;
  moreau::StepContext ctx;
  moreau::BuildContext build;
  std::unique_ptr<moreau::Modelization> model;
  std::unique_ptr<moreau::Integrator> integrator;
  std::vector<std::unique_ptr<moreau::Force>> forces;
};

/// Convergence order from errors at h and h/2.
inline double order(double e_h, double e_half) { return std::log2(e_h / e_half); }

}  // namespace moreau_test
