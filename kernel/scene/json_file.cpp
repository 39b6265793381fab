#include "json_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <moreau/error.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "validate.hpp"

namespace moreau::kernel {

namespace {

/// Follows the parser through the document (nlohmann's parse callback), knowing the JSON
/// pointer of the value being read, and refuses what JSON allows but a scene must not.
class StrictReader {
 public:
  explicit StrictReader(const std::string& file) : file_(file) {}

  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        if (static_cast<int>(stack_.size()) >= kMaxJsonDepth)
          throw InputError(pointer(), "objects and arrays nested more than " + std::to_string(kMaxJsonDepth) +
                                          " levels deep", file_);
        stack_.push_back(Level{event == E::array_start, 0, {}, {}});
        break;
      case E::key: {
        Level& top = stack_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second)
          throw InputError(pointer(), "duplicate key \"" + top.key + "\": a key may appear once in an object", file_);
        break;
      }
      case E::value:
        if (parsed.is_number_float() && !std::isfinite(parsed.get<double>()))
          throw InputError(pointer(), out_of_range_message, file_);
        next();
        break;
      case E::object_end:
      case E::array_end:
        stack_.pop_back();
        next();
        break;
    }
    return true;
  }

  static constexpr const char* out_of_range_message =
      "number out of range: a number must be below about 1.8e308 in magnitude";

  /// The pointer of the value being read.
  std::string pointer() const {
    std::string p;
    for (const auto& l : stack_) p += "/" + (l.array ? std::to_string(l.index) : pointer_token(l.key));
    return p;
  }

 private:
  struct Level {
    bool array;
    std::size_t index;     // arrays: the element being read
    std::string key;       // objects: the key of the value being read
    std::set<std::string> keys;
  };
  void next() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
  }
  const std::string& file_;
  std::vector<Level> stack_;
};

}  // namespace

nlohmann::json parse_json(const std::string& text, const std::string& file) {
  StrictReader reader(file);
  try {
    return nlohmann::json::parse(text, std::ref(reader));
  } catch (const nlohmann::json::parse_error& e) {
    // Byte offset → line and column, which editors show.
    std::size_t line = 1, col = 1;
    const std::size_t end = std::min<std::size_t>(e.byte ? e.byte - 1 : 0, text.size());
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    std::string what = e.what();
    if (auto p = what.find("syntax error"); p != std::string::npos) what = what.substr(p);
    throw InputError("", "malformed JSON at line " + std::to_string(line) + ", column " + std::to_string(col) + ": " + what,
                     file);
  } catch (const nlohmann::json::out_of_range& e) {
    // The parser refuses a number that overflows a double (1e400) before the reader sees
    // it, when the reader stands at that value: its pointer is the reader's.
    if (e.id == 406) throw InputError(reader.pointer(), StrictReader::out_of_range_message, file);
    throw InputError(reader.pointer(), std::string("malformed JSON: ") + e.what(), file);
  } catch (const nlohmann::json::exception& e) {
    throw InputError("", std::string("malformed JSON: ") + e.what(), file);
  }
}

JsonFile read_json_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError("", "is a folder, not a JSON file", path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("", "cannot open the file for reading", path);
  std::stringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError("", "cannot read the file", path);
  JsonFile f{path, ss.str(), {}};
  f.value = parse_json(f.text, path);
  return f;
}

}  // namespace moreau::kernel
