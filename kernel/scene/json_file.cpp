#include "json_file.hpp"

#include <fstream>
#include <moreau/error.hpp>
#include <sstream>

namespace moreau::kernel {

JsonFile read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("", "cannot open the file for reading", path);
  std::stringstream ss;
  ss << in.rdbuf();
  JsonFile f{path, ss.str(), {}};
  try {
    f.value = nlohmann::json::parse(f.text);
  } catch (const nlohmann::json::parse_error& e) {
    // Byte offset → line and column, which editors show.
    std::size_t line = 1, col = 1;
    const std::size_t end = std::min<std::size_t>(e.byte ? e.byte - 1 : 0, f.text.size());
    for (std::size_t i = 0; i < end; ++i) {
      if (f.text[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    std::string what = e.what();
    if (auto p = what.find("syntax error"); p != std::string::npos) what = what.substr(p);
    throw InputError("", "malformed JSON at line " + std::to_string(line) + ", column " + std::to_string(col) + ": " + what,
                     path);
  }
  return f;
}

}  // namespace moreau::kernel
