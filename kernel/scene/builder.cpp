#include "builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>
#include <moreau/contact_fields.hpp>
#include <moreau/node_fields.hpp>
#include <optional>
#include <map>
#include <set>
#include <sstream>

#include "../analysis/analysis_build.hpp"
#include "../contact/placement.hpp"
#include "../plugin/boundary.hpp"
#include "../run/console.hpp"
#include "../text/did_you_mean.hpp"
#include "display_build.hpp"
#include "generate.hpp"
#include "json_file.hpp"
#include "scene_schema.hpp"
#include "validate.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace moreau::kernel {

namespace {

/// A plugin named in the scene, with its validated parameters.
struct PluginUse {
  std::string name;
  Params params;
  std::string pointer;
  bool valid = false;  ///< its parameters passed validation (else only its errors count)
};

/// A validated contactor's group; nullopt when the contactor has errors of its own (its
/// `group` may then be any JSON value: it was reported, and must not be used).
std::optional<std::string> group_of(const PluginUse& c) {
  if (!c.valid || !c.params.has("group") || !c.params.json().at("group").is_string()) return std::nullopt;
  return c.params.string("group");
}

class SceneChecker {
 public:
  SceneChecker(const JsonFile& file, std::string shadow_solvers = {}) : file_(file), shadow_text_(std::move(shadow_solvers)) {}

  /// Everything validated (or InputErrors thrown). Leaves the registry loaded.
  void check() {
    const json& root = file_.value;
    if (!root.is_object()) fail_now("", "expected a JSON object at the top of the scene");
    // The dimension decides vector lengths everywhere: check it first.
    if (!root.contains("dimension") || !root["dimension"].is_number_integer() ||
        (root["dimension"] != 2 && root["dimension"] != 3))
      fail_now("/dimension", "missing or invalid \"dimension\": expected 2 or 3");
    dim_ = root["dimension"].get<int>();
    Validation v{dim_, errors_};
    top_ = validate_object(root, scene_schema::top(), "", v);
    time_ = validate_object(top_.value("time", json::object()), scene_schema::time(), "/time", v);
    output_ = validate_object(top_.value("output", json::object()), scene_schema::output(), "/output", v);
    detection_ = validate_object(top_.value("detection", json::object()), scene_schema::detection(), "/detection", v,
                                 scene_schema::detection_plugin_keys());
    if (output_.contains("file") && output_["file"].is_string() && output_["file"].get<std::string>().empty())
      errors_.emplace_back("/output/file", "expected a file name, got an empty string");

    std::vector<std::string> scene_paths;
    if (top_.contains("plugin_paths") && top_["plugin_paths"].is_array())
      for (std::size_t i = 0; i < top_["plugin_paths"].size(); ++i) {
        const auto& p = top_["plugin_paths"][i];
        const std::string ptr = "/plugin_paths/" + std::to_string(i);
        if (!p.is_string()) {
          errors_.emplace_back(ptr, "expected a folder path (string)");
          continue;
        }
        scene_paths.push_back(p.get<std::string>());
        // Relative to the scene's folder, as the registry resolves it.
        std::error_code ec;
        const fs::path folder = fs::path(scene_paths.back()).is_absolute()
                                    ? fs::path(scene_paths.back())
                                    : fs::absolute(fs::path(file_.path)).parent_path() / scene_paths.back();
        if (!fs::is_directory(folder, ec))
          errors_.emplace_back(ptr, "no folder " + folder.string() + " (relative paths start at the scene's folder)");
      }
    const fs::path scene_dir = fs::absolute(fs::path(file_.path)).parent_path();
    registry_ = std::make_unique<Registry>(Registry::standard_paths(scene_paths, scene_dir));

    check_materials();
    check_bodies();
    check_models();
    check_drivers();
    check_interactions();
    check_plugin_list(Kind::force, "forces", forces_);
    check_plugin_list(Kind::hook, "hooks", hooks_);
    check_analyses();
    if (!top_["solver"].empty() || has_interactions()) {
      solver_ = plugin_use(Kind::solver, top_["solver"], "/solver", "auto", {"on_failure"});
      const json& sv = top_["solver"];
      if (sv.is_object() && sv.contains("on_failure")) {
        const json& f = sv["on_failure"];
        if (!f.is_string() || (f != "warn" && f != "stop"))
          errors_.emplace_back("/solver/on_failure", "expected \"warn\" or \"stop\"" +
                                                         (f.is_string() ? did_you_mean(f.get<std::string>(), {"warn", "stop"}) : ""));
        else stop_on_failure_ = f == "stop";
      }
    }
    if (!shadow_text_.empty()) check_shadows();
    if (has_interactions() || detection_.contains("broadphase"))
      broadphase_ = plugin_use(Kind::broadphase, detection_.value("broadphase", json("grid")), "/detection/broadphase", "grid");
    if (has_interactions()) check_detectors();
    check_export();

    if (!errors_.empty()) throw_all();
    warn_groups_that_never_collide();
    warn_restitution_with_friction();
  }

