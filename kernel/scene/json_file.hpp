#pragma once
// The one JSON reader of the kernel: scenes, and JSON values given on the command line.
// Stricter than JSON itself, because every JSON the kernel reads is input a user wrote:
//  - a key given twice in one object is an error naming the key and its JSON pointer
//    (JSON leaves it open and nlohmann keeps the last value: a silent overwrite);
//  - a number too large for a double (1e400 parses to infinity) is an error at its pointer;
//  - nesting deeper than kMaxJsonDepth is an error (the validation and the copies of a
//    value recurse over it: 10^5 levels would overflow the stack).
#include <nlohmann/json.hpp>
#include <string>

namespace moreau::kernel {

/// Objects and arrays nested deeper than this are refused (a scene needs about 6).
inline constexpr int kMaxJsonDepth = 64;

/// A JSON file's parsed value and its text verbatim (the output keeps the scene as given).
struct JsonFile {
  std::string path;
  std::string text;
  nlohmann::json value;
};

/// Reads and parses `path`. Throws InputError naming the file and, for a syntax error,
/// the line and column; for a duplicate key, a non-finite number or too deep a nesting,
/// the JSON pointer.
JsonFile read_json_file(const std::string& path);

/// Parses `text` with the rules above; errors name `file` (may be a description such as
/// "--param tolerance").
nlohmann::json parse_json(const std::string& text, const std::string& file);

}  // namespace moreau::kernel
