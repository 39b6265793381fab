#include "mesh_input.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <moreau/error.hpp>

#include "fem/gmsh_read.hpp"
#include "fem/mesh_check.hpp"
#include "fem/mesh_generate.hpp"

namespace moreau::elastic {

namespace {

using nlohmann::json;

/// A key of the mesh object, checked: its pointer and the message if it is wrong.
class MeshObject {
 public:
  MeshObject(const json& j, std::string pointer) : j_(j), ptr_(std::move(pointer)) {}

  std::string key(const std::string& k) const { return ptr_ + "/" + k; }
  bool has(const std::string& k) const { return j_.contains(k); }

  double number(const std::string& k) const {
    if (!j_.contains(k)) throw InputError(ptr_, "missing \"" + k + "\"");
    if (!j_[k].is_number()) throw InputError(key(k), "expected a number, got " + j_[k].dump());
    return j_[k].get<double>();
  }
  std::vector<double> vector(const std::string& k, std::size_t n) const {
    if (!j_.contains(k)) throw InputError(ptr_, "missing \"" + k + "\"");
    const json& v = j_[k];
    if (!v.is_array() || v.size() != n || !std::all_of(v.begin(), v.end(), [](const json& x) { return x.is_number(); }))
      throw InputError(key(k), "expected " + std::to_string(n) + " numbers, got " + v.dump());
    return v.get<std::vector<double>>();
  }
  std::string string(const std::string& k, const std::string& fallback = "") const {
    if (!j_.contains(k)) {
      if (!fallback.empty()) return fallback;
      throw InputError(ptr_, "missing \"" + k + "\"");
    }
    if (!j_[k].is_string()) throw InputError(key(k), "expected a string, got " + j_[k].dump());
    return j_[k].get<std::string>();
  }
  /// Unknown keys are errors, naming the valid ones.
  void only(const std::vector<std::string>& allowed) const {
    for (auto it = j_.begin(); it != j_.end(); ++it)
      if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end()) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        throw InputError(key(it.key()), "unknown key \"" + it.key() + "\" in a mesh of this kind (valid: " + list + ")");
      }
  }

 private:
  const json& j_;
  std::string ptr_;
};

fem::ElementType element_type(const MeshObject& m, const std::vector<std::string>& allowed) {
  const std::string name = m.string("element", allowed.front());
  static const std::map<std::string, fem::ElementType> types = {
      {"T3", fem::ElementType::T3}, {"Q4", fem::ElementType::Q4}, {"T4", fem::ElementType::T4}, {"H8", fem::ElementType::H8}};
  if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
    throw InputError(m.key("element"), "unknown element \"" + name + "\" for this mesh: expected \"" + allowed[0] + "\" or \"" +
                                           allowed[1] + "\"");
  return types.at(name);
}

}  // namespace

fem::Mesh scene_mesh(const json& mesh, const std::string& pointer, const std::string& scene_dir, int dim,
                     const std::vector<double>& offset) {
  if (!mesh.is_object()) throw InputError(pointer, "expected a mesh object: {\"file\": …} or {\"generate\": …}");
  const MeshObject m(mesh, pointer);
  fem::Mesh out;
  std::string where = pointer;  // where a fault of the mesh itself is reported
  try {
    if (m.has("file")) {
      m.only({"file"});
      where = m.key("file");
      std::filesystem::path path(m.string("file"));
      if (path.is_relative()) path = std::filesystem::path(scene_dir) / path;
      out = fem::read_gmsh(path.lexically_normal().string());
    } else if (m.has("generate")) {
      const std::string kind = m.string("generate");
      if (kind == "rectangle") {
        m.only({"generate", "origin", "extent", "size", "element"});
        const auto o = m.vector("origin", 2), e = m.vector("extent", 2);
        out = fem::rectangle_mesh({o[0], o[1]}, {e[0], e[1]}, m.number("size"), element_type(m, {"Q4", "T3"}));
      } else if (kind == "disk") {
        m.only({"generate", "centre", "radius", "size", "element"});
        const auto c = m.vector("centre", 2);
        out = fem::disk_mesh({c[0], c[1]}, m.number("radius"), m.number("size"), element_type(m, {"Q4", "T3"}));
      } else if (kind == "box") {
        m.only({"generate", "origin", "extent", "size", "element"});
        const auto o = m.vector("origin", 3), e = m.vector("extent", 3);
        out = fem::box_mesh({o[0], o[1], o[2]}, {e[0], e[1], e[2]}, m.number("size"), element_type(m, {"H8", "T4"}));
      } else {
        throw InputError(m.key("generate"), "unknown mesh generator \"" + kind + "\" (valid: rectangle, disk, box)");
      }
    } else {
      throw InputError(pointer, "a mesh needs \"file\" (a Gmsh .msh file) or \"generate\" (rectangle, disk, box)");
    }
  } catch (const fem::MeshError& e) {
    throw InputError(where, e.what());
  }
  if (out.dim != dim)
    throw InputError(where, "a " + std::to_string(out.dim) + "D mesh in a " + std::to_string(dim) + "D scene");
  for (int n = 0; n < out.node_count(); ++n)
    for (int k = 0; k < dim; ++k) out.x(k, n) += offset[static_cast<std::size_t>(k)];
  return out;
}

}  // namespace moreau::elastic
