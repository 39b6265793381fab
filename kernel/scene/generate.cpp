#include "generate.hpp"

#include <cctype>
#include <filesystem>
#include <moreau/generator.hpp>

#include "../plugin/registry.hpp"
#include "validate.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace moreau::kernel {

InputError Generated::locate(const InputError& e) const {
  const std::string& where = e.where();
  const std::string prefix = "/bodies/";
  if (where.compare(0, prefix.size(), prefix) != 0) return e;
  std::size_t end = prefix.size();
  while (end < where.size() && std::isdigit(static_cast<unsigned char>(where[end]))) ++end;
  if (end == prefix.size()) return e;
  const std::size_t body = std::stoul(where.substr(prefix.size(), end - prefix.size()));
  for (const auto& r : ranges)
    if (body >= r.first && body < r.first + r.count)
      return InputError(where, std::string(e.what()) + " (body " + std::to_string(body - r.first) + " made by " +
                                   r.pointer + ")",
                        e.file());
  return e;
}

Generated expand_generators(JsonFile& file) {
  Generated out;
  json& root = file.value;
  if (!root.is_object() || !root.contains("generators")) return out;
  if (!root["generators"].is_array()) return out;  // the validation says what was expected
  if (root["generators"].empty()) {
    root.erase("generators");
    return out;
  }
  // Without a sound dimension the validation stops at it first.
  if (!root.contains("dimension") || !root["dimension"].is_number_integer() ||
      (root["dimension"] != 2 && root["dimension"] != 3))
    return out;
  const int dim = root["dimension"].get<int>();

  std::vector<std::string> scene_paths;
  if (root.contains("plugin_paths") && root["plugin_paths"].is_array())
    for (const auto& p : root["plugin_paths"])
      if (p.is_string()) scene_paths.push_back(p.get<std::string>());
  const fs::path scene_dir = fs::absolute(fs::path(file.path)).parent_path();
  Registry registry(Registry::standard_paths(scene_paths, scene_dir));

  BuildContext ctx;
  ctx.dimension = dim;
  ctx.scene_file = file.path;
  ctx.scene_dir = scene_dir.string();

  // Every generator's parameters are checked before any runs: all faults at once.
  struct Use {
    std::string type, pointer;
    Params params;
  };
  std::vector<Use> uses;
  std::vector<InputError> errors;
  const json list = root["generators"];
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string ptr = "/generators/" + std::to_string(i);
    const json& g = list[i];
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) {
      errors.emplace_back(g.is_object() ? ptr + "/type" : ptr,
                          "expected a generator object with \"type\" (the name of a generator plugin)");
      continue;
    }
    Use u{g["type"].get<std::string>(), ptr, {}};
    const RegistryEntry* e = nullptr;
    try {
      e = &registry.require(Kind::generator, u.type, ptr + "/type");
    } catch (const InputError& err) {
      errors.push_back(err);
      continue;
    }
    if (!e->registration.schema.supports(dim)) {
      errors.emplace_back(ptr + "/type", "generator '" + u.type + "' does not support " + std::to_string(dim) + "D scenes");
      continue;
    }
    Validation v{dim, errors};
    json filled = validate_object(g, e->registration.schema, ptr, v, {"type"});
    filled.erase("type");
    u.params = Params(filled, ptr);
    uses.push_back(std::move(u));
  }
  auto with_file = [&](std::vector<InputError> errs) {
    for (auto& x : errs) x = x.with_file(file.path);
    return InputErrors(std::move(errs));
  };
  if (!errors.empty()) throw with_file(std::move(errors));

  if (!root.contains("bodies")) root["bodies"] = json::array();
  if (!root["bodies"].is_array()) return out;  // reported by the validation
  root.erase("generators");
  for (const auto& u : uses) {
    try {
      auto gen = registry.create<Generator>(u.type, u.params, ctx, u.pointer);
      const std::vector<json> bodies = gen->generate(GeneratorInput{dim, root, u.pointer});
      Generated::Range r{root["bodies"].size(), bodies.size(), u.pointer};
      for (const auto& b : bodies) root["bodies"].push_back(b);
      out.ranges.push_back(r);
    } catch (const InputError& e) {
      throw e.with_file(file.path);
    }
  }
  return out;
}

}  // namespace moreau::kernel
