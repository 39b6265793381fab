#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace moreau::kernel {

/// A JSON file's parsed value and its text verbatim (the output keeps the scene as given).
struct JsonFile {
  std::string path;
  std::string text;
  nlohmann::json value;
};

/// Reads and parses `path`. Throws InputError naming the file and, for a syntax error,
/// the line and column.
JsonFile read_json_file(const std::string& path);

}  // namespace moreau::kernel