  std::unique_ptr<World> build(const std::string& output_path) {
    auto w = std::make_unique<World>(dim_);
    w->scene_file = file_.path;
    w->scene_text = file_.text;
    w->scene = top_;
    w->dimension = dim_;
    w->h = time_["step"].get<double>();
    w->theta = time_["theta"].get<double>();
    w->total_steps = std::llround(time_["duration"].get<double>() / w->h);
    w->gravity = top_["gravity"].is_null() ? std::vector<double>(dim_, 0.0) : top_["gravity"].get<std::vector<double>>();
    w->output.file = output_["file"].get<std::string>();
    w->output.every = output_["every"].get<long>();
    w->output.shapes = output_["display"] == "shapes";

    BuildContext ctx;
    ctx.dimension = dim_;
    ctx.time_step = w->h;
    ctx.theta = w->theta;
    ctx.scene_file = file_.path;
    ctx.scene_dir = fs::absolute(fs::path(file_.path)).parent_path().string();
    ctx.output_dir = fs::absolute(fs::path(output_path.empty() ? w->output.file : output_path)).parent_path().string();
    std::vector<std::string> names;
    for (const auto& b : bodies_) names.push_back(b.name);
    ctx.body_index = [names](const std::string& name, const std::string& pointer) {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
      throw InputError(pointer, "no body named \"" + name + "\"" + did_you_mean(name, names));
    };

    try {
      w->registry = std::move(registry_);
      Registry& reg = *w->registry;
      // The modelizations, in the order bodies first name them; each declares its sets and
      // the fields of its table this scene needs (DESIGN §5: nothing allocated it does not use).
      const bool with_contacts = !interactions_.empty(), with_forces = !forces_.empty(),
                 with_imposed = !drivers_.empty() || !hooks_.empty();
      auto needed = [&](Needed n) {
        return n == Needed::always || (n == Needed::contacts && with_contacts) || (n == Needed::forces && with_forces) ||
               (n == Needed::imposed && with_imposed);
      };
      std::map<std::string, int> model_index;
      std::vector<BodyLayout> layouts;
      for (const auto& b : bodies_) {
        const std::string& name = b.model.name;
        if (!model_index.count(name)) {
          const ModelUse& use = model_uses_.at(name);
          Model m;
          m.name = name;
          m.modelization = reg.create<Modelization>(name, use.params, ctx, use.pointer);
          const int index = w->state.add_model(ModelInfo{name, m.modelization->node_set(), m.modelization->element_set(),
                                                         m.modelization->node_dofs(dim_)});
          for (const auto& f : m.modelization->fields(dim_))
            if (f.components(dim_) > 0 && needed(f.needed)) w->state.declare(f);
          model_index[name] = index;
          w->models.push_back(std::move(m));
        }
        const BodySize size = w->models[model_index[name]].modelization->body_size(b.model.params, dim_);
        layouts.push_back(BodyLayout{b.name, model_index[name], size.nodes, size.elements});
      }
      if (with_contacts)
        for (const auto& f : contact_fields::table()) w->state.declare(f);
      w->state.add_bodies(layouts);
      std::vector<Contactor> contactors;
      std::map<std::string, int> group_index;
      for (const auto& in : interactions_)
        for (const auto& g : {in.a, in.b}) group_index.emplace(g, static_cast<int>(group_index.size()));
      const Schema contactor_keys = scene_schema::contactor_kernel_keys(dim_);  // the kernel's, not the shape's
      std::vector<const Shape*> display_shapes;  // every contactor's, for the viewer's meshes
      std::vector<Owned<Shape>> undetected;      // shapes no detector keeps, alive until then
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const auto& b = bodies_[i];
        const Params* material = b.material.empty() ? nullptr : &materials_.at(b.material);
        // Shapes: one object per contactor, at its placement; their mass properties add up
        // (a cluster: parallel-axis theorem in add()). A contactor on a `boundary` is
        // repeated over a group the modelization records in init_body: it is made after.
        std::optional<MassProperties> mass;
        const BodyRows rows = w->state.body(i);
        std::vector<Owned<Shape>> on_node(b.contactors.size());
        for (std::size_t c = 0; c < b.contactors.size(); ++c) {
          const auto& ct = b.contactors[c];
          if (ct.params.has("boundary")) continue;
          const long node = ct.params.has("node") ? ct.params.integer("node") : 0;
          if (static_cast<std::size_t>(node) >= rows.nodes)
            throw InputError(ct.pointer + "/node", "body \"" + b.name + "\" has " + std::to_string(rows.nodes) +
                                                       " node" + (rows.nodes == 1 ? "" : "s") + ": expected a node below " +
                                                       std::to_string(rows.nodes));
          on_node[c] = reg.create<Shape>(ct.name, shape_params(ct, contactor_keys), ctx, ct.pointer + "/shape");
          if (on_node[c]->support() == Support::facet)
            throw InputError(ct.pointer + "/shape", "shape \"" + ct.name + "\" is a facet of a mesh: give \"boundary\", "
                                                    "the boundary group whose facets it stands for");
          const Placement place_at = placement(ct.params);
          if (on_node[c]->has_mass())
            mass = add(mass, place_at.identity() ? on_node[c]->mass_properties() : place(dim_, on_node[c]->mass_properties(), place_at));
        }
        // The modelization may take the cluster's centre of mass as the body origin: the
        // contactors stay where the scene put them, so their offsets are re-expressed.
        const auto origin = w->models[rows.model].modelization->init_body(w->state, i, b.model.params, mass, material);
        auto emit = [&](Owned<Shape> shape, const PluginUse& ct, Placement place_at, const std::size_t* nodes, int count) {
          for (int k = 0; k < 3; ++k) place_at.offset[k] -= origin[k];
          const std::string group = ct.params.string("group");
          w->contactor_info.push_back(io::ContactorInfo{static_cast<int>(i), rows.model, nodes[0],
                                                        static_cast<int>(nodes[0] - rows.first_node), ct.name, group,
                                                        place_at.offset,
                                                        dim_ == 2 ? std::array<double, 4>{place_at.angle, 0, 0, 0}
                                                                  : place_at.orientation});
          display_shapes.push_back(shape.get());
          if (!group_index.count(group)) {  // contactors of groups no interaction names are never detected
            undetected.push_back(std::move(shape));
            return;
          }
          Contactor made{static_cast<int>(i), group_index.at(group), std::move(shape), place_at, rows.model, nodes[0]};
          made.count = count;
          std::copy(nodes, nodes + count, made.nodes.begin());
          contactors.push_back(std::move(made));
        };
        for (std::size_t c = 0; c < b.contactors.size(); ++c) {
          const auto& ct = b.contactors[c];
          if (on_node[c]) {
            const std::size_t node = rows.first_node + static_cast<std::size_t>(ct.params.has("node") ? ct.params.integer("node") : 0);
            emit(std::move(on_node[c]), ct, placement(ct.params), &node, 1);
          } else {
            emit_boundary(w->state, i, ct, contactor_keys, reg, ctx, emit);
          }
        }
      }
      if (w->output.shapes) w->display = build_display(w->state, w->contactor_info, display_shapes);
      for (const auto& m : w->models) {
        const Topology t = m.modelization->topology(w->state);
        if (t.count > 0)
          w->topologies.push_back(io::SetTopology{m.modelization->element_set(), m.modelization->node_set(), t.cells, t.count});
      }
      set_contactor_reach(dim_, w->contactor_info, display_shapes);
      undetected.clear();
      if (!interactions_.empty()) build_contacts(*w, reg, ctx, std::move(contactors), group_index);
      for (const auto& d : drivers_) w->drivers.push_back(built_driver(w->state, d, names));
      // Each modelization's integrator: the scene's `models.<name>.integrator`, else
      // `time.integrator`, else the modelization's own choice.
      for (auto& m : w->models) {
        const ModelUse& use = model_uses_.at(m.name);
        std::string name = use.integrator.empty() ? m.modelization->default_integrator() : use.integrator;
        m.integrator = reg.create<Integrator>(name, Params(json::object(), use.integrator_pointer), ctx, use.integrator_pointer);
        m.integrator->prepare(w->state, *m.modelization);
      }
      if (w->contacts) {
        for (const auto& m : w->models)
          w->contacts->models.push_back(ContactModel{m.modelization.get(), m.integrator.get(), m.modelization->node_set(),
                                                     m.modelization->node_dofs(dim_)});
        // A contactor's node must say where it is at detection and take the impulses back.
        for (const auto& c : w->contacts->contactors) {
          const ModelInfo& m = w->state.models()[c.model];
          for (const char* f : {node_fields::detection_position, node_fields::reaction})
            if (!w->state.has(m.nodes, f))
              throw InputError(bodies_[c.body].model.pointer + "/contactors",
                               "modelization \"" + m.name + "\" has no node field '" + f +
                                   "' (sdk/README.md, Writing a modelization): its bodies cannot carry contactors that interact");
        }
      }
      ctx.state = &w->state;
      for (const auto& f : forces_) w->forces.push_back(reg.create<Force>(f.name, f.params, ctx, f.pointer));
      for (const auto& h : hooks_) w->hooks.push_back(reg.create<Hook>(h.name, h.params, ctx, h.pointer));
      if (!analyses_.empty()) w->analyses = build_analyses(*w, reg, ctx, analyses_);
    } catch (const InputError& e) {
      throw e.with_file(file_.path);
    } catch (...) {
      // Still inside the World that keeps the plugins loaded (boundary.hpp).
      rethrow_kernel_owned("a plugin", "while the scene was built");
    }
    return w;
  }

