#include "builder.hpp"

#include <cmath>
#include <filesystem>
#include <moreau/error.hpp>
#include <moreau/imposed_velocity.hpp>
#include <optional>
#include <map>
#include <set>

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
};

class SceneChecker {
 public:
  SceneChecker(const JsonFile& file) : file_(file) {}

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
    detection_ = validate_object(top_.value("detection", json::object()), scene_schema::detection(), "/detection", v);
    if (top_.contains("generators") && top_["generators"].is_array() && !top_["generators"].empty())
      errors_.emplace_back("/generators", "no body generator plugins are available yet: list the bodies in \"bodies\"");

    std::vector<std::string> scene_paths;
    if (top_.contains("plugin_paths") && top_["plugin_paths"].is_array())
      for (std::size_t i = 0; i < top_["plugin_paths"].size(); ++i) {
        const auto& p = top_["plugin_paths"][i];
        if (p.is_string()) scene_paths.push_back(p.get<std::string>());
        else errors_.emplace_back("/plugin_paths/" + std::to_string(i), "expected a folder path (string)");
      }
    const fs::path scene_dir = fs::absolute(fs::path(file_.path)).parent_path();
    registry_ = std::make_unique<Registry>(Registry::standard_paths(scene_paths, scene_dir));

    check_materials();
    check_bodies();
    check_drivers();
    check_interactions();
    if (time_.contains("integrator")) integrator_ = plugin_use(Kind::integrator, time_["integrator"], "/time/integrator");
    check_plugin_list(Kind::force, "forces", forces_);
    check_plugin_list(Kind::hook, "hooks", hooks_);
    if (!top_["solver"].empty() || has_interactions()) {
      solver_ = plugin_use(Kind::solver, top_["solver"], "/solver", "auto", {"on_failure"});
      const json& sv = top_["solver"];
      if (sv.is_object() && sv.contains("on_failure")) {
        const json& f = sv["on_failure"];
        if (!f.is_string() || (f != "warn" && f != "stop"))
          errors_.emplace_back("/solver/on_failure", "expected \"warn\" or \"stop\"");
        else stop_on_failure_ = f == "stop";
      }
    }
    if (has_interactions()) {
      broadphase_ = plugin_use(Kind::broadphase, detection_["broadphase"], "/detection/broadphase");
      check_detectors();
    }

    if (!errors_.empty()) throw_all();
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

    BuildContext ctx;
    ctx.dimension = dim_;
    ctx.time_step = w->h;
    ctx.scene_file = file_.path;
    ctx.scene_dir = fs::absolute(fs::path(file_.path)).parent_path().string();
    ctx.output_dir = fs::absolute(fs::path(output_path.empty() ? w->output.file : output_path)).parent_path().string();
    std::vector<std::string> names;
    for (const auto& b : bodies_) names.push_back(b.name);
    ctx.body_index = [names](const std::string& name, const std::string& pointer) {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<int>(i);
      throw InputError(pointer, "no body named \"" + name + "\"");
    };

