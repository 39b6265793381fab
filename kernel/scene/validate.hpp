#pragma once
// Checking a JSON object against a Schema: types, ranges, lengths, choices, required
// keys, unknown keys (with the nearest valid key suggested). Every fault is appended to
// `errors` with its JSON pointer; the returned copy has the defaults filled in.
#include <moreau/error.hpp>
#include <moreau/schema.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace moreau::kernel {

struct Validation {
  int dimension = 3;
  std::vector<InputError>& errors;
};

/// `also_allowed`: keys checked elsewhere (e.g. "type" of a plugin object).
nlohmann::json validate_object(const nlohmann::json& value, const Schema& schema, const std::string& pointer,
                               Validation& v, const std::vector<std::string>& also_allowed = {});

/// JSON pointer token escaping (~ → ~0, / → ~1).
std::string pointer_token(const std::string& key);

/// Resolves a vector length code (schema.hpp `length::`) for a dimension.
int resolve_length(int code, int dimension);

}  // namespace moreau::kernel
