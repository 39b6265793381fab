#pragma once
// Runs the `moreau` executable as a user would, capturing exit code, stdout and stderr.
#include <filesystem>
#include <string>
#include <vector>

namespace moreau_test {

struct Result {
  int code = -1;
  std::string out, err;
};

/// Runs moreau with `args` (no shell), in `cwd` (default: a fresh temp folder).
Result run_moreau(const std::vector<std::string>& args, const std::filesystem::path& cwd = {});

/// A fresh empty folder for one test.
std::filesystem::path scratch_dir(const std::string& name);

/// Writes `text` to `dir/name` and returns the path.
std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name, const std::string& text);

}  // namespace moreau_test
