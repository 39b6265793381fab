#pragma once
// Parameter schemas: every plugin declares the parameters it accepts (type, default,
// range, units, doc) next to its class. The kernel validates a scene against these
// schemas before it constructs anything, reports every fault at once with its JSON
// pointer, and `moreau plugins` prints them. Unknown keys are always errors.
#include <deque>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace moreau {

enum class ParamType { number, integer, boolean, string, vector, object, array };

/// Length of a `vector` parameter. Positive values are exact lengths; the named
/// values below resolve against the scene's dimension d.
namespace length {
inline constexpr int any = 0;
inline constexpr int dimension = -1;    ///< d: positions, velocities, forces
inline constexpr int rotation = -2;     ///< 1 in 2D (an angle rate, a torque), 3 in 3D
inline constexpr int orientation = -3;  ///< 4 in 3D (unit quaternion w x y z)
}  // namespace length

/// One parameter. Built with chained setters: `s.number("radius", "…").units("m").gt(0)`.
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::number;
  std::string doc;
  std::string unit;
  bool required = true;
  nlohmann::json default_value;  ///< set when not required (null default = "absent")
  std::optional<double> lo, hi;  ///< range on numbers, integers and vector items
  bool lo_open = false, hi_open = false;
  int length = length::any;            ///< vectors only
  bool nullable_items = false;         ///< vectors: items may be null ("leave free")
  std::vector<std::string> choices;    ///< strings: the allowed values, if any

  ParamSpec& units(std::string u) { unit = std::move(u); return *this; }
  ParamSpec& optional() { required = false; return *this; }
  ParamSpec& fallback(nlohmann::json v) { required = false; default_value = std::move(v); return *this; }
  ParamSpec& min(double v) { lo = v; lo_open = false; return *this; }
  ParamSpec& gt(double v) { lo = v; lo_open = true; return *this; }
  ParamSpec& max(double v) { hi = v; hi_open = false; return *this; }
  ParamSpec& lt(double v) { hi = v; hi_open = true; return *this; }
  ParamSpec& size(int n) { length = n; return *this; }
  ParamSpec& allow_null_items() { nullable_items = true; return *this; }
  ParamSpec& one_of(std::vector<std::string> c) { choices = std::move(c); return *this; }
};

/// The parameters a plugin (or a kernel section of the scene) accepts.
class Schema {
 public:
  ParamSpec& number(std::string name, std::string doc) { return add(std::move(name), ParamType::number, std::move(doc)); }
  ParamSpec& integer(std::string name, std::string doc) { return add(std::move(name), ParamType::integer, std::move(doc)); }
  ParamSpec& boolean(std::string name, std::string doc) { return add(std::move(name), ParamType::boolean, std::move(doc)); }
  ParamSpec& string(std::string name, std::string doc) { return add(std::move(name), ParamType::string, std::move(doc)); }
  ParamSpec& vector(std::string name, std::string doc, int len) {
    auto& p = add(std::move(name), ParamType::vector, std::move(doc));
    p.length = len;
    return p;
  }
  /// A nested object or array the owner validates itself (the kernel checks only its type).
  ParamSpec& object(std::string name, std::string doc) { return add(std::move(name), ParamType::object, std::move(doc)); }
  ParamSpec& array(std::string name, std::string doc) { return add(std::move(name), ParamType::array, std::move(doc)); }

  /// Restrict to scenes of these dimensions (default: 2 and 3).
  Schema& dimensions(std::vector<int> dims) { dims_ = std::move(dims); return *this; }
  bool supports(int dim) const {
    for (int d : dims_) if (d == dim) return true;
    return false;
  }
  const std::vector<int>& dimensions() const { return dims_; }

  const std::deque<ParamSpec>& params() const { return params_; }
  const ParamSpec* find(const std::string& name) const {
    for (const auto& p : params_) if (p.name == name) return &p;
    return nullptr;
  }
  /// Adds every parameter of `other` (e.g. the keys every contactor accepts).
  Schema& merge(const Schema& other) {
    for (const auto& p : other.params_) params_.push_back(p);
    return *this;
  }

 private:
  ParamSpec& add(std::string name, ParamType t, std::string doc) {
    ParamSpec p;
    p.name = std::move(name);
    p.type = t;
    p.doc = std::move(doc);
    params_.push_back(std::move(p));
    return params_.back();
  }
  std::deque<ParamSpec> params_;  // deque: references returned by add() stay valid
  std::vector<int> dims_{2, 3};
};

const char* param_type_name(ParamType t);

}  // namespace moreau

// Implementation kept inline: tiny and needed by both kernel and plugins.
inline const char* moreau::param_type_name(ParamType t) {
  switch (t) {
    case ParamType::number: return "number";
    case ParamType::integer: return "integer";
    case ParamType::boolean: return "boolean";
    case ParamType::string: return "string";
    case ParamType::vector: return "array of numbers";
    case ParamType::object: return "object";
    case ParamType::array: return "array";
  }
  return "?";
}