 private:
  struct BodyUse {
    std::string name;
    std::string material;
    PluginUse model;
    std::vector<PluginUse> contactors;
    bool fixed = false;
  };

  /// A contactor's own parameters: the shape's, without the kernel's keys.
  static Params shape_params(const PluginUse& c, const Schema& kernel_keys) {
    json params = c.params.json();
    for (const auto& k : kernel_keys.params()) params.erase(k.name);
    return Params(params, c.pointer);
  }

  /// A contactor on a boundary group (docs/scene.md, "Contactors on meshes"): a shape on
  /// one node is repeated on each node of the group's facets (candidates: `point`), a
  /// facet shape on each facet (antagonists: `edge`, `face`), in the group's order.
  template <class Emit>
  void emit_boundary(const State& st, std::size_t body, const PluginUse& ct, const Schema& kernel_keys, Registry& reg,
                     const BuildContext& ctx, Emit& emit) const {
    if (ct.params.has("node"))
      throw InputError(ct.pointer + "/node", "a contactor on a \"boundary\" sits on the boundary's nodes or facets: "
                                             "give \"node\" or \"boundary\", not both");
    const FacetGroup& group = st.facet_group(body, ct.params.string("boundary"), ct.pointer + "/boundary");
    const Params params = shape_params(ct, kernel_keys);
    const Placement place_at = placement(ct.params);
    Owned<Shape> first = reg.create<Shape>(ct.name, params, ctx, ct.pointer + "/shape");
    auto make = [&]() { return first ? std::move(first) : reg.create<Shape>(ct.name, params, ctx, ct.pointer + "/shape"); };
    if (first->support() == Support::facet) {
      if (!place_at.identity())
        throw InputError(ct.pointer, "a facet shape (\"" + ct.name + "\") is its facet: it takes no \"offset\" or rotation");
      const std::size_t want_lo = dim_ == 2 ? 2 : 3, want_hi = dim_ == 2 ? 2 : 4;
      for (std::size_t f = 0; f < group.size(); ++f) {
        if (group.count(f) < want_lo || group.count(f) > want_hi)
          throw InputError(ct.pointer + "/boundary", "facet " + std::to_string(f) + " of group \"" + ct.params.string("boundary") +
                                                         "\" has " + std::to_string(group.count(f)) + " nodes: a " +
                                                         (dim_ == 2 ? "2D facet has 2" : "3D facet has 3 or 4"));
        emit(make(), ct, place_at, group.facet(f), static_cast<int>(group.count(f)));
      }
      return;
    }
    std::vector<std::size_t> nodes = group.nodes;
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (const std::size_t n : nodes) emit(make(), ct, place_at, &n, 1);
  }

