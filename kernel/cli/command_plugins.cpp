// `moreau plugins [--json]`: every plugin name by kind, with its parameters (and, for
// modelizations, the table of state fields they store).
#include <moreau/contact_fields.hpp>
#include <moreau/modelization.hpp>
#include <nlohmann/json.hpp>
#include <ostream>

#include "../plugin/registry.hpp"
#include "commands.hpp"

namespace moreau::kernel {

namespace {

nlohmann::json schema_json(const Schema& s) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : s.params()) {
    nlohmann::json j{{"name", p.name}, {"type", param_type_name(p.type)}, {"doc", p.doc}, {"required", p.required}};
    if (!p.unit.empty()) j["units"] = p.unit;
    if (!p.required && !p.default_value.is_null()) j["default"] = p.default_value;
    if (p.lo) j[p.lo_open ? "greater_than" : "minimum"] = *p.lo;
    if (p.hi) j[p.hi_open ? "less_than" : "maximum"] = *p.hi;
    if (p.type == ParamType::vector) j["length"] = p.length == length::dimension ? nlohmann::json("d")
                                                 : p.length == length::rotation  ? nlohmann::json("1 (2D) or 3 (3D)")
                                                 : p.length == length::orientation ? nlohmann::json("4 (3D)")
                                                 : nlohmann::json(p.length);
    if (!p.choices.empty()) j["choices"] = p.choices;
    params.push_back(j);
  }
  return params;
}

/// A field table as `moreau plugins` prints it (both dimensions).
nlohmann::json fields_json(const std::vector<FieldSpec>& table2, const std::vector<FieldSpec>& table3) {
  nlohmann::json out = nlohmann::json::array();
  for (int dim : {2, 3}) {
    for (const auto& f : dim == 2 ? table2 : table3) {
      if (f.components(dim) <= 0) continue;
      const char* where = f.output == FieldOutput::frame ? "frame" : f.output == FieldOutput::once ? "once" : "none";
      const char* needed = f.needed == Needed::always ? "always" : f.needed == Needed::contacts ? "contacts"
                           : f.needed == Needed::forces ? "forces" : "imposed";
      out.push_back({{"dimension", dim}, {"set", f.set}, {"name", f.name}, {"components", f.components(dim)},
                     {"depths", f.depths}, {"units", f.units}, {"output", where}, {"restart", f.restart},
                     {"persist", f.persist}, {"allocated", needed}, {"doc", f.doc}});
    }
  }
  return out;
}

/// The kernel's own sets: `bodies` and `contacts`.
nlohmann::json kernel_sets_json() {
  State st(2);
  std::vector<FieldSpec> bodies;
  for (const auto& f : st.set(sets::bodies).fields()) bodies.push_back(f.spec());
  std::vector<FieldSpec> all = bodies;
  for (const auto& f : contact_fields::table()) all.push_back(f);
  return fields_json(all, all);
}

}  // namespace

int command_plugins(bool as_json, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    Registry reg(Registry::standard_paths({}, "."));
    reg.load_all();
    nlohmann::json all = nlohmann::json::object();
    for (const RegistryEntry* e : reg.entries()) {
      const auto& r = e->registration;
      nlohmann::json j{{"name", r.name}, {"doc", r.doc}, {"dimensions", r.schema.dimensions()},
                       {"library", e->library ? e->library->path().string() : "(kernel)"},
                       {"parameters", schema_json(r.schema)}};
      if (r.kind == Kind::modelization) {
        BuildContext ctx;
        auto obj = r.factory(Params(nlohmann::json::object(), ""), ctx);
        if (auto* m = dynamic_cast<Modelization*>(obj.get())) {
          j["body_parameters_2d"] = schema_json(m->body_schema(2));
          j["body_parameters_3d"] = schema_json(m->body_schema(3));
          j["node_set"] = m->node_set();
          j["element_set"] = m->element_set();
          j["node_dofs"] = {m->node_dofs(2), m->node_dofs(3)};
          j["default_integrator"] = m->default_integrator();
          j["fields"] = fields_json(m->fields(2), m->fields(3));
        }
      }
      all[kind_name(r.kind)].push_back(j);
    }
    all["kernel"].push_back(nlohmann::json{{"name", "sets"}, {"doc", "the kernel's entity sets: bodies and contacts"},
                                           {"parameters", nlohmann::json::array()}, {"fields", kernel_sets_json()}});
    if (as_json) {
      out << all.dump(2) << "\n";
      return 0;
    }
    for (auto it = all.begin(); it != all.end(); ++it) {
      out << it.key() << ":\n";
      for (const auto& p : it.value()) {
        out << "  " << p["name"].get<std::string>() << "  — " << p["doc"].get<std::string>() << "\n";
        auto print_params = [&](const nlohmann::json& params, const char* title) {
          if (params.empty()) return;
          out << "    " << title << ":\n";
          for (const auto& q : params) {
            out << "      " << q["name"].get<std::string>() << " (" << q["type"].get<std::string>();
            if (q.contains("units")) out << ", " << q["units"].get<std::string>();
            if (q.contains("default")) out << ", default " << q["default"].dump();
            if (q["required"].get<bool>()) out << ", required";
            out << "): " << q["doc"].get<std::string>() << "\n";
          }
        };
        print_params(p["parameters"], "parameters");
        if (p.contains("body_parameters_2d")) print_params(p["body_parameters_2d"], "body keys (2D)");
        if (p.contains("body_parameters_3d")) print_params(p["body_parameters_3d"], "body keys (3D)");
        if (p.contains("fields")) {
          out << "    state fields:\n";
          for (const auto& f : p["fields"])
            out << "      " << f["dimension"].get<int>() << "D " << f["set"].get<std::string>() << "/"
                << f["name"].get<std::string>() << " ["
                << f["components"].get<int>() << "] " << f["units"].get<std::string>() << " ("
                << f["output"].get<std::string>() << "): " << f["doc"].get<std::string>() << "\n";
        }
      }
    }
    return 0;
  });
}

}  // namespace moreau::kernel
