#pragma once
// Validated parameters handed to a plugin's constructor: the scene's JSON object for
// it, already checked against the plugin's schema, with defaults filled in. Semantic
// checks the schema cannot express (a polygon is convex, …) throw `error(key, …)`,
// which carries the JSON pointer of the offending key.
#include <moreau/error.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace moreau {

class Params {
 public:
  Params() = default;
  Params(nlohmann::json values, std::string pointer)
      : values_(std::move(values)), pointer_(std::move(pointer)) {}

  bool has(const std::string& key) const {
    return values_.is_object() && values_.contains(key) && !values_.at(key).is_null();
  }
  double number(const std::string& key) const { return at(key).get<double>(); }
  long integer(const std::string& key) const { return at(key).get<long>(); }
  bool boolean(const std::string& key) const { return at(key).get<bool>(); }
  std::string string(const std::string& key) const { return at(key).get<std::string>(); }
  std::vector<double> vector(const std::string& key) const { return at(key).get<std::vector<double>>(); }
  const nlohmann::json& raw(const std::string& key) const { return at(key); }
  const nlohmann::json& json() const { return values_; }

  /// JSON pointer of this object, or of one of its keys.
  const std::string& pointer() const { return pointer_; }
  std::string pointer(const std::string& key) const { return pointer_ + "/" + key; }
  InputError error(const std::string& key, const std::string& message) const {
    return InputError(key.empty() ? pointer_ : pointer(key), message);
  }

 private:
  const nlohmann::json& at(const std::string& key) const {
    if (!has(key)) throw InputError(pointer(key), "missing required key '" + key + "'");
    return values_.at(key);
  }
  nlohmann::json values_ = nlohmann::json::object();
  std::string pointer_;
};

}  // namespace moreau
