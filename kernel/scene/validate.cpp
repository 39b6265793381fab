#include "validate.hpp"

#include "../text/did_you_mean.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace moreau::kernel {

namespace {

std::string type_of(const nlohmann::json& j) {
  if (j.is_null()) return "null";
  if (j.is_boolean()) return "a boolean";
  if (j.is_number_integer() || j.is_number_unsigned()) return "an integer";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "an array";
  return "an object";
}

std::string fmt(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

std::string range_text(const ParamSpec& p) {
  std::string s;
  if (p.lo) s += (p.lo_open ? "> " : ">= ") + fmt(*p.lo);
  if (p.hi) s += (s.empty() ? "" : " and ") + std::string(p.hi_open ? "< " : "<= ") + fmt(*p.hi);
  return s;
}

bool in_range(const ParamSpec& p, double x) {
  if (!std::isfinite(x)) return false;
  if (p.lo && (p.lo_open ? !(x > *p.lo) : !(x >= *p.lo))) return false;
  if (p.hi && (p.hi_open ? !(x < *p.hi) : !(x <= *p.hi))) return false;
  return true;
}

void check_value(const ParamSpec& p, const nlohmann::json& j, const std::string& ptr, Validation& v) {
  auto fail = [&](const std::string& msg) { v.errors.emplace_back(ptr, msg); };
  switch (p.type) {
    case ParamType::number:
      if (!j.is_number()) return fail("expected a number, got " + type_of(j));
      if (!in_range(p, j.get<double>())) return fail("value " + fmt(j.get<double>()) + " out of range: expected " + range_text(p));
      return;
    case ParamType::integer:
      if (!j.is_number_integer() && !j.is_number_unsigned()) return fail("expected an integer, got " + type_of(j));
      if (!in_range(p, j.get<double>())) return fail("value " + fmt(j.get<double>()) + " out of range: expected " + range_text(p));
      return;
    case ParamType::boolean:
      if (!j.is_boolean()) return fail("expected a boolean (true or false), got " + type_of(j));
      return;
    case ParamType::string:
      if (!j.is_string()) return fail("expected a string, got " + type_of(j));
      if (!p.choices.empty() &&
          std::find(p.choices.begin(), p.choices.end(), j.get<std::string>()) == p.choices.end()) {
        std::string c;
        for (const auto& x : p.choices) c += (c.empty() ? "" : ", ") + ("\"" + x + "\"");
        return fail("unexpected value \"" + j.get<std::string>() + "\": expected one of " + c +
                    did_you_mean(j.get<std::string>(), p.choices));
      }
      return;
    case ParamType::vector: {
      const int n = resolve_length(p.length, v.dimension);
      if (n == 1 && j.is_number()) {  // a 2D rotation quantity may be written as a plain number
        if (!in_range(p, j.get<double>())) fail("value " + fmt(j.get<double>()) + " out of range: expected " + range_text(p));
        return;
      }
      if (!j.is_array()) return fail("expected an array of " + (n > 0 ? std::to_string(n) + " " : std::string()) + "numbers, got " + type_of(j));
      if (n > 0 && static_cast<int>(j.size()) != n)
        return fail("expected " + std::to_string(n) + " numbers (dimension " + std::to_string(v.dimension) + "), got " +
                    std::to_string(j.size()));
      for (std::size_t i = 0; i < j.size(); ++i) {
        const auto& x = j[i];
        const std::string ip = ptr + "/" + std::to_string(i);
        if (x.is_null() && p.nullable_items) continue;
        if (!x.is_number()) { v.errors.emplace_back(ip, std::string("expected a number") + (p.nullable_items ? " or null" : "") + ", got " + type_of(x)); continue; }
        if (!in_range(p, x.get<double>())) v.errors.emplace_back(ip, "value " + fmt(x.get<double>()) + " out of range: expected " + range_text(p));
      }
      return;
    }
    case ParamType::object:
      if (!j.is_object()) return fail("expected an object, got " + type_of(j));
      return;
    case ParamType::array:
      if (!j.is_array()) return fail("expected an array, got " + type_of(j));
      return;
  }
}

}  // namespace

int resolve_length(int code, int dimension) {
  switch (code) {
    case length::dimension: return dimension;
    case length::rotation: return dimension == 2 ? 1 : 3;
    case length::orientation: return dimension == 2 ? 1 : 4;
    default: return code;
  }
}

std::string pointer_token(const std::string& key) {
  std::string s;
  for (char c : key) {
    if (c == '~') s += "~0";
    else if (c == '/') s += "~1";
    else s += c;
  }
  return s;
}

nlohmann::json validate_object(const nlohmann::json& value, const Schema& schema, const std::string& pointer,
                               Validation& v, const std::vector<std::string>& also_allowed) {
  if (!value.is_object()) {
    v.errors.emplace_back(pointer, "expected an object, got " + type_of(value));
    return nlohmann::json::object();
  }
  nlohmann::json out = value;
  std::vector<std::string> valid = also_allowed;
  for (const auto& p : schema.params()) valid.push_back(p.name);
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (std::find(valid.begin(), valid.end(), it.key()) != valid.end()) continue;
    std::string msg = "unknown key \"" + it.key() + "\"";
    if (auto near = did_you_mean(it.key(), valid); !near.empty()) msg += near;
    else {
      std::string all;
      for (const auto& k : valid) all += (all.empty() ? "" : ", ") + k;
      msg += "; valid keys: " + all;
    }
    v.errors.emplace_back(pointer + "/" + pointer_token(it.key()), msg);
  }
  for (const auto& p : schema.params()) {
    const std::string ptr = pointer + "/" + pointer_token(p.name);
    if (!value.contains(p.name)) {
      if (p.required) v.errors.emplace_back(ptr, "missing required key \"" + p.name + "\" (" + p.doc + ")");
      else if (!p.default_value.is_null()) out[p.name] = p.default_value;
      continue;
    }
    check_value(p, value.at(p.name), ptr, v);
    if (p.type == ParamType::vector && value.at(p.name).is_number()) out[p.name] = nlohmann::json::array({value.at(p.name)});
  }
  return out;
}

}  // namespace moreau::kernel