  /// A validated contactor's placement in its body frame (kernel keys, defaults filled in).
  Placement placement(const Params& c) const {
    Placement p;
    const auto o = c.vector("offset");
    for (int k = 0; k < dim_; ++k) p.offset[k] = o[k];
    if (dim_ == 2) {
      p.angle = c.number("angle");
    } else {
      const auto q = c.vector("orientation");
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);  // ≈ 1, checked
      for (int k = 0; k < 4; ++k) p.orientation[k] = q[k] / n;
    }
    return p;
  }

  static MassProperties add(const std::optional<MassProperties>& sum, const MassProperties& m) {
    if (!sum) return m;
    MassProperties out;
    out.volume = sum->volume + m.volume;
    for (int k = 0; k < 3; ++k)
      out.center[k] = out.volume > 0 ? (sum->center[k] * sum->volume + m.center[k] * m.volume) / out.volume : 0.0;
    // Parallel-axis theorem: both parts' inertia moved to the common centre.
    for (const MassProperties* part : {&*sum, &m}) {
      double dlt[3];
      for (int k = 0; k < 3; ++k) dlt[k] = part->center[k] - out.center[k];
      const double d2 = dlt[0] * dlt[0] + dlt[1] * dlt[1] + dlt[2] * dlt[2];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          out.inertia[3 * i + j] += part->inertia[3 * i + j] + part->volume * ((i == j ? d2 : 0.0) - dlt[i] * dlt[j]);
    }
    return out;
  }

  void build_contacts(World& w, Registry& reg, const BuildContext& ctx, std::vector<Contactor> contactors,
                      const std::map<std::string, int>& group_index) {
    auto cs = std::make_unique<ContactStages>();
    cs->contactors = std::move(contactors);
    cs->groups = static_cast<int>(group_index.size());
    cs->law_of.assign(static_cast<std::size_t>(cs->groups) * cs->groups, -1);
    std::map<std::string, int> law_index;
    std::vector<std::string> law_names, law_pointers;
    for (const auto& [name, use] : laws_) {
      law_index[name] = static_cast<int>(cs->laws.size());
      cs->laws.push_back(reg.create<Law>(use.name, use.params, ctx, use.pointer));
      law_names.push_back(name);
      law_pointers.push_back(use.pointer);
    }
    cs->setup_laws(w.state, law_names, law_pointers);
    for (const auto& in : interactions_) {
      const int a = group_index.at(in.a), b = group_index.at(in.b), l = law_index.at(in.law);
      cs->law_of[a * cs->groups + b] = cs->law_of[b * cs->groups + a] = l;
    }
    std::map<std::string, const Detector*> made;
    for (const auto& [pair, use] : detector_uses_) {
      if (!made.count(use.first)) {
        cs->detector_objects.push_back(reg.create<Detector>(use.first, Params(json::object(), "/interactions"), ctx));
        made[use.first] = cs->detector_objects.back().get();
      }
      cs->detectors.push_back(DetectorUse{pair.first, pair.second, made[use.first], use.second});
    }
    cs->broadphase = reg.create<BroadPhase>(broadphase_.name, broadphase_.params, ctx, broadphase_.pointer);
    cs->solver = reg.create<Solver>(solver_.name, solver_.params, ctx, solver_.pointer);
    cs->setup_solver(w.state);
    cs->alert = detection_["alert"].get<double>();
    // A law acting on open contacts (a meniscus) sees them only within the alert distance.
    for (std::size_t l = 0; l < cs->laws.size(); ++l)
      if (cs->laws[l]->range() > cs->alert) {
        char msg[256];
        std::snprintf(msg, sizeof msg, "law \"%s\" acts on contacts up to %g m apart: expected an alert distance of at "
                      "least that (it is %g m)", law_names[l].c_str(), cs->laws[l]->range(), cs->alert);
        throw InputError("/detection/alert", msg);
      }
    cs->stop_on_failure = stop_on_failure_;
    cs->solve_log.tolerance = solver_.params.json().value("tolerance", 0.0);
    if (!shadows_.empty()) make_shadows(*cs, reg, ctx);
    if (export_) cs->exporter = std::make_unique<ProblemExport>(export_settings(w, ctx));
    w.contacts = std::move(cs);
  }

  /// MOREAU_SHADOW_SOLVERS (docs/solvers.md, "Comparing solvers on one run"): a JSON array
  /// of solver blocks (or names), each validated as the scene's `solver` block; one without
  /// `tolerance` takes the scene solver's. Its faults name the variable, not the scene.
  void check_shadows() {
    const std::string var = "MOREAU_SHADOW_SOLVERS (environment variable)";
    json list;
    try {
      list = json::parse(shadow_text_);
    } catch (const json::parse_error& e) {
      errors_.emplace_back("", std::string("expected a JSON array of solver blocks, e.g. [{\"type\": \"nlgs\"}]: ") + e.what(), var);
      return;
    }
    if (!list.is_array() || list.empty()) {
      errors_.emplace_back("", "expected a non-empty JSON array of solver blocks, e.g. [{\"type\": \"nlgs\"}], got " + list.dump(), var);
      return;
    }
    if (!has_interactions()) {
      errors_.emplace_back("", "the scene has no interactions: no contact problems for shadow solvers to solve", var);
      return;
    }
    const json scene_tolerance = solver_.params.json().value("tolerance", json());
    const std::size_t before = errors_.size();
    for (std::size_t i = 0; i < list.size(); ++i) {
      json spec = list[i].is_string() ? json{{"type", list[i]}} : list[i];
      if (spec.is_object() && !spec.contains("tolerance") && !scene_tolerance.is_null()) spec["tolerance"] = scene_tolerance;
      shadows_.push_back(plugin_use(Kind::solver, spec, "/" + std::to_string(i)));
    }
    for (std::size_t k = before; k < errors_.size(); ++k) errors_[k] = errors_[k].with_file(var);
  }

  /// The shadow solvers, each its own instance (its own state over the run, as `auto`'s
  /// memory), made as the scene's solver is.
  void make_shadows(ContactStages& cs, Registry& reg, const BuildContext& ctx) const {
    auto block = [](const PluginUse& u) {
      json b = u.params.json();
      b["type"] = u.name;
      return b.dump();
    };
    cs.shadows = std::make_unique<ShadowSolvers>(solver_.name, block(solver_));
    std::map<std::string, int> seen{{solver_.name, 1}};
    for (const PluginUse& u : shadows_) {
      const int n = ++seen[u.name];
      cs.shadows->add(n == 1 ? u.name : u.name + " #" + std::to_string(n), block(u),
                      reg.create<Solver>(u.name, u.params, ctx, "MOREAU_SHADOW_SOLVERS" + u.pointer));
    }
  }

  /// `export_problems` (docs/scene.md): exactly one of `steps` and `every`, steps the run
  /// reaches, and contacts to export.
  void check_export() {
    if (!top_.contains("export_problems") || !top_["export_problems"].is_object()) return;  // a non-object is reported already
    const std::string ptr = "/export_problems";
    const std::size_t before = errors_.size();
    Validation v{dim_, errors_};
    json e = validate_object(top_["export_problems"], scene_schema::export_problems(), ptr, v);
    if (!has_interactions())
      errors_.emplace_back(ptr, "the scene has no interactions, so no contact problems to export");
    const bool steps = e.contains("steps"), every = e.contains("every");
    if (steps == every)
      errors_.emplace_back(ptr, steps ? "give either \"steps\" or \"every\", not both"
                                      : "missing \"steps\" (a list of steps) or \"every\" (every N-th step)");
    // The scene's step count, when its time section is sound (its faults are reported there).
    long last = -1;
    if (time_.contains("step") && time_["step"].is_number() && time_.contains("duration") && time_["duration"].is_number() &&
        time_["step"].get<double>() > 0)
      last = std::llround(time_["duration"].get<double>() / time_["step"].get<double>());
    std::vector<long> list;
    if (steps && e["steps"].is_array()) {
      if (e["steps"].empty()) errors_.emplace_back(ptr + "/steps", "expected at least one step number");
      for (std::size_t i = 0; i < e["steps"].size(); ++i) {
        const json& x = e["steps"][i];
        const std::string ip = ptr + "/steps/" + std::to_string(i);
        if (!x.is_number_integer() && !x.is_number_unsigned()) {
          errors_.emplace_back(ip, "expected a step number (an integer >= 1), got " + x.dump());
        } else if (x.get<long>() < 1) {
          errors_.emplace_back(ip, "step " + x.dump() + " out of range: steps are counted from 1 (step N ends at t = N h)");
        } else if (last >= 0 && x.get<long>() > last) {
          errors_.emplace_back(ip, "step " + x.dump() + " is after the scene's last step " + std::to_string(last) +
                                       " (round(duration / step))");
        } else {
          list.push_back(x.get<long>());
        }
      }
    }
    if (every && e["every"].is_number_integer() && last >= 0 && e["every"].get<long>() > last)
      errors_.emplace_back(ptr + "/every", "every " + e["every"].dump() + " exports nothing: the scene has " +
                                               std::to_string(last) + " steps");
    if (errors_.size() != before) return;
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    e["steps"] = list;
    export_ = e;
  }

  ProblemExportSettings export_settings(const World& w, const BuildContext& ctx) const {
    ProblemExportSettings s;
    s.steps = (*export_)["steps"].get<std::vector<long>>();
    s.every = export_->value("every", 0L);
    // Beside the output (--out moves both), so one run's files stay together.
    s.directory = (fs::path(ctx.output_dir) / (*export_)["directory"].get<std::string>()).lexically_normal().string();
    s.stem = fs::path(w.scene_file).stem().string();
    s.min_contacts = (*export_)["min_contacts"].get<long>();
    s.global = (*export_)["kind"] == "global";
    s.scene_file = w.scene_file;
    json solver = solver_.params.json();
    solver["type"] = solver_.name;
    s.solver = solver.dump();
    return s;
  }

  [[noreturn]] void fail_now(const std::string& ptr, const std::string& msg) {
    errors_.emplace_back(ptr, msg);
    throw_all();
  }
  [[noreturn]] void throw_all() {
    std::vector<InputError> with_file;
    for (const auto& e : errors_) with_file.push_back(e.with_file(file_.path));
    throw InputErrors(std::move(with_file));
  }

  /// Looks the plugin up (loading its library) and validates its parameters.
  /// `spec` is either a name or an object {"type": name, ...parameters}.
  PluginUse plugin_use(Kind kind, const json& spec, const std::string& ptr, const std::string& default_type = "",
                       const std::vector<std::string>& kernel_keys = {}) {
    PluginUse use;
    use.pointer = ptr;
    json params = json::object();
    std::string type_ptr = ptr;
    if (spec.is_string()) {
      use.name = spec.get<std::string>();
    } else if (spec.is_object()) {
      if (spec.contains("type") && spec["type"].is_string()) use.name = spec["type"].get<std::string>();
      else if (!spec.contains("type") && !default_type.empty()) use.name = default_type;
      else {
        errors_.emplace_back(ptr + "/type", std::string("missing or invalid \"type\": expected the name of a ") +
                                                kind_name(kind) + " plugin");
        return use;
      }
      params = spec;
      params.erase("type");
      type_ptr = ptr + "/type";
    } else {
      errors_.emplace_back(ptr, std::string("expected a ") + kind_name(kind) + " name or an object with \"type\"");
      return use;
    }
    const RegistryEntry* e = lookup(kind, use.name, type_ptr);
    if (!e) return use;
    check_dimension(*e, type_ptr);
    Validation v{dim_, errors_};
    std::vector<std::string> allowed = kernel_keys;
    allowed.push_back("type");
    use.params = Params(validate_object(spec.is_object() ? spec : json::object(), e->registration.schema, ptr, v, allowed), ptr);
    json filled = use.params.json();
    for (const auto& k : allowed) filled.erase(k);
    use.params = Params(filled, ptr);
    return use;
  }

  const RegistryEntry* lookup(Kind kind, const std::string& name, const std::string& ptr) {
    try {
      return &registry_->require(kind, name, ptr);
    } catch (const InputError& e) {
      errors_.push_back(e);
      return nullptr;
    }
  }

  void check_dimension(const RegistryEntry& e, const std::string& ptr) {
    if (!e.registration.schema.supports(dim_))
      errors_.emplace_back(ptr, std::string(kind_name(e.registration.kind)) + " '" + e.registration.name +
                                    "' does not support " + std::to_string(dim_) + "D scenes");
  }

  void check_materials() {
    Validation v{dim_, errors_};
    if (!top_["materials"].is_object()) return;
    for (auto it = top_["materials"].begin(); it != top_["materials"].end(); ++it) {
      json m = validate_object(it.value(), scene_schema::material(), "/materials/" + pointer_token(it.key()), v);
      if (m.contains("density") && m["density"].is_number())
        materials_[it.key()] = Params(m, "/materials/" + pointer_token(it.key()));
    }
  }

  void check_bodies() {
    if (!top_["bodies"].is_array()) return;
    Validation v{dim_, errors_};
    std::set<std::string> seen;
    const json& bodies = top_["bodies"];
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const std::string ptr = "/bodies/" + std::to_string(i);
      const json& b = bodies[i];
      if (!b.is_object()) { errors_.emplace_back(ptr, "expected a body object"); continue; }
      BodyUse body;
      const Schema kernel_keys = scene_schema::body_kernel_keys();
      // Kernel keys first, then the model's keys: one unknown-key pass over the union.
      std::string model = b.contains("model") && b["model"].is_string() ? b["model"].get<std::string>() : "rigid";
      const RegistryEntry* m = lookup(Kind::modelization, model, ptr + "/model");
      Schema all = kernel_keys;
      std::unique_ptr<Plugin> probe;
      if (m) {
        check_dimension(*m, ptr + "/model");
        all.merge(body_schema(*m, ptr + "/model"));
      }
      json checked = validate_object(b, all, ptr, v);
      if (checked.contains("name") && checked["name"].is_string()) {
        body.name = checked["name"].get<std::string>();
        if (!seen.insert(body.name).second) errors_.emplace_back(ptr + "/name", "duplicate body name \"" + body.name + "\"");
      }
      if (m && !model_uses_.count(model)) model_uses_[model] = ModelUse{};
      if (checked.contains("material") && checked["material"].is_string()) {
        body.material = checked["material"].get<std::string>();
        if (!materials_.count(body.material)) {
          std::vector<std::string> names;
          for (const auto& [k, d] : materials_) names.push_back(k);
          errors_.emplace_back(ptr + "/material",
                               "unknown material \"" + body.material + "\"" + did_you_mean(body.material, names));
        }
      }
      json model_params = checked;
      for (const auto& p : kernel_keys.params()) model_params.erase(p.name);
      body.model = PluginUse{model, Params(model_params, ptr), ptr};
      if (checked.contains("contactors") && checked["contactors"].is_array()) {
        const json& cs = checked["contactors"];
        for (std::size_t c = 0; c < cs.size(); ++c) body.contactors.push_back(contactor(cs[c], ptr + "/contactors/" + std::to_string(c)));
      }
      const json fixed = checked.value("fixed", json(false));
      body.fixed = fixed.is_boolean() && fixed.get<bool>();
      bodies_.push_back(std::move(body));
    }
    if (bodies.empty()) errors_.emplace_back("/bodies", "a scene needs at least one body");
  }

  /// A modelization's body schema comes from an instance (it depends on the dimension),
  /// made once per modelization.
  Schema body_schema(const RegistryEntry& m, const std::string& ptr) {
    auto it = body_schemas_.find(m.registration.name);
    if (it != body_schemas_.end()) return it->second;
    BuildContext ctx;
    ctx.dimension = dim_;
    Schema s;
    try {
      auto obj = m.registration.factory(Params(json::object(), "/bodies"), ctx);
      auto* model = dynamic_cast<Modelization*>(obj.get());
      if (model) s = model->body_schema(dim_);
    } catch (...) {
      rethrow_kernel_owned_input(ptr, plugin_label(Kind::modelization, m.registration.name), "while giving its body keys");
    }
    body_schemas_[m.registration.name] = s;
    return s;
  }

  /// `models` (docs/scene.md): per modelization its parameters (its schema) and, as
  /// `integrator`, the integrator it is paired with; `time.integrator` is the default of
  /// every model that names none. A model no body uses is an error (nothing ignored).
  void check_models() {
    const std::string time_integrator = time_.contains("integrator") && time_["integrator"].is_string()
                                            ? time_["integrator"].get<std::string>() : "";
    if (!time_integrator.empty()) lookup(Kind::integrator, time_integrator, "/time/integrator");
    for (auto& [name, use] : model_uses_) {
      use.integrator = time_integrator;
      use.integrator_pointer = time_integrator.empty() ? "/bodies" : "/time/integrator";
      use.pointer = "/bodies";
      use.params = Params(json::object(), "/models/" + pointer_token(name));
    }
    if (!top_.contains("models") || !top_["models"].is_object()) return;
    Validation v{dim_, errors_};
    for (auto it = top_["models"].begin(); it != top_["models"].end(); ++it) {
      const std::string ptr = "/models/" + pointer_token(it.key());
      if (!model_uses_.count(it.key())) {
        std::vector<std::string> used;
        for (const auto& [n, u] : model_uses_) used.push_back(n);
        errors_.emplace_back(ptr, "no body uses the modelization \"" + it.key() + "\"" + did_you_mean(it.key(), used));
        continue;
      }
      const RegistryEntry* e = lookup(Kind::modelization, it.key(), ptr);
      if (!e) continue;
      Schema all;
      all.string("integrator", "the integrator paired with this modelization").optional();
      all.merge(e->registration.schema);
      json checked = validate_object(it.value(), all, ptr, v);
      ModelUse& use = model_uses_[it.key()];
      if (checked.contains("integrator") && checked["integrator"].is_string()) {
        use.integrator = checked["integrator"].get<std::string>();
        use.integrator_pointer = ptr + "/integrator";
        lookup(Kind::integrator, use.integrator, use.integrator_pointer);
        checked.erase("integrator");
      }
      use.pointer = ptr;
      use.params = Params(checked, ptr);
    }
  }

  PluginUse contactor(const json& c, const std::string& ptr) {
    PluginUse use;
    use.pointer = ptr;
    if (!c.is_object()) { errors_.emplace_back(ptr, "expected a contactor object"); return use; }
    if (!c.contains("shape") || !c["shape"].is_string()) {
      errors_.emplace_back(ptr + "/shape", "missing or invalid \"shape\": expected the name of a shape plugin");
      return use;
    }
    use.name = c["shape"].get<std::string>();
    const RegistryEntry* e = lookup(Kind::shape, use.name, ptr + "/shape");
    if (!e) return use;
    check_dimension(*e, ptr + "/shape");
    Schema all = scene_schema::contactor_kernel_keys(dim_);
    all.merge(e->registration.schema);
    Validation v{dim_, errors_};
    const std::size_t before = errors_.size();
    use.params = Params(validate_object(c, all, ptr, v), ptr);
    use.valid = errors_.size() == before;
    // A placement's rotation must be a rotation: same tolerance as a body's orientation.
    const json& q = use.params.json().value("orientation", json());
    if (dim_ == 3 && q.is_array() && q.size() == 4 && std::all_of(q.begin(), q.end(), [](const json& x) { return x.is_number(); })) {
      double n2 = 0;
      for (const auto& x : q) n2 += x.get<double>() * x.get<double>();
      if (std::fabs(std::sqrt(n2) - 1) > 1e-6)
        errors_.emplace_back(ptr + "/orientation", "expected a unit quaternion [w, x, y, z], its norm is " +
                                                       std::to_string(std::sqrt(n2)));
    }
    return use;
  }

  void check_drivers() {
    if (!top_["drivers"].is_array()) return;
    Validation v{dim_, errors_};
    const json& ds = top_["drivers"];
    const int rot = dim_ == 2 ? 1 : 3;
    for (std::size_t i = 0; i < ds.size(); ++i) {
      const std::string ptr = "/drivers/" + std::to_string(i);
      const std::size_t before = errors_.size();
      json d = validate_object(ds[i], scene_schema::driver(), ptr, v);
      if (errors_.size() != before) continue;
      Driver drv;
      drv.pointer = ptr;
      const std::string name = d["body"].get<std::string>();
      drv.body = body_index(name);
      if (d.contains("nodes") && d["nodes"].is_string()) drv.node_group = d["nodes"].get<std::string>();
      if (drv.body < 0) {
        errors_.emplace_back(ptr + "/body", "no body named \"" + name + "\"" + did_you_mean(name, body_names()));
        continue;
      }
      drv.velocity.assign(dim_ + rot, std::nan(""));
      auto fill = [&](const char* key, int offset) {
        if (!d.contains(key) || d[key].is_null()) return;
        for (std::size_t k = 0; k < d[key].size(); ++k)
          if (!d[key][k].is_null()) drv.velocity[offset + k] = d[key][k].get<double>();
      };
      fill("velocity", 0);
      fill("angular_velocity", dim_);
      if (!d.contains("velocity") && !d.contains("angular_velocity"))
        errors_.emplace_back(ptr, "a driver imposes \"velocity\" and/or \"angular_velocity\": neither is given");
      drv.start = d["start"].get<double>();
      if (d.contains("end") && !d["end"].is_null()) {
        drv.end = d["end"].get<double>();
        if (drv.end < drv.start) errors_.emplace_back(ptr + "/end", "\"end\" is before \"start\"");
      }
      drivers_.push_back(drv);
    }
  }

  std::vector<std::string> body_names() const {
    std::vector<std::string> names;
    for (const auto& b : bodies_) names.push_back(b.name);
    return names;
  }

  /// A driver on the rows it drives (docs/scene.md, Drivers): the body's one node, or each
  /// node of a node group (`nodes`); its velocity cut to the modelization's k unknowns.
  Driver built_driver(const State& st, Driver drv, const std::vector<std::string>& names) const {
    const std::size_t b = static_cast<std::size_t>(drv.body);
    const BodyRows rows = st.body(b);
    const ModelInfo& m = st.models()[rows.model];
    const std::string& name = names[b];
    if (drv.node_group.empty()) {
      if (rows.nodes != 1)
        throw InputError(drv.pointer + "/body", "a driver without \"nodes\" imposes the velocity of a one-node body: body \"" +
                                                    name + "\" is a \"" + m.name + "\" body with " + std::to_string(rows.nodes) +
                                                    " nodes; give \"nodes\", one of its node groups");
      drv.rows = {rows.first_node};
    } else {
      drv.rows = st.node_group(b, drv.node_group, drv.pointer + "/nodes");
    }
    if (!st.has(m.nodes, node_fields::imposed_velocity))
      throw InputError(drv.pointer + "/body", "body \"" + name + "\" is a \"" + m.name +
                                                  "\" body, whose modelization takes no imposed velocities");
    const std::size_t k = static_cast<std::size_t>(m.node_dofs);
    if (k == static_cast<std::size_t>(dim_) && drv.velocity.size() > k) {  // nodes of a mesh: no rotation
      for (std::size_t i = k; i < drv.velocity.size(); ++i)
        if (!std::isnan(drv.velocity[i]))
          throw InputError(drv.pointer + "/angular_velocity", "body \"" + name + "\" is a \"" + m.name +
                                                                  "\" body: its nodes do not turn (give \"velocity\" only)");
      drv.velocity.resize(k);
    }
    if (drv.velocity.size() != k)
      throw InputError(drv.pointer, "body \"" + name + "\" has " + std::to_string(k) + " unknowns per node, the driver gives " +
                                        std::to_string(drv.velocity.size()));
    return drv;
  }

  int body_index(const std::string& name) const {
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (bodies_[i].name == name) return static_cast<int>(i);
    return -1;
  }

  /// The groups written on contactors whose shape is unknown (or invalid), which have no
  /// validated parameters: that error is said once, at the shape, not again at every
  /// interaction naming the group.
  void insert_groups_of_unknown_shapes(std::set<std::string>& groups) const {
    if (!top_["bodies"].is_array()) return;
    for (const auto& b : top_["bodies"])
      if (b.is_object() && b.contains("contactors") && b["contactors"].is_array())
        for (const auto& c : b["contactors"])
          if (c.is_object() && c.contains("group") && c["group"].is_string()) groups.insert(c["group"].get<std::string>());
  }

  void check_interactions() {
    if (!top_["laws"].is_object()) return;
    for (auto it = top_["laws"].begin(); it != top_["laws"].end(); ++it)
      laws_[it.key()] = plugin_use(Kind::law, it.value(), "/laws/" + pointer_token(it.key()));
    if (!top_["interactions"].is_array()) return;
    Validation v{dim_, errors_};
    std::set<std::string> groups;
    for (const auto& b : bodies_)
      for (const auto& c : b.contactors)
        if (auto g = group_of(c)) groups.insert(*g);
    insert_groups_of_unknown_shapes(groups);
    const json& is = top_["interactions"];
    for (std::size_t i = 0; i < is.size(); ++i) {
      const std::string ptr = "/interactions/" + std::to_string(i);
      const std::size_t before = errors_.size();
      json in = validate_object(is[i], scene_schema::interaction(), ptr, v);
      if (errors_.size() != before) continue;
      const json& g = in["groups"];
      if (g.size() != 2 || !g[0].is_string() || !g[1].is_string()) {
        errors_.emplace_back(ptr + "/groups", "expected two group names");
        continue;
      }
      for (int k = 0; k < 2; ++k)
        if (!groups.count(g[k].get<std::string>()))
          errors_.emplace_back(ptr + "/groups/" + std::to_string(k),
                               "no contactor has group \"" + g[k].get<std::string>() + "\"" +
                                   did_you_mean(g[k].get<std::string>(), {groups.begin(), groups.end()}));
      const std::string law = in["law"].get<std::string>();
      if (!laws_.count(law)) {
        std::vector<std::string> names;
        for (const auto& [n, use] : laws_) names.push_back(n);
        errors_.emplace_back(ptr + "/law", "no law named \"" + law + "\" in \"laws\"" + did_you_mean(law, names));
      }
      interactions_.push_back({g[0].get<std::string>(), g[1].get<std::string>(), law, ptr});
    }
  }

  /// A newcomer's scene often has shapes but no `interactions` (or leaves a group out of
  /// them): its bodies then fall through each other without a word. Say so.
  void warn_groups_that_never_collide() const {
    std::map<std::string, int> contactors;  // per group
    for (const auto& b : bodies_)
      for (const auto& c : b.contactors) ++contactors[c.params.has("group") ? c.params.string("group") : "default"];
    if (contactors.empty()) return;
    if (!has_interactions()) {
      warn(file_.path + ": the scene has " + std::to_string(bodies_.size()) + " bodies with contactors but no " +
           "\"interactions\": nothing will collide (add e.g. \"interactions\": [{\"groups\": [\"" +
           contactors.begin()->first + "\", \"" + contactors.begin()->first + "\"], \"law\": NAME}] and the law in \"laws\")");
      return;
    }
    for (const auto& [group, count] : contactors) {
      const bool paired = std::any_of(interactions_.begin(), interactions_.end(),
                                      [&g = group](const InteractionUse& in) { return in.a == g || in.b == g; });
      if (!paired)
        warn(file_.path + ": " + std::to_string(count) + " contactor" + (count == 1 ? "" : "s") + " of group \"" + group +
             "\" " + (count == 1 ? "is" : "are") + " in no interaction: nothing will collide with " +
             (count == 1 ? "it" : "them"));
    }
  }

  /// Newton's restitution with Coulomb friction can gain energy at an impact off a moving
  /// body's centre (docs/contacts.md, "Energy at impacts"; the θ-scheme's own gain is
  /// corrected, this one is the law's). Say so for a law with both (its `restitution` and
  /// `friction` parameters, `coulomb`'s names) with e above 0.8 (where a seeded sweep of
  /// spinning squares found gains; none below, tests/validation/test_bounce.cpp) used by a
  /// group that holds a contactor of a moving body other than one disk or sphere at its
  /// centre: a disk's or a sphere's contact normal goes through its centre.
  void warn_restitution_with_friction() const {
    std::set<std::string> eccentric;  // groups
    for (const auto& b : bodies_)
      for (const auto& c : b.contactors) {
        if (b.fixed) continue;
        const std::vector<double> offset = c.params.has("offset") ? c.params.vector("offset") : std::vector<double>{};
        const bool centred = std::all_of(offset.begin(), offset.end(), [](double x) { return x == 0.0; });
        const bool round = (c.name == "disk" || c.name == "sphere") && b.contactors.size() == 1 && centred;
        if (!round) eccentric.insert(c.params.has("group") ? c.params.string("group") : "default");
      }
    const auto above = [](const Params& p, const char* key, double x) {
      return p.has(key) && p.raw(key).is_number() && p.number(key) > x;
    };
    for (const auto& [name, use] : laws_) {
      if (!above(use.params, "restitution", 0.8) || !above(use.params, "friction", 0)) continue;
      const auto in = std::find_if(interactions_.begin(), interactions_.end(), [&, &law = name](const InteractionUse& i) {
        return i.law == law && (eccentric.count(i.a) || eccentric.count(i.b));
      });
      if (in == interactions_.end()) continue;
      std::ostringstream os;
      os << file_.path << ": law \"" << name << "\": Newton restitution (e = " << use.params.number("restitution")
         << ") with friction (mu = " << use.params.number("friction") << ") can gain energy at an impact off a body's "
         << "centre (group \"" << (eccentric.count(in->a) ? in->a : in->b) << "\" holds moving shapes other than "
         << "one centred disk or sphere): in a test of spinning squares hitting a floor, up to 5 % of the energy at "
         << "e = 0.85 and 29 % at e = 1, none at e <= 0.8 (docs/contacts.md, \"Energy at impacts\")";
      warn(os.str());
    }
  }

  bool has_interactions() const {
    return top_.contains("interactions") && top_["interactions"].is_array() && !top_["interactions"].empty();
  }

  /// Every pair of shape names that interacting groups can bring together needs a detector.
  void check_detectors() {
    for (const auto& in : interactions_) {
      std::set<std::string> shapes_a, shapes_b;
      for (const auto& b : bodies_)
        for (const auto& c : b.contactors) {
          const auto g = group_of(c);
          if (!g) continue;
          if (*g == in.a) shapes_a.insert(c.name);
          if (*g == in.b) shapes_b.insert(c.name);
        }
      for (const auto& sa : shapes_a)
        for (const auto& sb : shapes_b) {
          if (detector_uses_.count({sa, sb})) continue;
          const RegistryEntry* e = nullptr;
          bool swap = false;
          try {
            e = registry_->find(Kind::detector, sa + "-" + sb);
            if (!e) {
              e = registry_->find(Kind::detector, sb + "-" + sa);
              swap = true;
            }
          } catch (const InputError& err) {
            errors_.push_back(InputError(in.pointer, err.what() + std::string(" (library ") + err.file() + ")"));
            continue;
          }
          if (!e) {
            auto names = registry_->available(Kind::detector);
            std::string list;
            for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
            errors_.emplace_back(in.pointer + "/groups", "no detector for shapes \"" + sa + "\" and \"" + sb +
                                                             "\" (looked for detector \"" + sa + "-" + sb + "\" or \"" +
                                                             sb + "-" + sa + "\"; available: " + list + ")");
            continue;
          }
          detector_uses_[{sa, sb}] = {e->registration.name, swap};
          detector_uses_[{sb, sa}] = {e->registration.name, !swap};
        }
    }
  }

  /// `analyses`: each a plugin entry whose kernel keys (name, region, every) are checked
  /// in kernel/analysis (docs/analyses.md).
  void check_analyses() {
    if (!top_["analyses"].is_array()) return;
    const json& list = top_["analyses"];
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string ptr = "/analyses/" + std::to_string(i);
      PluginUse use = plugin_use(Kind::analysis, list[i], ptr, "", analysis_kernel_keys());
      analyses_.push_back(AnalysisEntry{use.name, use.params, ptr, list[i]});
    }
    check_analysis_entries(analyses_, dim_, errors_);
  }

  void check_plugin_list(Kind kind, const char* key, std::vector<PluginUse>& out) {
    if (!top_[key].is_array()) return;
    const json& list = top_[key];
    for (std::size_t i = 0; i < list.size(); ++i)
      out.push_back(plugin_use(kind, list[i], std::string("/") + key + "/" + std::to_string(i)));
  }

  const JsonFile& file_;
  int dim_ = 3;
  std::vector<InputError> errors_;
  json top_, time_, output_, detection_;
  std::unique_ptr<Registry> registry_;
  std::map<std::string, Params> materials_;
  std::map<std::string, PluginUse> laws_;
  std::vector<BodyUse> bodies_;
  std::vector<Driver> drivers_;
  PluginUse solver_, broadphase_;
  std::string shadow_text_;          ///< MOREAU_SHADOW_SOLVERS as `moreau run` read it ("" : none)
  std::vector<PluginUse> shadows_;   ///< its solvers, validated
  /// Per modelization the bodies name: its parameters and its integrator (`models`).
  struct ModelUse {
    Params params;
    std::string pointer;
    std::string integrator;  ///< "" : the modelization's default
    std::string integrator_pointer;
  };
  std::map<std::string, ModelUse> model_uses_;
  std::map<std::string, Schema> body_schemas_;
  struct InteractionUse {
    std::string a, b, law, pointer;
  };
  std::vector<InteractionUse> interactions_;
  std::map<std::pair<std::string, std::string>, std::pair<std::string, bool>> detector_uses_;
  bool stop_on_failure_ = false;
  std::vector<PluginUse> forces_, hooks_;
  std::vector<AnalysisEntry> analyses_;
  std::optional<json> export_;  ///< validated `export_problems`, steps sorted and unique
};

}  // namespace

std::unique_ptr<World> build_world(const std::string& scene_path, const std::string& output_path,
                                   const std::string& shadow_solvers) {
  return build_world(read_json_file(scene_path), output_path, shadow_solvers);
}

std::unique_ptr<World> build_world(const JsonFile& scene, const std::string& output_path, const std::string& shadow_solvers) {
  JsonFile file = scene;
  const Generated generated = expand_generators(file);  // `generators`: bodies appended first
  return generated.locate([&] {
    SceneChecker checker(file, shadow_solvers);
    try {
      checker.check();
    } catch (...) {
      rethrow_kernel_owned("a plugin", "while the scene was checked");  // the checker keeps them loaded
    }
    return checker.build(output_path);
  });
}

void check_scene(const JsonFile& scene) {
  // Built too (nothing is written): plugins check what a schema cannot say, such as
  // degenerate shapes or inconsistent masses, in their constructors.
  build_world(scene, "");
}

void check_scene(const std::string& scene_path) { check_scene(read_json_file(scene_path)); }

}  // namespace moreau::kernel