    try {
      w->registry = std::move(registry_);
      Registry& reg = *w->registry;
      if (!bodies_.empty()) {
        const auto& m = bodies_.front().model;
        w->model = reg.create<Modelization>(m.name, Params(json::object(), "/bodies"), ctx, m.pointer);
        w->state.declare(w->model->fields(dim_));
      }
      w->state.add_bodies(names);
      std::vector<Contactor> contactors;
      std::map<std::string, int> group_index;
      for (const auto& in : interactions_)
        for (const auto& g : {in.a, in.b}) group_index.emplace(g, static_cast<int>(group_index.size()));
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const auto& b = bodies_[i];
        std::optional<double> density;
        if (!b.material.empty()) density = materials_.at(b.material);
        // Shapes: one object per contactor; their mass properties add up.
        std::optional<MassProperties> mass;
        for (const auto& c : b.contactors) {
          json params = c.params.json();
          params.erase("shape");
          params.erase("group");
          Owned<Shape> shape = reg.create<Shape>(c.name, Params(params, c.pointer), ctx, c.pointer + "/shape");
          if (shape->has_mass()) mass = add(mass, shape->mass_properties());
          const std::string group = c.params.string("group");
          if (group_index.count(group))  // contactors of groups no interaction names are never detected
            contactors.push_back(Contactor{static_cast<int>(i), group_index.at(group), std::move(shape)});
        }
        w->model->init_body(w->state, i, b.model.params, mass, density);
      }
      if (!interactions_.empty()) build_contacts(*w, reg, ctx, std::move(contactors), group_index);
      for (const auto& d : drivers_) w->drivers.push_back(d);
      if (!w->drivers.empty() || !hooks_.empty()) {
        Field& f = w->state.declare(imposed_velocity_field());
        std::fill(f.data(Depth::begin), f.data(Depth::begin) + f.bodies() * f.components(), std::nan(""));
      }
      w->integrator = reg.create<Integrator>(integrator_.name, integrator_.params, ctx, integrator_.pointer);
      w->integrator->prepare(w->state);
      for (const auto& f : forces_) w->forces.push_back(reg.create<Force>(f.name, f.params, ctx, f.pointer));
      for (const auto& h : hooks_) w->hooks.push_back(reg.create<Hook>(h.name, h.params, ctx, h.pointer));
    } catch (const InputError& e) {
      throw e.with_file(file_.path);
    }
    return w;
  }

 private:
  struct BodyUse {
    std::string name;
    std::string material;
    PluginUse model;
    std::vector<PluginUse> contactors;
  };

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
    for (const auto& [name, use] : laws_) {
      law_index[name] = static_cast<int>(cs->laws.size());
      cs->laws.push_back(reg.create<Law>(use.name, use.params, ctx, use.pointer));
    }
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
    cs->alert = detection_["alert"].get<double>();
    cs->stop_on_failure = stop_on_failure_;
    w.contacts = std::move(cs);
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
      if (m.contains("density") && m["density"].is_number()) materials_[it.key()] = m["density"].get<double>();
    }
  }

  void check_bodies() {
    if (!top_["bodies"].is_array()) return;
    Validation v{dim_, errors_};
    std::set<std::string> seen;
    std::string first_model;
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
        all.merge(body_schema(*m));
      }
      json checked = validate_object(b, all, ptr, v);
      if (checked.contains("name") && checked["name"].is_string()) {
        body.name = checked["name"].get<std::string>();
        if (!seen.insert(body.name).second) errors_.emplace_back(ptr + "/name", "duplicate body name \"" + body.name + "\"");
      }
      if (first_model.empty()) first_model = model;
      else if (model != first_model)
        errors_.emplace_back(ptr + "/model", "all bodies of a scene must use one modelization for now (\"" +
                                                 first_model + "\" first, then \"" + model + "\")");
      if (checked.contains("material") && checked["material"].is_string()) {
        body.material = checked["material"].get<std::string>();
        if (!materials_.count(body.material)) {
          std::vector<std::string> names;
          for (const auto& [k, d] : materials_) names.push_back(k);
          std::string msg = "unknown material \"" + body.material + "\"";
          if (auto n = nearest_key(body.material, names); !n.empty()) msg += "; did you mean \"" + n + "\"?";
          errors_.emplace_back(ptr + "/material", msg);
        }
      }
      json model_params = checked;
      for (const auto& p : kernel_keys.params()) model_params.erase(p.name);
      body.model = PluginUse{model, Params(model_params, ptr), ptr};
      if (checked.contains("contactors") && checked["contactors"].is_array()) {
        const json& cs = checked["contactors"];
        for (std::size_t c = 0; c < cs.size(); ++c) body.contactors.push_back(contactor(cs[c], ptr + "/contactors/" + std::to_string(c)));
      }
      bodies_.push_back(std::move(body));
    }
    if (bodies.empty()) errors_.emplace_back("/bodies", "a scene needs at least one body");
  }

  /// A modelization's body schema comes from an instance (it depends on the dimension).
  Schema body_schema(const RegistryEntry& m) {
    BuildContext ctx;
    ctx.dimension = dim_;
    auto obj = m.registration.factory(Params(json::object(), "/bodies"), ctx);
    auto* model = dynamic_cast<Modelization*>(obj.get());
    if (!model) return {};
    return model->body_schema(dim_);
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
    Schema all = scene_schema::contactor_kernel_keys();
    all.merge(e->registration.schema);
    Validation v{dim_, errors_};
    use.params = Params(validate_object(c, all, ptr, v), ptr);
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
      const std::string name = d["body"].get<std::string>();
      drv.body = body_index(name);
      if (drv.body < 0) { errors_.emplace_back(ptr + "/body", "no body named \"" + name + "\""); continue; }
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

  int body_index(const std::string& name) const {
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (bodies_[i].name == name) return static_cast<int>(i);
    return -1;
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
        if (c.params.has("group")) groups.insert(c.params.string("group"));
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
                               "no contactor has group \"" + g[k].get<std::string>() + "\"");
      const std::string law = in["law"].get<std::string>();
      if (!laws_.count(law)) errors_.emplace_back(ptr + "/law", "no law named \"" + law + "\" in \"laws\"");
      interactions_.push_back({g[0].get<std::string>(), g[1].get<std::string>(), law, ptr});
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
          if (!c.params.has("group")) continue;
          if (c.params.string("group") == in.a) shapes_a.insert(c.name);
          if (c.params.string("group") == in.b) shapes_b.insert(c.name);
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
  std::map<std::string, double> materials_;
  std::map<std::string, PluginUse> laws_;
  std::vector<BodyUse> bodies_;
  std::vector<Driver> drivers_;
  PluginUse integrator_, solver_, broadphase_;
  struct InteractionUse {
    std::string a, b, law, pointer;
  };
  std::vector<InteractionUse> interactions_;
  std::map<std::pair<std::string, std::string>, std::pair<std::string, bool>> detector_uses_;
  bool stop_on_failure_ = false;
  std::vector<PluginUse> forces_, hooks_;
};

}  // namespace

std::unique_ptr<World> build_world(const std::string& scene_path, const std::string& output_path) {
  JsonFile file = read_json_file(scene_path);
  SceneChecker checker(file);
  checker.check();
  return checker.build(output_path);
}

void check_scene(const std::string& scene_path) {
  JsonFile file = read_json_file(scene_path);
  SceneChecker checker(file);
  checker.check();
  // Then build it (nothing is written): plugins check what a schema cannot say, such as
  // degenerate shapes or inconsistent masses, in their constructors.
  checker.build("");
}

}  // namespace moreau::kernel
